# Sourced by the MeshLab 2022.02 scripts: where the Debian 13 root, the MeshLab 2022.02
# sources and the 2022.02 build live. Expects ROOT (the project folder) to be set.
# DEBIAN13_NATIVE=1 on a Debian 13 host: no root is made, the system MeshLab is used.
DEBIAN13_ROOT="${HHT_DEBIAN13_ROOT:-$ROOT/build/debian13/root}"
MESHLAB2022_SRC="$ROOT/third_party/meshlab-2022.02-src"
DEBIAN13_NATIVE=0
if [ "$(. /etc/os-release && echo "${VERSION_CODENAME:-}")" = trixie ]; then DEBIAN13_NATIVE=1; fi
# The 2022.02 build folder, seen from the host and from the command run by in_debian13.sh.
MESHLAB2022_BUILD="$ROOT/build/meshlab2022"
if [ "$DEBIAN13_NATIVE" = 1 ]; then MESHLAB2022_BUILD_INSIDE="$MESHLAB2022_BUILD"; PROJECT_INSIDE="$ROOT"
else MESHLAB2022_BUILD_INSIDE=/project/build/meshlab2022; PROJECT_INSIDE=/project; fi
