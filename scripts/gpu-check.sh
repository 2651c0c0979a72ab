#!/usr/bin/env bash
# GPU check, in under 10 minutes on a machine with an NVIDIA GPU that has nvcc, cmake (>= 3.25) and
# ninja but none of Debian's -dev packages and no ParaView:
#   1. fails at once (exit 3, before building anything) where no GPU is visible: no nvidia-smi, no
#      GPU in its list, or a tiny device query (scripts/gpu_query.cu) that cannot use one;
#   2. configures the solver-only preset with CUDA on (ParaView and the dashboard off), builds
#      poresph and gpu_tests (-j16), runs the gpu-labelled tests (CPU/CUDA agreement per physics
#      family), then `poresph bench --backend cuda --json --profile` (each pass's share too) on the
#      3D fluid box at 1e6 particles, SPHERIC test 2 at its published 4,989,696 particles, the whole
#      claystone drainage cell and the fluid box at 1e7, then, while time is left, the other CUDA benchmarks
#      one by one; the same build, agreement tests and large benchmarks in mixed precision
#      (build/solver-only-mixed); where the machine has MPI, a run on 2 processes against one (monitors identical),
#      and again with the halos handed to MPI in device memory where its MPI was built with CUDA.
# Header-only dependencies: toml++ (used header-only), CLI11, nlohmann-json, and GoogleTest's
# sources (the tests' CMake needs it); Thrust/CUB come with CUDA. They are gathered on a Debian 12
# machine with `scripts/gpu-deps.sh` into build/gpu-deps (ignored by git, ~3 MiB) and carried with
# the working tree to the GPU machine: carry = ["build/gpu-deps"]. PORESPH_DEPS_DIR overrides the folder.
#
#   scripts/gpu-check.sh [--dry-run] [OUTDIR]      OUTDIR defaults to $OUT
# Writes into OUTDIR: progress.log (a line per phase with its time, so a timeout still leaves what
# was done), device.txt, build.log, ctest-gpu.log, build-mixed.log, ctest-gpu-mixed.log, bench.log,
# bench-large.json (both precisions), bench-rest.json.
# --dry-run (a machine without a GPU): no GPU gate, Debian's copies of the dependencies hidden (a
# private mount namespace when run as root), build/gpu-dry with -j2, the agreement harness CPU
# against CPU, a small CPU bench. GPU_CHECK_BUDGET (seconds, default 560) bounds the whole run; the
# benchmarks after the two large ones stop when it is spent. Exit: 0 passed, 1 a phase failed,
# 2 bad setup (a tool or the dependency folder missing), 3 no GPU.
set -uo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
dry=0
outdir=""
for a in "$@"; do
  case $a in
    --dry-run) dry=1 ;;
    -h | --help) sed -n '2,22p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "gpu-check: unknown option $a (expected --dry-run or an output folder)" >&2; exit 2 ;;
    *) outdir=$a ;;
  esac
done
outdir=${outdir:-${OUT:-}}
if [[ -z $outdir ]]; then
  echo "gpu-check: name the output folder: \$OUT or the first argument" >&2
  exit 2
fi

# A dry run as root hides Debian's copies in a private mount namespace, so the build can only use
# the carried folder (the compiler would otherwise still find /usr/include/toml++ and the like).
if ((dry)) && [[ -z ${GPU_CHECK_NS:-} ]] && [[ $(id -u) == 0 ]] && unshare -m true 2>/dev/null; then
  exec env GPU_CHECK_NS=1 unshare -m --propagation private "$0" "$@"
fi

mkdir -p "$outdir" || exit 2
out=$(cd "$outdir" && pwd)
cd "$root" || exit 2  # the presets are read from the source folder
for f in progress.log build.log ctest-gpu.log bench.log; do : >"$out/$f"; done
t0=$SECONDS
# Seconds for everything (the GPU machine's limit is 10 minutes a command); a dry run on a small
# machine has ten times longer for each phase.
scale=$( ((dry)) && echo 10 || echo 1)
budget=${GPU_CHECK_BUDGET:-$((560 * scale))}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failed=()

