#!/usr/bin/env bash
# Idempotent set-up for a Debian 12 machine: Debian packages, the MeshLab 2020.09 sources
# matching the installed MeshLab (headers + vcglib, from Debian's source package), and the
# test meshes from libcgal-demo. Quick when everything is already there.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
THIRD="$ROOT/third_party"
DATA="$ROOT/data"
SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"

PACKAGES=(
  build-essential cmake pkg-config dpkg-dev xz-utils
  meshlab qtbase5-dev libqt5opengl5-dev libqt5xmlpatterns5-dev libglew-dev
  libeigen3-dev libsuitesparse-dev libfftw3-dev libgtest-dev
  # CHOLMOD's supernodal factorisation is BLAS-bound: Debian's reference BLAS is several times
  # slower (docs/benchmarks.md); OpenBLAS takes over libblas.so.3 through the alternatives.
  libopenblas0-pthread
  xvfb xauth libgl1-mesa-dri libcgal-demo bc time
  xdotool x11-apps netpbm
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

apt_updated=0
apt_update() { [ $apt_updated -eq 1 ] || { $SUDO apt-get update -qq; apt_updated=1; }; }

if [ ${#missing[@]} -gt 0 ]; then
  echo "[setup] installing Debian packages: ${missing[*]}"
  apt_update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# MeshLab sources matching the installed package (headers and vcglib are not packaged).
MESHLAB_VERSION="$(dpkg-query -W -f='${Version}' meshlab)"
SRC_STAMP="$THIRD/meshlab-src/.debian-version"
if [ ! -f "$SRC_STAMP" ] || [ "$(cat "$SRC_STAMP")" != "$MESHLAB_VERSION" ]; then
  if ! grep -rqsE '^(Types:.*deb-src|deb-src )' /etc/apt/sources.list /etc/apt/sources.list.d/; then
    echo "[setup] enabling a deb-src entry for Debian's main archive"
    if [ -f /etc/apt/sources.list.d/debian.sources ]; then
      sed 's/^Types: deb$/Types: deb-src/' /etc/apt/sources.list.d/debian.sources \
        | $SUDO tee /etc/apt/sources.list.d/filter-hht-deb-src.sources >/dev/null
    else
      grep -E '^deb ' /etc/apt/sources.list | sed 's/^deb /deb-src /' \
        | $SUDO tee /etc/apt/sources.list.d/filter-hht-deb-src.list >/dev/null
    fi
    apt_updated=0
  fi
  apt_update
  echo "[setup] fetching MeshLab $MESHLAB_VERSION sources (Debian source package)"
  rm -rf "$THIRD/meshlab-src" "$THIRD/apt-source"
  mkdir -p "$THIRD/apt-source"
  (cd "$THIRD/apt-source" && apt-get source -qq "meshlab=$MESHLAB_VERSION" >/dev/null 2>&1 \
     || apt-get source -qq meshlab >/dev/null)
  src_dir="$(find "$THIRD/apt-source" -maxdepth 1 -mindepth 1 -type d -name 'meshlab-*' | head -n1)"
  [ -n "$src_dir" ] || { echo "[setup] apt-get source meshlab produced no tree" >&2; exit 1; }
  mv "$src_dir" "$THIRD/meshlab-src"
  rm -rf "$THIRD/apt-source"
  echo "$MESHLAB_VERSION" > "$SRC_STAMP"
fi
[ -f "$THIRD/meshlab-src/src/common/interfaces.h" ] || [ -d "$THIRD/meshlab-src/src/common" ] \
  || { echo "[setup] MeshLab sources incomplete in $THIRD/meshlab-src" >&2; exit 1; }

# Test meshes from libcgal-demo's data archive.
mkdir -p "$DATA"
CGAL_DATA=/usr/share/doc/libcgal-dev/data.tar.gz
for m in fandisk cube-meshed armadillo elephant elephant-with-holes sphere cow bull femur camel blade turbine spool rotor anchor_dense mannequin-devil handle boeing; do
  if [ ! -s "$DATA/$m.off" ]; then
    tar -xzf "$CGAL_DATA" -C "$DATA" --strip-components=2 "data/meshes/$m.off"
  fi
done
echo "[setup] ready: MeshLab $MESHLAB_VERSION, sources in third_party/meshlab-src, meshes in data/"
