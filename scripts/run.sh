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
# run_script <output-name> <script>...: the scripts' filters, in order, in one meshlabserver run
run_script() {
  local name="$1"; shift
  local log="$OUT/$name.log" script="$OUT/.$name.mlx"
  { echo '<!DOCTYPE FilterScript>'; echo '<FilterScript>'
    for s in "$@"; do sed -n '/<filter /,/<\/filter>/p' "$ROOT/resources/$s.mlx"; done
    echo '</FilterScript>'; } > "$script"
  (cd "$OUT" && xvfb-run -a -s "-screen 0 800x600x24" meshlabserver -i "$MODEL" -o "$OUT/$name.ply" -m vq vc \
      -s "$script" >"$log" 2>&1) || { echo "[run] $name failed, see $log" >&2; tail -5 "$log" >&2; exit 1; }
  rm -f "$script"
  grep '^LOG:' "$log" | sed 's/^LOG: [0-9]* /    /'
  echo "[run] $* -> $OUT/$name.ply"
}
run_script "${name}_cycle" hamiltonian_cycle
run_script "${name}_curvature" curvature_signal
run_script "${name}_spectra" hilbert_spectra
run_script "${name}_noisy" add_noise
run_script "${name}_noisy_smoothed" add_noise smooth
run_script "${name}_enhanced" enhance
run_script "${name}_noisy_denoised" add_noise denoise
echo "[run] results in $OUT (frequency_distribution.png/.csv: the IMFs' frequency distribution)"
