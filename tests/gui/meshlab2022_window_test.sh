#!/bin/sh
# The real MeshLab 2022.02 window, under Xvfb in the Debian 13 root, driven with xdotool:
# open Fandisk, open Filters > Quality Measure and Computations (the HHT filters are listed
# there), click "HHT: Curvature Signal", press Apply in its dialog. Passes when the dialog of
# that filter opened and the mesh on screen went from grey to the curvature colour ramp.
#   scripts/in_debian13.sh sh tests/gui/meshlab2022_window_test.sh PLUGIN.so OUT_DIR
# Screenshots: OUT_DIR/{start,filters_menu,applied}.png. Screen positions are those of this
# root's MeshLab 2022.02 at 1280x900 (the window has no window manager, so it does not move).
set -eu
plugin=$1; out=$2
mkdir -p "$out"
# The root is this project's test environment: the plugin goes where its MeshLab looks.
cp "$plugin" /usr/lib/x86_64-linux-gnu/meshlab/plugins/libfilter_hht.so
tmp=$(mktemp -d)
Xvfb :57 -screen 0 1280x900x24 -nolisten tcp > "$tmp/xvfb.log" 2>&1 &
xvfb=$!
export DISPLAY=:57
meshlab=""
cleanup() { [ -z "$meshlab" ] || kill "$meshlab" 2>/dev/null || true; kill "$xvfb" 2>/dev/null || true; rm -rf "$tmp"; }
trap cleanup EXIT
for _ in 1 2 3 4 5 6 7 8 9 10; do xdotool getdisplaygeometry > /dev/null 2>&1 && break; sleep 0.5; done
meshlab /project/data/fandisk.off > "$out/meshlab.log" 2>&1 &
meshlab=$!
window=$(timeout 60 xdotool search --sync --onlyvisible --name "^MeshLab 2022" | head -n1)
sleep 2
xdotool windowmove "$window" 0 0 windowsize "$window" 1280 900
sleep 3

# shot NAME: the screen, open menus included, as $out/NAME.png and $tmp/NAME.ppm.
. "$(dirname "$0")/screen_shot.sh"
# Pixels of the 3D view coloured red to yellow (the low end of MeshLab's quality ramp): none
# on the grey mesh and blue background MeshLab starts with.
ramp_pixels() {
  pamcut -left 0 -top 70 -width 870 -height 700 "$tmp/$1.ppm" | ppmhist -noheader 2> /dev/null \
    | awk '$1 > 150 && $1 > $3 + 80 { n += $5 } END { print n + 0 }'
}

shot start
xdotool mousemove 116 9 click 1                                      # Filters
sleep 1
xdotool mousemove 190 238 sleep 0.5 mousemove 205 240                 # Quality Measure and Computations
sleep 2
shot filters_menu
xdotool mousemove 520 440 sleep 0.3 mousemove 576 451 sleep 0.5 click 1  # HHT: Curvature Signal
sleep 2
dialog=$(timeout 10 xdotool search --sync --onlyvisible --name "^HHT: Curvature Signal$" | head -n1) || true
if [ -z "$dialog" ]; then
  shot failed
  echo "FAIL: no 'HHT: Curvature Signal' dialog opened from Filters > Quality Measure and Computations; see $out/failed.png"
  exit 1
fi
eval "$(xdotool getwindowgeometry --shell "$dialog")"
xdotool mousemove $((X + WIDTH - 85)) $((Y + HEIGHT - 21)) sleep 0.3 click 1   # Apply
sleep 3
xdotool mousemove $((X + 80)) $((Y + HEIGHT - 21)) sleep 0.3 click 1           # Close
sleep 2
shot applied

before=$(ramp_pixels start); after=$(ramp_pixels applied)
echo "ramp-coloured pixels in the 3D view: $before before, $after after applying HHT: Curvature Signal"
grep -h "Curvature signal\|Applied filter" "$out/meshlab.log" || true
if [ "$before" -gt 5000 ] || [ "$after" -lt 20000 ]; then
  echo "FAIL: the mesh on screen did not take the curvature colours; see $out/applied.png"
  exit 1
fi
echo "PASS"
