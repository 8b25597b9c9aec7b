#!/usr/bin/env bash
# Makes the large benchmark meshes: armadillo (26k vertices) Loop-subdivided 1, 2 and 3 times
# through meshlabserver (104k, 416k, 1.66M vertices), into data/bench/. Skips what exists.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
mkdir -p "$ROOT/data/bench"
for k in 1 2 3; do
  out="$ROOT/data/bench/armadillo_loop$k.ply"
  [ -s "$out" ] && continue
  script="$ROOT/data/bench/loop$k.mlx"
  cat > "$script" <<MLX
<!DOCTYPE FilterScript>
<FilterScript>
 <filter name="Subdivision Surfaces: Loop">
  <Param type="RichEnum" name="LoopWeight" value="0" enum_cardinality="3" enum_val0="Loop" enum_val1="Enhance regularity" enum_val2="Enhance continuity"/>
  <Param type="RichInt" name="Iterations" value="$k"/>
  <Param type="RichAbsPerc" name="Threshold" value="0" min="0" max="100"/>
  <Param type="RichBool" name="Selected" value="false"/>
 </filter>
</FilterScript>
MLX
  xvfb-run -a -s "-screen 0 800x600x24" meshlabserver -i "$ROOT/data/armadillo.off" -o "$out" -s "$script" >/dev/null 2>&1
  echo "[bench] $out"
done
