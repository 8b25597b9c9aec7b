#!/usr/bin/env bash
# Whole meshlabserver runs (load, filter, save), as a user runs them: MeshLab's TwoStep Smooth
# with its defaults against resources/smooth.mlx, enhance.mlx and denoise.mlx, one after the
# other on each mesh, in the same session; wall time and peak memory from /usr/bin/time, and
# each script's ratio to TwoStep's. Needs scripts/build.sh and scripts/bench_meshes.sh first;
# uses the staged plugin in build/stage. Arguments: meshes (default: the armadillos at 104k,
# 416k and 1.66M vertices, clean and with 20% noise).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SERVER="$ROOT/build/stage/bin/meshlabserver"
OUT="$(mktemp -d)"
trap 'rm -rf "$OUT"' EXIT
MESHES=("$@")
if [ ${#MESHES[@]} -eq 0 ]; then
  for k in 1 2 3; do MESHES+=("$ROOT/data/bench/armadillo_loop$k.ply" "$ROOT/data/bench/armadillo_loop${k}_noise20.ply"); done
fi
echo "| mesh | vertices | method | wall time (s) | peak memory (MB) | time / TwoStep | memory / TwoStep |"
echo "|---|---|---|---|---|---|---|"
for m in "${MESHES[@]}"; do
  n=$(grep -a -m1 "element vertex" "$m" | awk '{print $3}')
  base_time=""; base_memory=""
  for method in twostep smooth enhance denoise; do
    case $method in
      twostep) script="$ROOT/bench/scripts/twostep_default.mlx"; label="TwoStep Smooth (defaults)";;
      *) script="$ROOT/resources/$method.mlx"; label="$method.mlx";;
    esac
    if ! /usr/bin/time -f "%e %M" -o "$OUT/time" xvfb-run -a -s "-screen 0 800x600x24" "$SERVER" -i "$m" -o "$OUT/out.ply" \
        -s "$script" > "$OUT/log" 2>&1; then
      echo "failed: $method on $m" >&2; tail -3 "$OUT/log" >&2; continue
    fi
    read -r secs kb < "$OUT/time"
    mb=$((kb / 1024))
    if [ $method = twostep ]; then base_time=$secs; base_memory=$mb; fi
    ratios=$(awk -v t="$secs" -v bt="$base_time" -v m="$mb" -v bm="$base_memory" 'BEGIN { printf "%.2f | %.2f", t / bt, m / bm }')
    echo "| $(basename "$m") | $n | $label | $secs | $mb | $ratios |"
  done
done
