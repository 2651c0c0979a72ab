#!/usr/bin/env bash
# docker/podman-storage.sh: the storage the image builds use, and a clear error for a bad choice.
#   podman_storage.sh SOURCE_DIR
set -uo pipefail
lib=$1/docker/podman-storage.sh
fail() { echo "FAIL: $*" >&2; exit 1; }
pick() { PORESPH_PODMAN_STORAGE=$1 bash -c 'source "$0" && echo "${podman[*]}"' "$lib" 2>&1; }

out=$(pick zfs) && fail "zfs was accepted: $out"
[[ $out == *PORESPH_PODMAN_STORAGE*overlay*vfs*zfs* ]] || fail "unclear error for zfs: $out"
[[ $(pick vfs) == "podman --storage-driver vfs" ]] || fail "vfs: $(pick vfs)"
out=$(pick overlay)
[[ $out == *"--storage-driver overlay"*"--root /var/lib/containers/storage-overlay"* ]] ||
  fail "overlay must have its own store: $out"
# Unset: overlay where this machine mounts one (root only), else vfs.
out=$(pick "")
case $out in
  *"--storage-driver overlay"*) [[ $(id -u) -eq 0 ]] || fail "overlay chosen without root" ;;
  "podman --storage-driver vfs") ;;
  *) fail "default: $out" ;;
esac
[[ -z $(ls -d /var/lib/containers/poresph-probe.* 2>/dev/null) ]] || fail "the probe left its folder"
echo "podman storage: ${out#podman }"
