#!/usr/bin/env bash
# The library's unit tests (label `unit`, the fuzz test included) under AddressSanitizer and
# UndefinedBehaviorSanitizer, in their own build folder (build-asan/, no plugin: MeshLab's own
# libraries are not instrumented). Any sanitizer report fails the test that triggered it.
#   scripts/sanitize.sh [ctest arguments, e.g. -R Fuzz]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$ROOT/scripts/setup.sh"
cmake -S "$ROOT" -B "$ROOT/build-asan" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DHHT_SANITIZE=ON -DHHT_BUILD_PLUGIN=OFF -DHHT_BUILD_BENCH=OFF >/dev/null
cmake --build "$ROOT/build-asan" --target hht_unit_tests -j"$(nproc)"
cd "$ROOT/build-asan"
export ASAN_OPTIONS="abort_on_error=1:${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:${UBSAN_OPTIONS:-}"
ctest -L unit --output-on-failure -j"$(nproc)" "$@"
