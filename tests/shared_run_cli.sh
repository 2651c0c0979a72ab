#!/bin/bash
# `mpirun -n N poresph run` through the real binary: on 2 and 3 processes the run directory holds
# exactly the monitors, extracts and checkpoints of one process (the extracts, one piece per process,
# read through VTK: tests/compare_extracts.py; the HDF5 checkpoints compared and read by h5py:
# tests/checkpoint_h5py.py); so do VTU extracts; a checkpoint of one process restarts on three, one of
# three on two, and both end as the uninterrupted run; SIGTERM ends every process with a final
# checkpoint (exit 130); a process killed with SIGKILL ends the job without a hang;
# a bad case is refused once, before any work, with nothing left behind, and so is device memory
# asked of an MPI that cannot take it.
# Usage: shared_run_cli.sh PORESPH MPIEXEC SRC WORK
set -u
poresph=$(realpath "$1") mpiexec=$2 src=$(realpath "$3") work=$4
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fail() { echo "shared run: $*" >&2; exit 1; }
h5py() { /usr/bin/python3 "$src/tests/checkpoint_h5py.py" "$@" || fail "h5py $1 ${*:2}"; }
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_mpi_yield_when_idle=1

sed 's/^end = 0.5/end = 0.02/' "$src/cases/poiseuille_2d.toml" > short.toml
sed 's/^end = 0.5/end = 0.04/' "$src/cases/poiseuille_2d.toml" > longer.toml
sed 's/^end = 0.5/end = 1000.0/' "$src/cases/poiseuille_2d.toml" > endless.toml

