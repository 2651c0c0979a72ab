#!/usr/bin/env bash
# Gathers the header-only dependencies of a solver-only build into one folder (default
# build/gpu-deps, ignored by git), for a GPU machine that has nvcc, cmake and ninja but none of
# Debian's -dev packages. Run it here, on Debian 12 with scripts/install-deps.sh --minimal done;
# configure with -DPORESPH_DEPS_DIR=<folder> there (scripts/gpu-check.sh does). It takes:
#   toml++ 3.3 headers (libtomlplusplus-dev; used header-only, Debian's build is a shared library),
#   CLI11 2.1 (libcli11-dev), nlohmann-json 3.11 (nlohmann-json3-dev), GoogleTest 1.12 sources
#   (googletest; built with the tests), each with its Debian copyright file (the licence text).
# Thrust/CUB are not gathered: a CUDA build uses CUDA's own (CCCL), never Debian's libthrust-dev.
set -euo pipefail

out=${1:-build/gpu-deps}
need=(/usr/include/toml++/toml.h /usr/include/CLI/CLI.hpp /usr/include/nlohmann/json.hpp
      /usr/src/googletest/CMakeLists.txt /usr/src/googletest/googletest/src/gtest-all.cc)
for f in "${need[@]}"; do
  if [[ ! -f $f ]]; then
    echo "gpu-deps: $f is missing: run scripts/install-deps.sh --minimal first (Debian 12)" >&2
    exit 2
  fi
done

rm -rf "$out"
mkdir -p "$out/include" "$out/googletest/googletest" "$out/licences"
cp -r /usr/include/toml++ /usr/include/CLI /usr/include/nlohmann "$out/include/"
# GoogleTest: the top-level CMakeLists (it sets the version) and the library, not its own tests.
cp /usr/src/googletest/CMakeLists.txt "$out/googletest/"
for d in CMakeLists.txt cmake include src; do cp -r "/usr/src/googletest/googletest/$d" "$out/googletest/googletest/"; done
for p in libtomlplusplus-dev libcli11-dev nlohmann-json3-dev googletest; do
  cp "/usr/share/doc/$p/copyright" "$out/licences/$p.copyright"
done
# What was gathered, with the Debian versions (read by nobody but people).
for p in libtomlplusplus-dev libcli11-dev nlohmann-json3-dev googletest; do
  dpkg-query -W -f='${Package} ${Version}\n' "$p"
done >"$out/VERSIONS"
echo "gpu-deps: $(du -sh "$out" | cut -f1) in $out"
