#!/usr/bin/env bash
# Runs every case of cases/ (shortened to a fraction of its end time) and the demo with two poresph
# binaries, and compares their monitors.csv and final checkpoints byte for byte: a refactoring
# that must not change the physics leaves both identical.
#   scripts/compare-runs.sh OLD_POREPSH NEW_PORESPH OUTDIR [FRACTION]    (FRACTION default 1/40)
# Exit 0 when every case is identical, 1 when one differs, 2 on bad arguments.
set -uo pipefail
if (($# < 3)); then
  echo "usage: $0 OLD_PORESPH NEW_PORESPH OUTDIR [FRACTION]" >&2
  exit 2
fi
old=$1 new=$2 out=$3 fraction=${4:-0.025}
root=$(cd "$(dirname "$0")/.." && pwd)
for b in "$old" "$new"; do [[ -x $b ]] || { echo "compare-runs: $b is not an executable" >&2; exit 2; }; done
mkdir -p "$out/cases" || exit 2
# Each case with time.end scaled by FRACTION.
for f in "$root"/cases/*.toml; do
  python3 - "$f" "$out/cases/$(basename "$f")" "$fraction" <<'PY'
import re, sys
t = open(sys.argv[1]).read()
m = re.search(r'(\[time\][^\[]*?\nend\s*=\s*)([0-9.eE+-]+)', t)
t = t[:m.start(2)] + repr(float(m.group(2)) * float(sys.argv[3])) + t[m.end(2):]
open(sys.argv[2], 'w').write(t)
PY
done
run() {  # binary tag case
  local dir=$out/$2/$3
  rm -rf "$dir"
  if [[ $3 == demo ]]; then OMP_NUM_THREADS=1 "$1" demo --quiet --out "$dir" >/dev/null 2>&1
  else OMP_NUM_THREADS=1 "$1" run "$out/cases/$3.toml" --quiet --out "$dir" >/dev/null 2>&1; fi
}
differ=0
for name in $(cd "$out/cases" && ls *.toml | sed 's/\.toml$//') demo; do
  run "$old" old "$name"; run "$new" new "$name"
  a=$(ls "$out/old/$name/checkpoints" 2>/dev/null | tail -1) b=$(ls "$out/new/$name/checkpoints" 2>/dev/null | tail -1)
  if [[ -n $a && $a == "$b" ]] && cmp -s "$out/old/$name/monitors.csv" "$out/new/$name/monitors.csv" &&
     cmp -s "$out/old/$name/checkpoints/$a" "$out/new/$name/checkpoints/$b"; then
    echo "$name: identical ($(($(wc -l <"$out/new/$name/monitors.csv") - 1)) monitor rows, final checkpoint $a)"
  else
    echo "$name: DIFFERS (checkpoints $a / $b)"
    differ=1
  fi
done
exit $differ
