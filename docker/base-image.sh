#!/usr/bin/env bash
# Makes a local Debian 12 base image for the builds where no registry is reachable:
# debootstrap (minbase) from the Debian mirror, then `podman import`. Rootful podman, on the
# storage docker/podman-storage.sh chooses.
#   docker/base-image.sh [TAG]     default TAG localhost/poresph-base:debian12
# The image holds the same packages as Docker Hub's debian:12 (minbase) and the same apt sources
# (bookworm, bookworm-updates, bookworm-security); nothing of this machine goes into it.
set -euo pipefail
tag=${1:-localhost/poresph-base:debian12}
mirror=${DEBIAN_MIRROR:-http://deb.debian.org/debian}
source "$(dirname "${BASH_SOURCE[0]}")/podman-storage.sh"

if "${podman[@]}" image exists "$tag"; then
  echo "base-image: $tag exists"
  exit 0
fi
[[ $(id -u) -eq 0 ]] || { echo "base-image: debootstrap and rootful podman need root" >&2; exit 2; }
command -v debootstrap >/dev/null || { apt-get update -qq && apt-get install -y -qq --no-install-recommends debootstrap >/dev/null; }

root=$(mktemp -d /var/tmp/poresph-base.XXXXXX)
trap 'rm -rf "$root"' EXIT
chmod 755 "$root"  # the image's / (mktemp makes it root's only, and no other user could run anything)
echo "base-image: debootstrap bookworm from $mirror (a few minutes)"
debootstrap --variant=minbase bookworm "$root" "$mirror" >"$root.log" 2>&1 || {
  tail -20 "$root.log" >&2; echo "base-image: debootstrap failed (log $root.log)" >&2; exit 1; }
rm -f "$root.log"
rm -f "$root/etc/apt/sources.list"
cat >"$root/etc/apt/sources.list.d/debian.sources" <<SOURCES
Types: deb
URIs: ${mirror}
Suites: bookworm bookworm-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg

Types: deb
URIs: ${mirror}-security
Suites: bookworm-security
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SOURCES
# As Docker's debian images: no apt cache kept, no recommends, no man pages' doc trees.
rm -rf "$root"/var/lib/apt/lists/* "$root"/var/cache/apt/*.bin "$root"/var/cache/apt/archives/*.deb
printf 'APT::Install-Recommends "false";\n' >"$root/etc/apt/apt.conf.d/90poresph-norecommends"
: >"$root/etc/resolv.conf"
tar -C "$root" --numeric-owner -c . | "${podman[@]}" import -q \
  --change 'CMD ["bash"]' --change 'ENV LANG=C.UTF-8' - "$tag" >/dev/null
echo "base-image: $tag ($("${podman[@]}" image inspect --format '{{.Size}}' "$tag") bytes)"
