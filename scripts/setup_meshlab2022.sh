#!/usr/bin/env bash
# Idempotent set-up of the MeshLab 2022.02 side on a Debian 12 machine: a Debian 13 ("trixie")
# root made by debootstrap in build/debian13/root (git-ignored), Debian 13's meshlab 2022.02
# and the build dependencies installed into it from the archive, and MeshLab 2022.02's sources
# (for the headers; Debian ships none) unpacked into third_party/meshlab-2022.02-src.
# On a Debian 13 host the packages go onto the host itself and no root is made.
# Quick when everything is already there. Exits 3 (after saying why) when this machine cannot
# make the root (no debootstrap rights): the caller then skips the 2022.02 part.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$ROOT/scripts/debian13_env.sh"
SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
MIRROR="${HHT_DEBIAN_MIRROR:-http://deb.debian.org/debian}"
KEYRING=/usr/share/keyrings/debian-archive-keyring.gpg

# meshlab's own plugins need the five libraries after it (filter_func, filter_qhull, io_3ds,
# io_ctm, io_e57 do not load without them); then the build and test tools.
PACKAGES=(
  meshlab lib3ds-1-3 libmuparser2v5 libopenctm1 libqhull-r8.0 libxerces-c3.2t64
  g++ cmake make pkg-config xz-utils qtbase5-dev libqt5opengl5-dev libqt5xmlpatterns5-dev
  libglew-dev libeigen3-dev libsuitesparse-dev libfftw3-dev
  xvfb xauth libgl1-mesa-dri xdotool x11-apps netpbm
)
in_root() { "$ROOT/scripts/in_debian13.sh" "$@"; }
skip() { echo "[meshlab2022] SKIPPED: $*" >&2; exit 3; }
start=$SECONDS

if [ "$DEBIAN13_NATIVE" = 0 ]; then
  if [ -n "$SUDO" ] && ! sudo -n true 2>/dev/null; then
    skip "making the Debian 13 root needs root rights (debootstrap, chroot, unshare) and sudo asks for a password"
  fi
  if ! command -v debootstrap >/dev/null; then
    echo "[meshlab2022] installing debootstrap"
    $SUDO apt-get install -y -qq --no-install-recommends debootstrap >/dev/null
  fi
  $SUDO unshare --mount true 2>/dev/null \
    || skip "this machine refuses a private mount namespace (unshare --mount), needed to enter the root"
  if [ ! -f "$DEBIAN13_ROOT/.hht-root" ]; then
    echo "[meshlab2022] making a Debian 13 root in $DEBIAN13_ROOT (debootstrap, a few minutes)"
    $SUDO rm -rf "$DEBIAN13_ROOT"
    mkdir -p "$(dirname "$DEBIAN13_ROOT")"
    $SUDO debootstrap --variant=minbase --keyring="$KEYRING" trixie "$DEBIAN13_ROOT" "$MIRROR" \
      > "$(dirname "$DEBIAN13_ROOT")/debootstrap.log" 2>&1 \
      || { echo "[meshlab2022] debootstrap failed; see $(dirname "$DEBIAN13_ROOT")/debootstrap.log" >&2; exit 1; }
    printf 'deb %s trixie main\ndeb-src %s trixie main\n' "$MIRROR" "$MIRROR" \
      | $SUDO tee "$DEBIAN13_ROOT/etc/apt/sources.list" >/dev/null
    $SUDO mkdir -p "$DEBIAN13_ROOT/project"
    $SUDO touch "$DEBIAN13_ROOT/.hht-root"
  fi
  $SUDO cp /etc/resolv.conf "$DEBIAN13_ROOT/etc/resolv.conf"
fi

# Packages: only the missing ones are installed (one dpkg-query when nothing is missing).
missing="$(in_root sh -c 'for p in "$@"; do dpkg-query -W -f="\${Status}" "$p" 2>/dev/null \
  | grep -q "install ok installed" || echo "$p"; done' sh "${PACKAGES[@]}" | tr '\n' ' ')"
if [ -n "${missing// }" ]; then
  echo "[meshlab2022] installing into Debian 13: $missing"
  in_root sh -c 'export DEBIAN_FRONTEND=noninteractive; apt-get update -qq \
    && apt-get install -y -qq --no-install-recommends "$@" > /var/log/hht-install.log 2>&1 \
    || { tail -20 /var/log/hht-install.log; exit 1; }' sh $missing
fi
MESHLAB_VERSION="$(in_root dpkg-query -W -f='${Version}' meshlab)"
case "$MESHLAB_VERSION" in 2022.02*) ;; *) echo "[meshlab2022] expected meshlab 2022.02, got $MESHLAB_VERSION" >&2; exit 1;; esac

# Sources: apt-get source fails here (the .dsc is not served) but the .orig.tar.xz downloads;
# it is checked against the archive's Sources index and unpacked by hand.
SRC_STAMP="$MESHLAB2022_SRC/.debian-version"
if [ ! -f "$SRC_STAMP" ] || [ "$(cat "$SRC_STAMP")" != "$MESHLAB_VERSION" ]; then
  echo "[meshlab2022] fetching MeshLab $MESHLAB_VERSION sources (.orig.tar.xz of Debian's source package)"
  upstream="${MESHLAB_VERSION%-*}"
  orig="meshlab_${upstream}.orig.tar.xz"
  download="$ROOT/build/debian13/source"
  mkdir -p "$download"
  download_inside="${download/#$ROOT//project}"; [ "$DEBIAN13_NATIVE" = 1 ] && download_inside="$download"
  in_root sh -c 'cd "$1" && { apt-get update -qq; apt-get source --download-only -qq "meshlab=$2" >/dev/null 2>&1 || true; }
    test -s "$3" || { echo "apt-get source did not download $3" >&2; exit 1; }
    expected="$(apt-cache showsrc meshlab | sed -n "/^Checksums-Sha256:/,/^[A-Z]/p" | awk -v f="$3" "\$3 == f {print \$1}" | head -n1)"
    test -n "$expected" || { echo "no checksum for $3 in the Sources index" >&2; exit 1; }
    echo "$expected  $3" | sha256sum -c --quiet -' sh "$download_inside" "$MESHLAB_VERSION" "$orig"
  rm -rf "$MESHLAB2022_SRC" "$download/unpack"
  mkdir -p "$download/unpack"
  tar -xJf "$download/$orig" -C "$download/unpack"
  mv "$download/unpack"/meshlab-* "$MESHLAB2022_SRC"
  rm -rf "$download"
  echo "$MESHLAB_VERSION" > "$SRC_STAMP"
fi
[ -f "$MESHLAB2022_SRC/src/common/plugins/interfaces/filter_plugin.h" ] \
  || { echo "[meshlab2022] MeshLab sources incomplete in $MESHLAB2022_SRC" >&2; exit 1; }
echo "[meshlab2022] ready: MeshLab $MESHLAB_VERSION in ${DEBIAN13_ROOT/#$ROOT\//} ($((SECONDS - start)) s)," \
  "sources in ${MESHLAB2022_SRC/#$ROOT\//}"
