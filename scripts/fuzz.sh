#!/usr/bin/env bash
# The fuzzers, each for SECONDS (default 600): the case reader's and the segmented-image readers'
# (WHICH: all, the default, case or image). Installs clang and libomp if missing (Debian 12),
# gathers the header-only dependencies (so that toml++'s parser is instrumented too), builds the
# libFuzzer binaries (preset fuzz, build/fuzz) and runs them under the CTest label `fuzz`, one after
# the other. A finding is left in build/fuzz/tests/fuzz/case_reader/ or image_reader/ (crash-*,
# timeout-*, oom-*); its fix goes with the input, copied to tests/fuzz/regressions/ or
# image_regressions/, which make test replays. Usage: fuzz.sh [SECONDS] [WHICH]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600} which=${2:-all}
case $which in
  all) targets=(fuzz_case_reader fuzz_image_reader) tests='^fuzz_(case|image)_reader$' ;;
  case) targets=(fuzz_case_reader) tests='^fuzz_case_reader$' ;;
  image) targets=(fuzz_image_reader) tests='^fuzz_image_reader$' ;;
  *) echo "fuzz: expected all, case or image, got \"$which\"" >&2; exit 2 ;;
esac
missing=()
command -v clang++ > /dev/null || missing+=(clang)
[[ -e /usr/lib/llvm-14/lib/libomp.so || -e /usr/lib/x86_64-linux-gnu/libomp.so.5 ]] || missing+=(libomp-dev)
if ((${#missing[@]})); then
  echo "fuzz: installing ${missing[*]}"
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}"
fi
[[ -f build/gpu-deps/include/toml++/toml.h ]] || scripts/gpu-deps.sh build/gpu-deps
cmake --preset fuzz -DPORESPH_FUZZ_SECONDS="$seconds" > /dev/null
cmake --build build/fuzz --target "${targets[@]}"
ctest --test-dir build/fuzz -L fuzz -R "$tests" --output-on-failure