log() { printf '[gpu-check +%3ds] %s\n' $((SECONDS - t0)) "$*" | tee -a "$out/progress.log"; }
die() { local rc=$1; shift; log "FAILED: $*"; exit "$rc"; }
# phase NAME CAP STDOUT STDERR CMD...: CMD under a limit of CAP seconds or the time left, logged.
phase() {
  local name=$1 cap=$2 o=$3 e=$4 lim rc start
  shift 4
  lim=$((budget - (SECONDS - t0)))
  ((lim > cap * scale)) && lim=$((cap * scale))
  if ((lim < 5)); then log "$name: not run, no time left"; return 124; fi
  log "$name: start (limit ${lim}s)"
  start=$SECONDS
  timeout --kill-after=5 "$lim" "$@" >>"$o" 2>>"$e"
  rc=$?
  if ((rc == 0)); then log "$name: ok in $((SECONDS - start))s"
  else log "$name: FAILED (exit $rc$( ((rc == 124)) && echo ', timed out')) in $((SECONDS - start))s"; fi
  return $rc
}
# Joins JSON arrays (files) into one array.
merge_json() {
  local dest=$1 first=1 body f
  shift
  { echo "["
    for f in "$@"; do
      body=$(sed '1d;$d' "$f" 2>/dev/null)
      [[ -n $body ]] || continue
      ((first)) || echo ","
      echo "$body"
      first=0
    done
    echo "]"; } >"$dest"
}

log "mode: $( ((dry)) && echo dry run || echo GPU check); host $(uname -n), $(nproc) cores; output $out"
[[ -e $root/.git ]] && command -v git >/dev/null && log "source: $(git -C "$root" rev-parse --short HEAD 2>/dev/null) $(git -C "$root" status --porcelain 2>/dev/null | wc -l) changed files"

# Tools, before anything else.
nvcc=$(command -v nvcc || echo /usr/local/cuda/bin/nvcc)
[[ -x $nvcc ]] || die 2 "no nvcc (neither on PATH nor /usr/local/cuda/bin)"
command -v cmake >/dev/null || die 2 "no cmake"
command -v ninja >/dev/null || die 2 "no ninja"
cmake_version=$(cmake --version | head -1 | awk '{print $3}')
[[ $(printf '%s\n' 3.25 "$cmake_version" | sort -V | head -1) == 3.25 ]] || die 2 "cmake $cmake_version is older than 3.25 (the presets need 3.25)"
printf 'int main() {\n#pragma omp parallel\n  {}\n  return 0;\n}\n' >"$tmp/omp.cpp"
cxx=${CXX:-$(command -v c++ || command -v g++)}
[[ -n $cxx ]] || die 2 "no C++ compiler (c++ or g++)"
"$cxx" -fopenmp "$tmp/omp.cpp" -o "$tmp/omp" 2>"$tmp/omp.log" || die 2 "$cxx cannot build OpenMP code (-fopenmp): $(head -3 "$tmp/omp.log")"
log "tools: $("$nvcc" --version | tail -1), cmake $cmake_version, ninja $(ninja --version), $("$cxx" --version | head -1)"

# The GPU gate: nothing is built where no GPU is visible.
if ((dry)); then
  log "dry run: no GPU gate"
  echo "dry run on $(uname -n): no GPU gate" >"$out/device.txt"
else
  command -v nvidia-smi >/dev/null || die 3 "no GPU visible: nvidia-smi is not installed (no NVIDIA driver); nothing was built"
  gpus=$(nvidia-smi -L 2>&1)
  grep -q '^GPU [0-9]' <<<"$gpus" || die 3 "no GPU visible: nvidia-smi lists none ($(head -1 <<<"$gpus")); nothing was built"
  { echo "$gpus"; nvidia-smi 2>&1; } >"$out/device.txt"
  "$nvcc" -O2 -o "$tmp/gpu_query" "$root/scripts/gpu_query.cu" >>"$out/device.txt" 2>&1 ||
    die 3 "the device query does not compile with $nvcc (see device.txt); nothing was built"
  query=$("$tmp/gpu_query" 2>&1) || die 3 "no usable GPU: $query; nothing was built"
  echo "$query" >>"$out/device.txt"
  log "GPU: $query"
fi

if ((dry)) && [[ -n ${GPU_CHECK_NS:-} ]]; then
  mkdir -p "$tmp/empty"
  hidden=()
  for d in /usr/include/toml++ /usr/include/CLI /usr/include/nlohmann /usr/include/gtest /usr/include/gmock \
           /usr/include/thrust /usr/include/cub /usr/src/googletest /usr/share/cmake/CLI11 /usr/share/cmake/nlohmann_json \
           /usr/lib/x86_64-linux-gnu/cmake/GTest; do
    [[ -d $d ]] && mount --bind "$tmp/empty" "$d" && hidden+=("$d")
  done
  for f in /usr/bin/pkg-config /usr/lib/x86_64-linux-gnu/libtomlplusplus.so* /usr/lib/x86_64-linux-gnu/libgtest*.a /usr/include/httplib.h; do
    [[ -f $f ]] && mount --bind /dev/null "$f" && hidden+=("$f")
  done
  log "dry run: hidden in a private mount namespace: ${hidden[*]}"
