#!/usr/bin/env bash
# Quality harness (issue 7): smoothing and denoising methods on libcgal-demo's organic and CAD
# meshes with isotropic and normal-direction Gaussian noise, every method run through the staged
# meshlabserver (build/stage, made by scripts/build.sh), metrics against the clean mesh.
# Writes the tables into docs/quality.md (between the quality-table markers) and pictures into
# docs/images/quality_*.png; --quick runs a small subset and writes only build/quality/.
#   scripts/evaluate_quality.sh [--quick] [--jobs N] [--resume [--rerun METHOD,...]] [--work DIR]
#                               [--cad-models isotropic,normal,random]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"

missing=()
for p in python3-numpy xvfb xauth libcgal-demo; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "[evaluate_quality] installing Debian packages: ${missing[*]}"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
[ -x "$ROOT/build/stage/bin/meshlabserver" ] || { echo "no staged meshlabserver: run scripts/build.sh first" >&2; exit 1; }

# One X display for all the meshlabserver calls; Debian's python3 (it has python3-numpy).
exec xvfb-run -a -s "-screen 0 800x600x24" /usr/bin/python3 "$ROOT/scripts/evaluate_quality.py" "$@"
