#!/usr/bin/env bash
# Set-up (idempotent) and a Release build in build/. Extra arguments go to cmake's configure.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$ROOT/scripts/setup.sh"
cmake -S "$ROOT" -B "$ROOT/build" "$@" >/dev/null
cmake --build "$ROOT/build" -j"$(nproc)"
