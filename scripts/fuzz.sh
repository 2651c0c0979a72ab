#!/usr/bin/env bash
# The case-reader fuzzer for SECONDS (default 600): installs clang and libomp if missing (Debian 12),
# gathers the header-only dependencies (so that toml++'s parser is instrumented too), builds the
# libFuzzer binary (preset fuzz, build/fuzz) and runs the CTest label `fuzz`. A finding is left in
# build/fuzz/tests/fuzz/case_reader/ (crash-*, timeout-*); its fix goes with the input, copied to
# tests/fuzz/regressions/, which make test replays.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
missing=()
command -v clang++ > /dev/null || missing+=(clang)
[[ -e /usr/lib/llvm-14/lib/libomp.so || -e /usr/lib/x86_64-linux-gnu/libomp.so.5 ]] || missing+=(libomp-dev)
if ((${#missing[@]})); then
  echo "fuzz: installing ${missing[*]}"
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}"
fi
[[ -f build/gpu-deps/include/toml++/toml.h ]] || scripts/gpu-deps.sh build/gpu-deps
cmake --preset fuzz -DPORESPH_FUZZ_SECONDS="$seconds" > /dev/null
cmake --build build/fuzz --target fuzz_case_reader
ctest --test-dir build/fuzz -L fuzz --output-on-failure
