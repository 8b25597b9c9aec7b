#!/usr/bin/env bash
# Stages a private MeshLab prefix that loads the freshly built plugin without root:
# meshlabserver finds libmeshlab-common.so and its plugins relative to its own binary.
#   stage_meshlab.sh <stage-dir> <libfilter_hht.so>
set -euo pipefail
stage="$1"; plugin="$2"
system_lib=/usr/lib/x86_64-linux-gnu/meshlab
lib="$stage/lib/x86_64-linux-gnu/meshlab"
rm -rf "$stage"
mkdir -p "$stage/bin" "$lib/plugins"
cp /usr/bin/meshlabserver /usr/bin/meshlab "$stage/bin/"  # the GUI for tests/gui/meshlab2020_window_test.sh
ln -s "$system_lib/libmeshlab-common.so" "$lib/"
for p in "$system_lib"/plugins/*.so; do
  # an installed copy of this plugin must not shadow the one under test
  [ "$(basename "$p")" = libfilter_hht.so ] || ln -s "$p" "$lib/plugins/"
done
ln -s "$(realpath "$plugin")" "$lib/plugins/libfilter_hht.so"
