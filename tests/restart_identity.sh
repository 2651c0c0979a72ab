#!/bin/bash
# A run stopped in any way and restarted ends bitwise identical to the run that was never stopped:
# SIGTERM and SIGINT (a final checkpoint at the step it stopped at), SIGKILL (the newest periodic
# checkpoint), and a run that writes checkpoints ten times as often (a checkpoint changes nothing).
# Usage: restart_identity.sh PORESPH SRC WORK
set -u
poresph=$(realpath "$1") src=$(realpath "$2") work=$3
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fail() { echo "restart identity: $*" >&2; exit 1; }

sed 's/^end = 0.25/end = 0.01/' "$src/cases/drainage_2d.toml" > case.toml
sed 's/^monitor_interval = /checkpoint_interval = 0.0001\nmonitor_interval = /' case.toml > often.toml
"$poresph" run case.toml --out whole --quiet > /dev/null || fail "the uninterrupted run failed"
final=$(ls whole/checkpoints | tail -1)

# The run in the background until its log shows `checkpoints` periodic checkpoints and a few more
# steps, then the signal; the restart continues from the newest checkpoint to the end.
stop_and_restart() {
  local name=$1 signal=$2 checkpoints=$3 expect_rc=$4
  "$poresph" run case.toml --out "$name" --quiet > /dev/null 2>&1 &
  local pid=$!
  for _ in $(seq 600); do
    local written
    written=$(grep -c '^checkpoint ' "$name/log.txt" 2>/dev/null)
    [ "${written:-0}" -ge "$checkpoints" ] && break
    sleep 0.05
  done
  sleep 0.2
  kill -s "$signal" $pid
  wait $pid 2>/dev/null
  local rc=$?
  [ $rc -eq "$expect_rc" ] || fail "$name: a run sent SIG$signal exited $rc, expected $expect_rc"
  grep -q "^run completed" "$name/log.txt" && fail "$name: the run ended before the signal; nothing was tested"
  "$poresph" run case.toml --restart "$name" --out "$name.restarted" --quiet > /dev/null ||
    fail "$name: the restart failed"
  cmp -s "whole/checkpoints/$final" "$name.restarted/checkpoints/$final" ||
    fail "$name: restarted after SIG$signal, the final state differs from the uninterrupted run's"
  echo "restart after SIG$signal: bitwise identical ($(grep -o '^restarted from .* at t = [^ ]*' "$name.restarted/log.txt"))"
}

stop_and_restart term TERM 1 130
stop_and_restart int INT 1 130
stop_and_restart kill KILL 2 137

"$poresph" run often.toml --out often --quiet > /dev/null || fail "the run with frequent checkpoints failed"
# (the files store their case, which differs in its checkpoint interval: the states are compared)
/usr/bin/python3 "$src/tests/checkpoint_h5py.py" same "whole/checkpoints/$final" "often/checkpoints/$final" ||
  fail "a run that writes checkpoints every 1e-4 s ends differently from one that writes them every 1e-3 s"
echo "checkpoints every 1e-4 s and every 1e-3 s: bitwise identical"
