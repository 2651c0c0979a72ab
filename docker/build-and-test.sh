#!/usr/bin/env bash
# Builds poresph's container images with podman (rootful; overlay or vfs storage, as
# docker/podman-storage.sh finds; chroot isolation, host network) and tests them. The tests run
# inside the builds: ctest in the build stage, docker/smoke-test.sh as the image's user in the
# runtime stage (`podman run` needs a runtime allowed to set rlimits, which some sandboxes refuse).
#   docker/build-and-test.sh [cpu|cuda|all]            default all
# Environment:
#   PORESPH_BASE_IMAGE  a Debian 12 image; default docker.io/library/debian:12 where it can be
#                       pulled, else localhost/poresph-base:debian12 (docker/base-image.sh)
#   PORESPH_CUDA_IMAGE  an image with the CUDA toolkit in /usr/local/cuda; default NVIDIA's devel
#                       image where it can be pulled, else one made from this machine's toolkit
#                       (docker/cuda-toolkit-image.sh)
#   CTEST_ARGS          the build stage's tests (default "-LE validation"; "" runs all)
#   PORESPH_ROCKS       segmented rock images for the tests (default ../shared/data/rocks)
# Each image's build log goes to build/docker/<image>.log; build time and size to build/docker/images.txt.
set -euo pipefail
cd "$(dirname "$0")/.."
what=${1:-all}
[[ $what =~ ^(cpu|cuda|all)$ ]] || { echo "build-and-test: expected cpu, cuda or all, not '$what'" >&2; exit 2; }
[[ $(id -u) -eq 0 ]] || { echo "build-and-test: rootful podman and debootstrap: run it as root" >&2; exit 2; }
# podman from Debian (docker/base-image.sh installs debootstrap when it needs it).
command -v podman >/dev/null || { apt-get update -qq &&
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends podman >/dev/null; }
source "$(dirname "${BASH_SOURCE[0]}")/podman-storage.sh"
out=build/docker
mkdir -p "$out"

pullable() { timeout 600 "${podman[@]}" pull -q "$1" >/dev/null 2>&1; }

base=${PORESPH_BASE_IMAGE:-docker.io/library/debian:12}
if [[ -z ${PORESPH_BASE_IMAGE:-} ]] && ! pullable "$base"; then
  base=localhost/poresph-base:debian12
  docker/base-image.sh "$base"
fi
echo "build-and-test: base image $base, $PORESPH_PODMAN_STORAGE storage"

# A network that re-signs TLS (a proxy's own CA in /usr/local/share/ca-certificates) also re-signs
# npm's registry: npm gets those certificates as a build secret, which never enters an image.
secret=()
extra=(/usr/local/share/ca-certificates/*.crt)
if [[ -e ${extra[0]} ]]; then
  ca=$(mktemp)
  trap 'rm -f "$ca"' EXIT
  cat "${extra[@]}" >"$ca"
  secret=(--secret "id=npm-ca,src=$ca")
fi
rocks_dir=${PORESPH_ROCKS:-../shared/data/rocks}
rocks=()
[[ -f $rocks_dir/berea_110.raw ]] && rocks=(-v "$(readlink -f "$rocks_dir"):/rocks:ro")

# build NAME DOCKERFILE [BUILD ARGS...]: builds localhost/poresph:NAME and records time and size.
build() {
  local name=$1 file=$2 tag=localhost/poresph:$1 t0=$SECONDS
  shift 2
  echo "build-and-test: building $tag from $file (log $out/$name.log)"
  if ! "${podman[@]}" build --isolation chroot --network host --layers -f "$file" -t "$tag" \
      --build-arg "BASE=$base" --build-arg "CTEST_ARGS=${CTEST_ARGS--LE validation}" \
      "${secret[@]}" "${rocks[@]}" "$@" . >"$out/$name.log" 2>&1; then
    tail -40 "$out/$name.log" >&2
    echo "build-and-test: $tag failed to build or its tests failed (log $out/$name.log)" >&2
    return 1
  fi
  local size
  size=$("${podman[@]}" image inspect --format '{{.Size}}' "$tag")
  echo "$(date -u +%FT%TZ) $tag built and tested in $((SECONDS - t0)) s, $((size / 1000000)) MB" | tee -a "$out/images.txt"
}

if [[ $what != cuda ]]; then build cpu docker/Dockerfile; fi
if [[ $what != cpu ]]; then
  cuda_image=${PORESPH_CUDA_IMAGE:-docker.io/nvidia/cuda:13.0.2-devel-ubuntu24.04}
  if [[ -z ${PORESPH_CUDA_IMAGE:-} ]] && ! pullable "$cuda_image"; then
    cuda_image=$(docker/cuda-toolkit-image.sh | tail -1)
  fi
  echo "build-and-test: CUDA toolkit from $cuda_image"
  build cuda docker/Dockerfile.cuda --build-arg "CUDA_IMAGE=$cuda_image"
fi
