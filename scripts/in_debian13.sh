#!/usr/bin/env bash
# Runs a command inside the project's Debian 13 root (made by setup_meshlab2022.sh), with the
# project folder mounted at /project. The mounts live in a private mount namespace, so nothing
# stays mounted on the host when the command ends. On a Debian 13 host (MeshLab 2022.02
# installed natively) the command runs directly, in the project folder.
#   in_debian13.sh COMMAND [ARGS...]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
source "$ROOT/scripts/debian13_env.sh"

if [ "$DEBIAN13_NATIVE" = 1 ]; then
  cd "$ROOT" && exec "$@"
fi
[ -f "$DEBIAN13_ROOT/.hht-root" ] || { echo "in_debian13: no Debian 13 root in $DEBIAN13_ROOT (run scripts/setup_meshlab2022.sh)" >&2; exit 1; }
SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
exec $SUDO unshare --mount --fork /bin/sh -c '
  set -e
  r=$1; project=$2; shift 2
  mount --make-rprivate /
  mount -t proc proc "$r/proc"
  mount --rbind /dev "$r/dev"
  mount --bind "$project" "$r/project"
  exec chroot "$r" /usr/bin/env -i HOME=/root PATH=/usr/local/bin:/usr/bin:/bin:/usr/sbin:/sbin \
    LANG=C.UTF-8 sh -c "cd /project && exec \"\$@\"" sh "$@"' sh "$DEBIAN13_ROOT" "$ROOT" "$@"
