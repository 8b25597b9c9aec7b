#!/usr/bin/env bash
# Reproduces the paper's denoising experiments as numbers, every method run through
# meshlabserver: Fandisk at 5% noise (Fig. 10), the meshed cube at 10% (Fig. 9), a torus at
# 10% (Fig. 8) and Fandisk at 30% (the usual level of the denoising literature); Gaussian noise
# in random directions, sigma in percent of the mean edge length, fixed seeds.
# Prints a Markdown table (E_a, E_v, time per method) and writes pictures into docs/images/.
# Time: the whole meshlabserver run of the method (start-up, load, filter, save), wall clock.
#   scripts/evaluate_denoising.sh [work-dir]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
WORK="$(realpath -m "${1:-$ROOT/build/evaluation}")"
SERVER="$ROOT/build/stage/bin/meshlabserver"
RENDER="$ROOT/build/tools/render_mesh"
IMAGES="$ROOT/docs/images"
mkdir -p "$WORK" "$IMAGES"
cd "$WORK"

server() { xvfb-run -a -s "-screen 0 800x600x24" "$SERVER" "$@" > "$WORK/last.log" 2>&1 || { echo "meshlabserver failed: $*" >&2; tail -5 "$WORK/last.log" >&2; return 1; }; }
script() {  # script <file> <filter xml>...
  local f="$1"; shift
  { echo '<!DOCTYPE FilterScript>'; echo '<FilterScript>'; printf '%s\n' "$@"; echo '</FilterScript>'; } > "$f"
}
resource_filter() { sed -n '/<filter /,/<\/filter>/p' "$ROOT/resources/$1.mlx"; }
with() {  # with <xml> name=value...: overrides parameter values
  local xml="$1"; shift
  for kv in "$@"; do xml="$(sed "s|name=\"${kv%%=*}\" value=\"[^\"]*\"|name=\"${kv%%=*}\" value=\"${kv#*=}\"|" <<< "$xml")"; done
  printf '%s\n' "$xml"
}

# Ground truths: two of libcgal-demo's meshes and a torus made by MeshLab.
cp "$ROOT/data/fandisk.off" fandisk.off
cp "$ROOT/data/cube-meshed.off" cube.off
script torus.mlx '<filter name="Torus"><Param type="RichFloat" name="hRadius" value="3"/><Param type="RichFloat" name="vRadius" value="1"/><Param type="RichInt" name="hSubdiv" value="128"/><Param type="RichInt" name="vSubdiv" value="48"/></filter>'
server -i fandisk.off -o torus.ply -s torus.mlx

twostep() { echo "<filter name=\"TwoStep Smooth\"><Param type=\"RichInt\" name=\"stepSmoothNum\" value=\"$1\"/><Param type=\"RichFloat\" name=\"normalThr\" value=\"60\"/><Param type=\"RichInt\" name=\"stepNormalNum\" value=\"20\"/><Param type=\"RichInt\" name=\"stepFitNum\" value=\"20\"/><Param type=\"RichBool\" name=\"Selected\" value=\"false\"/></filter>"; }
LAPLACIAN='<filter name="Laplacian Smooth"><Param type="RichInt" name="stepSmoothNum" value="3"/><Param type="RichBool" name="Boundary" value="true"/><Param type="RichBool" name="cotangentWeight" value="true"/><Param type="RichBool" name="Selected" value="false"/></filter>'
TAUBIN='<filter name="Taubin Smooth"><Param type="RichFloat" name="lambda" value="0.5"/><Param type="RichFloat" name="mu" value="-0.53"/><Param type="RichInt" name="stepSmoothNum" value="10"/><Param type="RichBool" name="Selected" value="false"/></filter>'
HC='<filter name="HC Laplacian Smooth"></filter>'

measure() {  # measure <truth> <mesh>: prints "E_a E_v"
  server -i "$1" -i "$2" -o compare_out.ply -s "$ROOT/resources/compare.mlx"
  local ea ev
  ea=$(grep -m1 -o 'E_a = [0-9.e+-]*' "$WORK/last.log" | awk '{print $3}')
  ev=$(grep -m1 -o 'E_v = [0-9.e+-]*' "$WORK/last.log" | awk '{print $3}')
  echo "$ea $ev"
}

echo "| case | method | E_a (degrees) | E_v (/ bbox diagonal) | time (s) |"
echo "|---|---|---|---|---|"
run_case() {  # run_case <name> <truth> <noise %> <seed> <features true|false> <bilateral sigma_s> <bilateral passes> <twostep steps>
  local name="$1" truth="$2" percent="$3" seed="$4" features="$5" sigma_s="$6" passes="$7" steps="$8"
  script noise.mlx "$(with "$(resource_filter add_noise)" sigmaPercent="$percent" seed="$seed")"
  server -i "$truth" -o "${name}_noisy.ply" -s noise.mlx
  read -r ea ev < <(measure "$truth" "${name}_noisy.ply")
  echo "| $name | noisy input | $ea | $ev | - |"
  local methods=(ours paper bilateral twostep laplacian taubin hc)
  script ours.mlx "$(with "$(resource_filter denoise)" detectFeatures="$features")"
  script paper.mlx "$(with "$(resource_filter denoise)" detectFeatures="$features" refineNormalPasses=0 paperStage=true untangle=false)"
  script bilateral.mlx "$(with "$(resource_filter bilateral)" sigmaS="$sigma_s" passes="$passes")"
  script twostep.mlx "$(twostep "$steps")"
  script laplacian.mlx "$LAPLACIAN"
  script taubin.mlx "$TAUBIN"
  script hc.mlx "$HC"
  for m in "${methods[@]}"; do
    local t0 t1
    t0=$(date +%s.%N)
    server -i "${name}_noisy.ply" -o "${name}_$m.ply" -s "$m.mlx"
    t1=$(date +%s.%N)
    read -r ea ev < <(measure "$truth" "${name}_$m.ply")
    local label
    case $m in
      ours) label="HHT: Feature-Preserving Denoise (denoise.mlx$([ "$features" = false ] && echo ', no features' || true))";;
      paper) label="HHT, the paper's method alone (paperStage on, untangle off, refineNormalPasses 0)";;
      bilateral) label="Bilateral (sigma_c 0.4, sigma_s $sigma_s, $passes passes)";;
      twostep) label="TwoStep Smooth ($steps steps, 60 deg, 20, 20)";;
      laplacian) label="Laplacian Smooth (defaults)";;
      taubin) label="Taubin Smooth (defaults)";;
      hc) label="HC Laplacian Smooth";;
    esac
    printf '| %s | %s | %s | %s | %.2f |\n' "$name" "$label" "$ea" "$ev" "$(echo "$t1 - $t0" | bc)"
  done
  if [ -x "$RENDER" ]; then
    "$RENDER" --azimuth "${AZIMUTH:-35}" --elevation "${ELEVATION:-25}" --size 360 \
      --title "ground truth|noisy ($percent%)|HHT denoise|bilateral|TwoStep" \
      "$IMAGES/denoise_$name.png" "$truth" "${name}_noisy.ply" "${name}_ours.ply" "${name}_bilateral.ply" "${name}_twostep.ply" >/dev/null
  fi
}
run_case fandisk_5 fandisk.off 5 11 true 0.05 3 3
run_case cube_10 cube.off 10 12 true 0.05 3 2
run_case torus_10 torus.ply 10 13 false 0.15 5 3
run_case fandisk_30 fandisk.off 30 14 true 0.05 3 3
