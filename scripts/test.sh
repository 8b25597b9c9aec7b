#!/usr/bin/env bash
# The test command: set up, build, run every test (unit tests and meshlabserver tests).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$ROOT/scripts/build.sh"
cd "$ROOT/build"
ctest --output-on-failure -j"$(nproc)"
