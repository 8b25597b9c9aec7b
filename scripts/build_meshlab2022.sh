#!/usr/bin/env bash
# Builds the plugin for MeshLab 2022.02 and its script runner (meshlabserver2022) inside the
# Debian 13 root (or natively on Debian 13) into build/meshlab2022/. Runs setup_meshlab2022.sh
# first; exits 3 like it when this machine cannot make the root.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$ROOT/scripts/debian13_env.sh"
"$ROOT/scripts/setup_meshlab2022.sh" || exit $?
src_inside="$PROJECT_INSIDE/third_party/meshlab-2022.02-src"
"$ROOT/scripts/in_debian13.sh" sh -c 'cmake -S "$1" -B "$2" -DMESHLAB_SOURCE_DIR="$3" \
    -DHHT_BUILD_TESTS=OFF -DHHT_BUILD_BENCH=OFF > /dev/null && cmake --build "$2" -j2 -- --no-print-directory' \
  sh "$PROJECT_INSIDE" "$MESHLAB2022_BUILD_INSIDE" "$src_inside"
