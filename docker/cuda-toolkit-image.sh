#!/usr/bin/env bash
# Makes a CUDA toolkit image from a toolkit installed on this machine, for building
# docker/Dockerfile.cuda where NVIDIA's registry is not reachable. The image holds only what the
# build takes from NVIDIA's devel images: /usr/local/cuda-<version> (nvcc and its tools, NVVM,
# headers with CCCL, the CUDA runtime libraries) and the /usr/local/cuda link. No OS.
#   docker/cuda-toolkit-image.sh [TAG]    default TAG localhost/poresph-cuda-toolkit:<version>
# CUDA_HOME (default /usr/local/cuda) names the toolkit. Prints the tag on its last line.
set -euo pipefail
cuda=$(readlink -f "${CUDA_HOME:-/usr/local/cuda}")
[[ -x $cuda/bin/nvcc ]] || { echo "cuda-toolkit-image: no nvcc in $cuda/bin (set CUDA_HOME)" >&2; exit 2; }
version=$("$cuda/bin/nvcc" --version | sed -n 's/.*release \([0-9.]*\),.*/\1/p')
tag=${1:-localhost/poresph-cuda-toolkit:$version}
source "$(dirname "${BASH_SOURCE[0]}")/podman-storage.sh"
if "${podman[@]}" image exists "$tag"; then echo "$tag"; exit 0; fi

stage=$(mktemp -d /var/tmp/poresph-cuda.XXXXXX)
trap 'rm -rf "$stage"' EXIT
chmod 755 "$stage"  # the image's /, as in docker/base-image.sh
dest=$stage/usr/local/cuda-$version
mkdir -p "$dest/lib" "$dest/targets/x86_64-linux"
# include and lib64 are folders or links into targets/, depending on how the toolkit was installed:
# the image has real folders and the links of NVIDIA's layout.
for d in bin nvvm include; do cp -a "$(readlink -f "$cuda/$d")" "$dest/$d"; done
lib=$(readlink -f "$cuda/lib64")
for f in "$lib"/libcudart* "$lib"/libcudadevrt.a "$lib"/libculibos.a "$lib"/cmake "$lib"/stubs; do
  [[ -e $f ]] && cp -a "$f" "$dest/lib/"
done
ln -s lib "$dest/lib64"
ln -s ../../include "$dest/targets/x86_64-linux/include"
ln -s ../../lib "$dest/targets/x86_64-linux/lib"
ln -s "cuda-$version" "$stage/usr/local/cuda"
tar -C "$stage" --numeric-owner -c . | "${podman[@]}" import -q - "$tag" >/dev/null
echo "cuda-toolkit-image: $(du -sh "$stage" | cut -f1) from $cuda" >&2
echo "$tag"
