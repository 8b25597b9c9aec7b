#!/usr/bin/env bash
# The main job: set up, build, install the plugin into MeshLab's plugin folder, and run the
# HHT pipeline through meshlabserver on the default model (Fandisk, the paper's Fig. 10),
# writing the results into out/ (or the folder given as the first argument).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT="$(realpath -m "${1:-$ROOT/out}")"
MODEL="${HHT_MODEL:-$ROOT/data/fandisk.off}"
SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"

"$ROOT/scripts/build.sh"
$SUDO cmake --install "$ROOT/build" >/dev/null
echo "[run] installed $(ls /usr/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_hht.so)"

mkdir -p "$OUT"
name="$(basename "${MODEL%.*}")"
run_script() {  # run_script <script> <output-name>
  local log="$OUT/$2.log"
  (cd "$OUT" && xvfb-run -a -s "-screen 0 800x600x24" meshlabserver -i "$MODEL" -o "$OUT/$2.ply" -m vq vc \
      -s "$ROOT/resources/$1.mlx" >"$log" 2>&1) || { echo "[run] $1 failed, see $log" >&2; tail -5 "$log" >&2; exit 1; }
  grep '^LOG:' "$log" | sed 's/^LOG: [0-9]* /    /'
  echo "[run] $1 -> $OUT/$2.ply"
}
run_script hamiltonian_cycle "${name}_cycle"
run_script curvature_signal "${name}_curvature"
echo "[run] results in $OUT"
