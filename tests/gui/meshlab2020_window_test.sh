#!/bin/sh
# The real MeshLab 2020.09 window (Debian 12's `meshlab`), under a private Xvfb, driven with
# xdotool: the staged MeshLab (build/stage: the freshly built plugin, no root) opens a noisy
# Fandisk; Filters > Smoothing, Fairing and Deformation > HHT: Feature-Preserving Denoise; Apply
# in its dialog. Passes when that dialog opened, MeshLab's log shows the filter's own lines and
# "Applied filter", and the mesh on screen changed (pixels of the 3D view before and after).
#   sh tests/gui/meshlab2020_window_test.sh STAGE_DIR OUT_DIR [IMAGES_DIR]
# Screenshots in OUT_DIR: start_flat, start, filters_menu, dialog, applied, applied_flat (.png;
# the comparison is made in per-vertex shading, the flat ones are for the eye); with IMAGES_DIR, the
# README's pictures are written there too (meshlab2020_filters_menu.png, meshlab2020_denoise_before.png,
# meshlab2020_denoise_after.png). Screen positions are those of MeshLab 2020.09 at 1280x900 (no window
# manager: the window does not move).
set -eu
stage=$(realpath "$1"); out=$(realpath -m "$2"); images=${3:-}
root=$(cd "$(dirname "$0")/../.." && pwd)
mkdir -p "$out"
tmp=$(mktemp -d)
Xvfb -displayfd 3 -screen 0 1280x900x24 -nolisten tcp 3> "$tmp/display" > "$tmp/xvfb.log" 2>&1 &
xvfb=$!
meshlab=""
cleanup() { [ -z "$meshlab" ] || kill "$meshlab" 2>/dev/null || true; kill "$xvfb" 2>/dev/null || true; rm -rf "$tmp"; }
trap cleanup EXIT
for _ in $(seq 50); do [ -s "$tmp/display" ] && break; sleep 0.2; done
export DISPLAY=":$(cat "$tmp/display")"

# The input: Fandisk with the paper's 10% noise (resources/add_noise.mlx), by the staged meshlabserver.
"$stage/bin/meshlabserver" -i "$root/data/fandisk.off" -o "$out/fandisk_noisy.ply" \
  -s "$root/resources/add_noise.mlx" > "$out/noise.log" 2>&1

"$stage/bin/meshlab" "$out/fandisk_noisy.ply" > "$out/meshlab.log" 2>&1 &
meshlab=$!
window=$(timeout 60 xdotool search --sync --onlyvisible --name "^MeshLab 2020" | head -n1)
sleep 2
xdotool windowmove "$window" 0 0 windowsize "$window" 1280 900
sleep 3

# shot NAME: the screen, open menus included, as $out/NAME.png and $tmp/NAME.ppm.
. "$(dirname "$0")/screen_shot.sh"
# The 3D view (left of the layer panel, above the info bar).
view() { pamcut -left 0 -top 72 -width 860 -height 705 "$tmp/$1.ppm"; }

shot start_flat
# Smooth (per-vertex) shading for the comparison: MeshLab switches to it after a filter that
# updates the normals, which alone would change the picture of an unchanged mesh.
xdotool mousemove 1048 496 sleep 0.3 click 1                         # Shading: Vert
sleep 2
shot start
grep -q "Plugins Dir is: $stage" "$out/meshlab.log" || {
  echo "FAIL: MeshLab did not load the staged plugins from $stage:"; head -5 "$out/meshlab.log"; exit 1; }
xdotool mousemove 120 10 click 1                                     # Filters
sleep 1
xdotool mousemove 240 236 sleep 0.5 mousemove 250 237                # Smoothing, Fairing and Deformation
sleep 2
shot filters_menu
xdotool mousemove 560 237 sleep 0.3 mousemove 600 412 sleep 0.5 click 1  # HHT: Feature-Preserving Denoise
sleep 2
dialog=$(timeout 10 xdotool search --sync --onlyvisible --name "^HHT: Feature-Preserving Denoise$" | head -n1) || true
if [ -z "$dialog" ]; then
  shot failed
  echo "FAIL: no 'HHT: Feature-Preserving Denoise' dialog opened from Filters > Smoothing, Fairing and Deformation; see $out/failed.png"
  exit 1
fi
shot dialog
eval "$(xdotool getwindowgeometry --shell "$dialog")"
xdotool mousemove $((X + WIDTH - 145)) $((Y + HEIGHT - 23)) sleep 0.3 click 1   # Apply
for _ in $(seq 60); do grep -q "Applied filter HHT: Feature-Preserving Denoise" "$out/meshlab.log" && break; sleep 0.5; done
xdotool mousemove $((X + 144)) $((Y + HEIGHT - 23)) sleep 0.3 click 1          # Close
sleep 3
shot applied
xdotool mousemove 1093 496 sleep 0.3 click 1                         # Shading: Face (the README's pictures)
sleep 2
shot applied_flat

grep "LOG: " "$out/meshlab.log" || true
status=0
grep -q "LOG: [0-9] Feature-preserving denoise: noise sigma" "$out/meshlab.log" || {
  echo "FAIL: the log has no line of the filter (Feature-preserving denoise: noise sigma ...)"; status=1; }
grep -q "Applied filter HHT: Feature-Preserving Denoise" "$out/meshlab.log" || {
  echo "FAIL: MeshLab did not report the filter as applied"; status=1; }
view start > "$tmp/view_before.ppm"; view applied > "$tmp/view_after.ppm"
changed=$(pamarith -difference "$tmp/view_before.ppm" "$tmp/view_after.ppm" | ppmtopgm \
  | pgmhist -machine 2> /dev/null | awk '$1 > 24 { n += $2 } END { print n + 0 }')
echo "3D view pixels changed by the filter: $changed"
if [ "$changed" -lt 2000 ]; then
  echo "FAIL: the mesh on screen did not change; see $out/start.png and $out/applied.png"; status=1
fi
if [ -n "$images" ] && [ $status -eq 0 ]; then
  mkdir -p "$images"
  pamcut -left 0 -top 0 -width 830 -height 900 "$tmp/filters_menu.ppm" | pnmtopng > "$images/meshlab2020_filters_menu.png"
  pamcut -left 150 -top 230 -width 600 -height 420 "$tmp/start_flat.ppm" | pnmtopng > "$images/meshlab2020_denoise_before.png"
  pamcut -left 150 -top 230 -width 600 -height 420 "$tmp/applied_flat.ppm" | pnmtopng > "$images/meshlab2020_denoise_after.png"
fi
[ $status -eq 0 ] && echo "PASS"
exit $status
