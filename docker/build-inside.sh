#!/usr/bin/env bash
# The images' build stage (docker/Dockerfile, docker/Dockerfile.cuda): configures, builds and tests
# poresph in the current folder, then gathers what the runtime stage takes into /opt/poresph-stage.
#   docker/build-inside.sh PRESET [CMAKE_ARGS...]
# CTEST_ARGS chooses the tests (default "-LE validation": unit, command line, images, browser;
# the GPU tests skip: no GPU during a build; empty: every test). A failing test fails the build.
# A build secret npm-ca (PEM), where the network re-signs TLS, reaches npm only; it is never
# written into the image. Segmented rocks mounted at /rocks are read by the tests that need them.
set -euo pipefail
preset=$1
shift
jobs=${JOBS:-$(nproc)}
ca=/run/secrets/npm-ca
[[ -s $ca ]] && export NODE_EXTRA_CA_CERTS=$ca
rocks=()
[[ -f /rocks/berea_110.raw ]] && rocks=(-DPORESPH_ROCKS_DIR=/rocks)

# The tools this build used, for its log.
for t in gcc cmake node npm nvcc; do
  command -v "$t" >/dev/null && echo "build-inside: $t $("$t" --version | grep -m1 -oE '[0-9]+\.[0-9][0-9.]*' | head -1)"
done
cmake --preset "$preset" "${rocks[@]}" "$@"
cmake --build --preset "$preset" -j "$jobs"
# shellcheck disable=SC2086  # CTEST_ARGS is a list of ctest options
ctest --test-dir "build/$preset" --output-on-failure -j "$jobs" ${CTEST_ARGS--LE validation}

stage=/opt/poresph-stage
mkdir -p "$stage/bin"
cp "build/$preset/solver/poresph" "$stage/bin/"
cp -r pipelines cases "$stage/"
[[ -f build/$preset/web/dist/index.html ]] && cp -r "build/$preset/web/dist" "$stage/web"
cp docker/smoke-test.sh "$stage/"
