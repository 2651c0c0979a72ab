#!/bin/bash
# A run whose disk fills stops with exit 5 and says which file it could not write; it leaves no
# half-written checkpoint, its status says write_failed, and the checkpoints it kept restart. The
# run directory lies on a real full filesystem: a 160 kB tmpfs in a private mount namespace
# (unshare, no root needed where user namespaces are allowed); where they are not, a file-size
# limit (ulimit -f) fails the first checkpoint's write the same way (EFBIG instead of ENOSPC).
# Usage: disk_full.sh PORESPH SRC WORK
set -u
poresph=$(realpath "$1") src=$(realpath "$2") work=$3 mode=${4:-}
fail() { echo "disk full: $*" >&2; exit 1; }

if [ -z "$mode" ]; then
  rm -rf "$work" && mkdir -p "$work/full" || exit 1
  # Ten checkpoints of 35 kB, all kept: more than the filesystem holds.
  sed -e 's/^end = 0.5/end = 0.1/' -e 's/^monitor_interval = .*/monitor_interval = 0.001\ncheckpoint_keep = 100/' \
    "$src/cases/poiseuille_2d.toml" > "$work/case.toml"
  if unshare -rm true 2>/dev/null; then exec unshare -rm "$0" "$@" tmpfs; fi
  exec "$0" "$@" ulimit
fi

cd "$work" || exit 1
if [ "$mode" = tmpfs ]; then
  mount -t tmpfs -o size=160k tmpfs full || fail "cannot mount the tmpfs"
  reason="No space left on device"
else
  ulimit -f 20  # blocks of 1 kB: every file grows to 20 kB at most, the first checkpoint fails
  reason="File too large"
fi
"$poresph" run case.toml --out full/run --quiet > out.txt 2>&1
rc=$?
[ $rc -eq 5 ] || fail "the run exited $rc, expected 5: $(cat out.txt)"
grep -q "write failed: .*$reason" out.txt || fail "no message naming the file and the reason: $(cat out.txt)"
partial=$(find full/run -name '*.partial')
[ -z "$partial" ] || fail "half-written files left behind: $partial"
grep -q '"state": "write_failed"' full/run/status.json || fail "status.json does not say write_failed"
if [ "$mode" = ulimit ]; then
  echo "exit 5 at the first checkpoint under a file-size limit: $(grep -m1 'write failed' out.txt)"
  exit 0
fi
ls full/run/checkpoints/step_*.h5 > /dev/null 2>&1 || fail "no checkpoint was written before the disk filled"
# A disk full before the run begins: exit 5 and no run directory left.
mkdir -p tiny && mount -t tmpfs -o size=8k tmpfs tiny || fail "cannot mount the small tmpfs"
"$poresph" run case.toml --out tiny/run --quiet > tiny.txt 2>&1
rc=$?
[ $rc -eq 5 ] || fail "a run on a disk full from the start exited $rc, expected 5: $(cat tiny.txt)"
[ -e tiny/run ] && fail "a run that could not begin left its run directory: $(ls -R tiny/run)"
"$poresph" run case.toml --restart full/run --out restarted --quiet > restart.txt 2>&1 ||
  fail "the kept checkpoints do not restart: $(cat restart.txt)"
grep -q "skipped a damaged" restarted/log.txt && fail "a kept checkpoint is damaged: $(cat restarted/log.txt)"
echo "exit 5 on a full filesystem ($mode): $(grep -m1 'write failed' out.txt)"
echo "$(ls full/run/checkpoints | wc -l) intact checkpoints kept; the restart from the newest completes"
