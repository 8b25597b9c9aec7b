#!/usr/bin/env bash
# Whole-run wall time and peak memory of meshlabserver smoothing the large armadillos with
# MeshLab's TwoStep Smooth (defaults) and with HHT: Spectral Filter (resources/smooth.mlx and
# the filter's defaults), as a user would run them. Needs scripts/build.sh and
# scripts/bench_meshes.sh first; uses the staged plugin in build/stage.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SERVER="$ROOT/build/stage/bin/meshlabserver"
OUT="$(mktemp -d)"
default_script="$OUT/spectral_default.mlx"
# the Spectral Filter with every default (one cycle, lambda 0.01), from smooth.mlx
sed -e 's/name="cutoff" value="[^"]*"/name="cutoff" value="0.1"/' -e 's/name="cycles" value="[^"]*"/name="cycles" value="1"/' \
    -e 's/name="lambda" value="[^"]*"/name="lambda" value="0.01"/' "$ROOT/resources/smooth.mlx" > "$default_script"
echo "| mesh | vertices | method | wall time (s) | peak memory (MB) |"
echo "|---|---|---|---|---|"
for mesh in "${@:-$ROOT/data/bench/armadillo_loop2.ply $ROOT/data/bench/armadillo_loop3.ply}"; do
  for m in $mesh; do
    n=$(grep -a -m1 "element vertex" "$m" | awk '{print $3}')
    for method in twostep spectral_default smooth; do
      case $method in
        twostep) script="$ROOT/bench/scripts/twostep_default.mlx"; label="TwoStep Smooth (defaults)";;
        spectral_default) script="$default_script"; label="HHT: Spectral Filter (defaults)";;
        smooth) script="$ROOT/resources/smooth.mlx"; label="HHT: Spectral Filter (smooth.mlx, 4 cycles)";;
      esac
      /usr/bin/time -f "%e %M" -o "$OUT/time" xvfb-run -a -s "-screen 0 800x600x24" "$SERVER" -i "$m" -o "$OUT/out.ply" \
        -s "$script" > "$OUT/log" 2>&1 || { echo "failed: $method on $m" >&2; tail -3 "$OUT/log" >&2; }
      read -r secs kb < "$OUT/time"
      echo "| $(basename "$m") | $n | $label | $secs | $((kb / 1024)) |"
    done
  done
done
rm -rf "$OUT"