elif ((dry)); then
  log "dry run: not root, Debian's copies stay visible to the compiler (CMake still ignores them)"
fi

deps=${PORESPH_DEPS_DIR:-$root/build/gpu-deps}
[[ -f $deps/include/toml++/toml.h ]] || die 2 "no dependency folder $deps: run scripts/gpu-deps.sh on Debian 12 and carry build/gpu-deps"
bdir=$root/build/$( ((dry)) && echo gpu-dry || echo solver-only)
jobs=$( ((dry)) && echo 2 || echo 16)
# Only the carried folder: no pkg-config, and Debian's locations ignored by every find_*.
ignore="/usr/include/toml++;/usr/include/CLI;/usr/include/nlohmann;/usr/include/gtest;/usr/src/googletest"
ignore+=";/usr/share/cmake/CLI11;/usr/share/cmake/nlohmann_json;/usr/lib/x86_64-linux-gnu/cmake/GTest"
# configure_build DIR PRECISION LOG: the solver-only preset with CUDA on, poresph and gpu_tests.
configure_build() {
  phase "configure $2" 120 "$3" "$3" \
    cmake --preset solver-only -B "$1" -DPORESPH_CUDA=ON -DCMAKE_CUDA_COMPILER="$nvcc" -DPORESPH_DEPS_DIR="$deps" \
    -DPORESPH_PRECISION="$2" -DCMAKE_DISABLE_FIND_PACKAGE_PkgConfig=ON "-DCMAKE_IGNORE_PATH=$ignore" &&
    phase "build $2" 330 "$3" "$3" cmake --build "$1" -j"$jobs" --target poresph gpu_tests
}
configure_build "$bdir" double "$out/build.log" || die 1 "configure or build (see build.log)"
poresph=$bdir/solver/poresph

# The agreement tests (label gpu), verbose: every field's difference is logged, passed or not.
# Where a GPU was found, a skipped test is a failure.
if phase "ctest -L gpu" 150 "$out/ctest-gpu.log" "$out/ctest-gpu.log" \
     ctest --test-dir "$bdir" -L gpu -V --timeout 120; then
  if ((!dry)) && grep -q 'Skipped' "$out/ctest-gpu.log"; then log "ctest -L gpu: a test was skipped with a GPU present"; failed+=(ctest); fi
else
  failed+=(ctest)
fi
if ((dry)); then
  phase "gpu_tests --all --against cpu" 240 "$out/ctest-gpu.log" "$out/ctest-gpu.log" "$bdir/tests/gpu_tests" --all --against cpu ||
    failed+=(agreement-cpu)
fi
grep -E '^[0-9: ]*[a-z_]+: (passed|FAILED)$' "$out/ctest-gpu.log" | sed 's/^[0-9]*: //' | while read -r line; do log "  $line"; done

# Two processes on the GPU(s) (one each; both on GPU 0 of a one-GPU machine) write exactly the
# monitors of one, where this machine has MPI (mpirun, and the build found it).
if command -v mpirun >/dev/null && grep -q '^MPI_C_FOUND:BOOL=TRUE' "$bdir/CMakeCache.txt"; then
  backend=$( ((dry)) && echo cpu || echo cuda)
  case2=$tmp/shared.toml
  sed 's/^end = 0.5/end = 0.05/' "$root/cases/poiseuille_2d.toml" >"$case2"
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
  if phase "2 processes, backend $backend" 90 "$out/shared.log" "$out/shared.log" sh -c \
       "'$poresph' run '$case2' --backend $backend --quiet --out '$tmp/one' && mpirun -n 2 '$poresph' run '$case2' --backend $backend --quiet --out '$tmp/two' && cmp '$tmp/one/monitors.csv' '$tmp/two/monitors.csv'"; then
    log "  2 processes: monitors.csv identical to one process's"
  else
    failed+=(shared-run)
  fi
  # The halos handed to MPI in device memory (PORESPH_CUDA_AWARE_MPI=1), where this MPI takes it.
  if ((dry)) || ! ompi_info --parsable --all 2>/dev/null | grep -q 'mpi_built_with_cuda_support:value:true'; then
    log "  2 processes, CUDA-aware MPI: skipped (a dry run, or this MPI was built without CUDA)"
  elif phase "2 processes, CUDA-aware MPI" 90 "$out/shared-aware.log" "$out/shared-aware.log" sh -c \
       "PORESPH_CUDA_AWARE_MPI=1 mpirun -n 2 -x PORESPH_CUDA_AWARE_MPI '$poresph' run '$case2' --backend cuda --quiet --out '$tmp/aware' && cmp '$tmp/one/monitors.csv' '$tmp/aware/monitors.csv'"; then
    log "  2 processes, CUDA-aware MPI: monitors.csv identical to one process's"
  else
    failed+=(shared-run-cuda-aware)
  fi