same_run() {  # the run directories $1 and $2 hold the same numbers
  cmp -s "$1/monitors.csv" "$2/monitors.csv" || fail "$2/monitors.csv differs from $1's"
  /usr/bin/python3 "$src/tests/compare_extracts.py" "$1" "$2" "${3:-pvtp}" > /dev/null || fail "$2's extracts differ from $1's"
  [ "$(ls "$1/checkpoints")" = "$(ls "$2/checkpoints")" ] || fail "$2 has other checkpoints than $1"
  for f in "$1"/checkpoints/*.h5; do h5py same "$f" "$2/${f#$1/}"; done
}

"$poresph" run longer.toml --out one --quiet > /dev/null || fail "the one-process run failed"
for n in 2 3; do
  "$mpiexec" -n $n "$poresph" run longer.toml --out shared$n --quiet > /dev/null || fail "the run on $n processes failed"
  same_run one shared$n
  [ "$(grep -c '"particles": 208' shared$n/summary.json)" = 1 ] || fail "summary.json of $n processes: $(cat shared$n/summary.json)"
  [ "$(grep -c '^poresph run' shared$n/log.txt)" = 1 ] || fail "log.txt of $n processes is not written once"
done
h5py check "shared3/checkpoints/$(ls shared3/checkpoints | tail -1)" > /dev/null
"$mpiexec" -n 3 "$poresph" run longer.toml --out grids3 --quiet --set output.extract_format=vtu > /dev/null ||
  fail "the run with VTU extracts failed"
same_run one grids3 pvtu

# One process's checkpoint at t = 0.02 continued on three; three processes' continued on two.
last=$(ls one/checkpoints | tail -1)
"$poresph" run short.toml --out first --quiet > /dev/null || fail "the short run failed"
"$mpiexec" -n 3 "$poresph" run longer.toml --restart first --out resumed --quiet > /dev/null || fail "the restart on 3 processes failed"
h5py same "one/checkpoints/$last" "resumed/checkpoints/$last"
"$mpiexec" -n 3 "$poresph" run short.toml --out first3 --quiet > /dev/null || fail "the short run on 3 processes failed"
"$mpiexec" -n 2 "$poresph" run longer.toml --restart first3 --out resumed2 --quiet > /dev/null || fail "the restart on 2 processes failed"
h5py same "one/checkpoints/$last" "resumed2/checkpoints/$last"

# SIGTERM: a final checkpoint from every process and exit 130, sent to the processes (as a batch
# system's scancel does) or to the launcher, which forwards it (OpenMPI's mpirun then exits 1
# whatever its processes' codes: measured with OpenMPI 4.1).
interrupt() {  # name, whom to signal (launcher or processes), expected launcher exit code
  "$mpiexec" -n 2 "$poresph" run endless.toml --out "$1" --quiet > "$1.out" 2>&1 &
  local pid=$! rc
  for _ in $(seq 300); do [ -s "$1/monitors.csv" ] && break; sleep 0.05; done
  sleep 1
  if [ "$2" = launcher ]; then kill -TERM $pid; else pkill -TERM -f "^$poresph run endless.toml --out $1"; fi
  wait $pid
  rc=$?
  [ $rc = "$3" ] || fail "SIGTERM to the $2: exit $rc, expected $3: $(cat "$1.out")"
  grep -q '"status": "interrupted"' "$1/summary.json" || fail "SIGTERM to the $2: $(cat "$1/summary.json")"
  ls "$1"/checkpoints/*.h5 > /dev/null 2>&1 || fail "SIGTERM to the $2: no final checkpoint"
}
interrupt stopped processes 130
interrupt stopped_launcher launcher 1

# SIGKILL on one process: the job ends, without a hang.
"$mpiexec" -n 2 "$poresph" run endless.toml --out killed --quiet > killed.out 2>&1 &
pid=$!
sleep 2
victim=$(pgrep -f "^$poresph run endless.toml --out killed" | tail -1)
[ -n "$victim" ] || fail "SIGKILL: no process to kill"
kill -KILL "$victim"
for _ in $(seq 300); do kill -0 $pid 2>/dev/null || break; sleep 0.1; done
if kill -0 $pid 2>/dev/null; then kill -KILL $pid; fail "SIGKILL: the job still runs 30 s after one process was killed"; fi
wait $pid && fail "SIGKILL: the job exited 0"

# A full disk (a 160 kB file system of the test's own, where user namespaces allow one): exit 5
# from every process, the file and the reason said, no half-written checkpoint, the kept ones whole.
full_disk() {
  mkdir -p full && mount -t tmpfs -o size=160k tmpfs full || fail "full disk: cannot mount the tmpfs"
  "$mpiexec" -n 2 "$poresph" run many.toml --out full/run --quiet > full.out 2>&1
  local rc=$?
  [ $rc = 5 ] || fail "full disk: exit $rc, expected 5: $(cat full.out)"
  grep -q "write failed: .*checkpoints/step_.*No space left on device" full.out || fail "full disk: $(cat full.out)"
  [ -z "$(find full/run -name '*.partial')" ] || fail "full disk: half-written files left behind"
  ls full/run/checkpoints/*.h5 > /dev/null 2>&1 || fail "full disk: no checkpoint kept"
  for f in full/run/checkpoints/*.h5; do h5py check "$f" > /dev/null; done
}
if unshare -rm true 2>/dev/null; then
  sed -e 's/^monitor_interval = .*/monitor_interval = 0.001\ncheckpoint_keep = 100/' short.toml > many.toml
  export -f full_disk fail h5py
  export poresph mpiexec src
  unshare -rm bash -c full_disk || exit 1
else
  echo "no user namespaces here: the full-disk case did not run"
fi

# Refused once, before any work: a case with a bad value.
"$mpiexec" -n 2 "$poresph" run longer.toml --set time.end=-1 --out refused > refused.out 2>&1
rc=$?
[ $rc = 2 ] || fail "refusal: exit $rc, expected 2: $(cat refused.out)"
[ "$(grep -c 'time.end' refused.out)" = 1 ] || fail "refusal not said once: $(cat refused.out)"
[ -e refused ] && fail "a refused run left its directory behind"
# Device memory to MPI (PORESPH_CUDA_AWARE_MPI): a bad value, or asked of an MPI built without
# CUDA, stops every process before any work, said once, exit 2.
aware_refused() {  # value, what the message must hold
  PORESPH_CUDA_AWARE_MPI=$1 "$mpiexec" -n 2 -x PORESPH_CUDA_AWARE_MPI "$poresph" run longer.toml --out aware > aware.out 2>&1
  rc=$?
  [ $rc = 2 ] || fail "PORESPH_CUDA_AWARE_MPI=$1: exit $rc, expected 2: $(cat aware.out)"
  [ "$(grep -c "$2" aware.out)" = 1 ] || fail "PORESPH_CUDA_AWARE_MPI=$1 not refused once: $(cat aware.out)"
  [ -e aware ] && fail "PORESPH_CUDA_AWARE_MPI=$1 left a run directory"
}
aware_refused yes "expected 1"
if ompi_info --parsable --all 2>/dev/null | grep -q 'mpi_built_with_cuda_support:value:false'; then
  aware_refused 1 "built without CUDA"
fi
echo "shared run command-line tests passed"
