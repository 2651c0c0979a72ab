# Sourced by the scripts in docker/: sets `podman` to rootful podman on the storage the builds use.
# PORESPH_PODMAN_STORAGE: overlay or vfs. Default overlay where the kernel mounts an overlay on
# /var/lib/containers (each layer holds only what its step changed), else vfs (each layer a full
# copy of the root file system: ~80 GB free for the GPU image). The overlay store has its own
# folders, so a machine that has built with vfs keeps those images in the default store.
poresph_storage() {
  local probe
  mkdir -p /var/lib/containers 2>/dev/null
  probe=$(mktemp -d /var/lib/containers/poresph-probe.XXXXXX 2>/dev/null) || { echo vfs; return; }
  mkdir "$probe"/{l,u,w,m}
  if mount -t overlay overlay -o "lowerdir=$probe/l,upperdir=$probe/u,workdir=$probe/w" \
      "$probe/m" 2>/dev/null; then
    umount "$probe/m"
    echo overlay
  else
    echo vfs
  fi
  rm -rf "$probe"
}
PORESPH_PODMAN_STORAGE=${PORESPH_PODMAN_STORAGE:-$(poresph_storage)}
export PORESPH_PODMAN_STORAGE
case $PORESPH_PODMAN_STORAGE in
  overlay) podman=(podman --storage-driver overlay --root /var/lib/containers/storage-overlay
                   --runroot /run/containers/storage-overlay) ;;
  vfs) podman=(podman --storage-driver vfs) ;;
  *) echo "PORESPH_PODMAN_STORAGE: expected overlay or vfs, not '$PORESPH_PODMAN_STORAGE'" >&2
     exit 2 ;;
esac