else
  log "2 processes: skipped (no mpirun, or the build found no MPI)"
fi

# The benchmarks: each in its own process, so that a timeout keeps the records before it.
mkdir -p "$tmp/bench"
if ((dry)); then backend=cpu; large=(fluid_box_3d_10000); else backend=cuda; large=(fluid_box_3d_1000000 spheric_dam_break_3d_dp6mm claystone_drainage fluid_box_3d_10000000); fi
parts=()
for b in "${large[@]}"; do
  phase "bench $b" 150 "$tmp/bench/$b.json" "$out/bench.log" "$poresph" bench --backend $backend --json --profile "$b" || failed+=("$b")
  parts+=("$tmp/bench/$b.json")
  merge_json "$out/bench-large.json" "${parts[@]}"
done
# Mixed precision (solver/core/config.hpp): the agreement tests and the large benchmarks again
# (the claystone cell's engine in a length unit of 2^-25 m, core/length_unit.hpp), in records
# that say "precision": "mixed".
mdir=$bdir-mixed
if configure_build "$mdir" mixed "$out/build-mixed.log"; then
  phase "ctest -L gpu (mixed)" 150 "$out/ctest-gpu-mixed.log" "$out/ctest-gpu-mixed.log" \
    ctest --test-dir "$mdir" -L gpu -V --timeout 120 || failed+=(ctest-mixed)
  if ((!dry)) && grep -q 'Skipped' "$out/ctest-gpu-mixed.log"; then failed+=(ctest-mixed-skipped); fi
  if ((dry)); then
    phase "gpu_tests --all --against cpu (mixed)" 240 "$out/ctest-gpu-mixed.log" "$out/ctest-gpu-mixed.log" \
      "$mdir/tests/gpu_tests" --all --against cpu || failed+=(agreement-cpu-mixed)
  fi
  for b in "${large[@]}"; do
    phase "bench $b (mixed)" 150 "$tmp/bench/$b-mixed.json" "$out/bench.log" "$mdir/solver/poresph" bench --backend $backend --json --profile "$b" ||
      failed+=("$b-mixed")
    parts+=("$tmp/bench/$b-mixed.json")
    merge_json "$out/bench-large.json" "${parts[@]}"
  done
else
  failed+=(build-mixed)
fi
if ((!dry)); then
  # Last-bit noise on the CPU alone (positions moved by an ulp), beside the GPU's drift: informative.
  phase "gpu_tests --all --against cpu-ulp (informative)" 60 "$out/ctest-gpu.log" "$out/ctest-gpu.log" \
    "$bdir/tests/gpu_tests" --all --against cpu-ulp
  rest=()
  for b in $("$poresph" bench --backend cuda --list); do
    [[ " ${large[*]} " == *" $b "* ]] && continue
    if ((budget - (SECONDS - t0) < 10)); then log "bench: no time left for $b and the ones after it"; break; fi
    phase "bench $b" 60 "$tmp/bench/$b.json" "$out/bench.log" "$poresph" bench --backend cuda --json --profile "$b"
    rest+=("$tmp/bench/$b.json")
    merge_json "$out/bench-rest.json" "${rest[@]}"
  done
fi

# A short table last: the records of bench-large.json.
if command -v python3 >/dev/null; then
  python3 - "$out/bench-large.json" <<'EOF' | tee -a "$out/progress.log"
import json, sys
for r in json.load(open(sys.argv[1])):
    print(f"{r['case']:24} {r['precision']:6} {r['particles']:>9} particles {r['steps']:>4} steps {r['seconds']:8.3f} s "
          f"{r['particle_steps_per_second']:10.4g} particle-steps/s {r['interactions_per_second']:10.4g} interactions/s  {r['device']}")
EOF
fi
((${#failed[@]} == 0)) || die 1 "${failed[*]}"
log "PASSED in $((SECONDS - t0))s"
