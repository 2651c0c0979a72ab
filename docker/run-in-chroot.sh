#!/usr/bin/env bash
# Runs an image's entry point as `docker run --rm [-v DIR:PATH] [--user UID] IMAGE [ARGS...]` would,
# in a chroot of the image's files, for machines where no container can start (`podman run` needs
# a runtime allowed to set rlimits, which some sandboxes refuse): the image's files, environment,
# user and working folder, the host's network and processes; no namespaces, no limits. Root only.
#   docker/run-in-chroot.sh [-v HOSTDIR:PATH]... [--user UID[:GID]] [--entrypoint CMD] IMAGE [ARGS...]
set -euo pipefail
binds=() user="" entrypoint=""
while [[ $# -gt 0 ]]; do
  case $1 in
    -v) binds+=("$2"); shift 2 ;;
    --user) user=$2; shift 2 ;;
    --entrypoint) entrypoint=$2; shift 2 ;;
    *) break ;;
  esac
done
[[ $# -ge 1 ]] || { echo "usage: $0 [-v HOSTDIR:PATH]... [--user UID[:GID]] [--entrypoint CMD] IMAGE [ARGS...]" >&2; exit 2; }
image=$1
shift
source "$(dirname "${BASH_SOURCE[0]}")/podman-storage.sh"
cfg() { "${podman[@]}" image inspect --format "$1" "$image"; }

# The image's files, mounted where every user may traverse the path (podman's own is root's only).
root=$(mktemp -d /tmp/poresph-chroot.XXXXXX)
chmod 755 "$root"
mounted=()
cleanup() {
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -l "${mounted[i]}" 2>/dev/null || true; done
  "${podman[@]}" image unmount "$image" >/dev/null 2>&1 || true
  rmdir "$root" 2>/dev/null || true
}
trap cleanup EXIT
mnt_at() { mount "$@"; mounted+=("${!#}"); }
mnt_at --bind "$("${podman[@]}" image mount "$image")" "$root"
mnt_at --bind /proc "$root/proc"
mnt_at --bind /dev "$root/dev"
mnt_at -t tmpfs tmpfs "$root/dev/shm"
mnt_at -t tmpfs -o mode=1777 tmpfs "$root/tmp"
for b in "${binds[@]}"; do
  mkdir -p "$root/${b#*:}"
  mnt_at --bind "${b%%:*}" "$root/${b#*:}"
done

user=${user:-$(cfg '{{.Config.User}}')}
user=${user:-root}
uid=$(chroot "$root" id -u "${user%%:*}" 2>/dev/null || echo "${user%%:*}")
gid=${user#*:}
[[ $gid != "$user" ]] || gid=$(chroot "$root" id -g "$uid" 2>/dev/null || echo "$uid")
home=$(chroot "$root" getent passwd "$uid" | cut -d: -f6) || home=/
workdir=$(cfg '{{.Config.WorkingDir}}')
mapfile -t env < <(cfg '{{range .Config.Env}}{{println .}}{{end}}' | sed '/^$/d')
mapfile -t entry < <(cfg '{{range .Config.Entrypoint}}{{println .}}{{end}}' | sed '/^$/d')
[[ -z $entrypoint ]] || entry=("$entrypoint")
[[ $# -gt 0 ]] || mapfile -t args < <(cfg '{{range .Config.Cmd}}{{println .}}{{end}}' | sed '/^$/d')
[[ $# -eq 0 ]] || args=("$@")
cd /
env -i "${env[@]}" HOME="$home" chroot --userspec="$uid:$gid" "$root" \
  sh -c 'cd "$0" && exec "$@"' "${workdir:-/}" "${entry[@]}" "${args[@]}" &
child=$!
# A stop goes to the entry point (as `docker stop` does), which ends before the mounts go.
trap 'kill -TERM "$child" 2>/dev/null' TERM INT
status=0
while kill -0 "$child" 2>/dev/null; do wait "$child" && status=0 || status=$?; done
exit "$status"
