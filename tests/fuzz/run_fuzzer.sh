#!/bin/bash
# Runs a libFuzzer binary for a bounded time from the seed corpus, keeping what it learns in a
# working corpus; a crash, a sanitizer report, a leak or an input over 10 s fails the test, and the
# input is left as WORK/crash-* or WORK/timeout-* (copy it to tests/fuzz/regressions/, or image_regressions/, with the fix).
# Prints the number of inputs tried. A single allocation over FUZZ_MALLOC_LIMIT_MB (default 4096,
# the RSS limit) is a finding too. Usage: run_fuzzer.sh FUZZER SECONDS WORK DICT SEED_DIR...
set -u
fuzzer=$(realpath "$1") seconds=$2 work=$3 dict=$(realpath "$4")
shift 4
seeds=()
for d in "$@"; do seeds+=("$(realpath "$d")"); done
mkdir -p "$work/corpus"
# Every sanitizer report stops the fuzzer, except the known ones of tests/fuzz/ubsan.supp.
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$(dirname "$(realpath "$0")")/ubsan.supp"
export ASAN_OPTIONS="detect_leaks=1"
cd "$work" || exit 1
"$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 -malloc_limit_mb="${FUZZ_MALLOC_LIMIT_MB:-4096}" \
  -max_len=65536 -print_final_stats=1 -dict="$dict" -artifact_prefix="$work/" corpus "${seeds[@]}" > fuzz.log 2>&1
rc=$?
grep -E "^stat::number_of_executed_units|^Done|SUMMARY|ERROR|Test unit written" fuzz.log
echo "fuzz: exit $rc after $(grep -o 'stat::number_of_executed_units: [0-9]*' fuzz.log | grep -o '[0-9]*$') inputs; log in $work/fuzz.log"
exit $rc
