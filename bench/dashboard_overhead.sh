#!/usr/bin/env bash
# The dashboard's cost to the solver: the same run (CASE shortened to END, default 0.03 s) without a server,
# with `--serve` and nobody reading, and with `--serve` and readers (3 event streams, as three
# open pages, and a client fetching /api/state every 2 s, on the same machine), alternated
# REPEATS times; prints each run's particle-steps per second and the medians.
#   bench/dashboard_overhead.sh POREPSH_BINARY [CASE] [REPEATS]
set -euo pipefail
bin=${1:?usage: bench/dashboard_overhead.sh POREPSH_BINARY [CASE] [REPEATS]}
case_file=${2:-$(dirname "$0")/../cases/drainage_2d.toml}
repeats=${3:-5}
work=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null || true; rm -rf "$work"' EXIT
sed "s/^end = .*/end = ${END:-0.03}/" "$case_file" > "$work/case.toml"
rate() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['particle_steps_per_second'])" "$1/summary.json"; }
plain=() idle=() read=()
for k in $(seq "$repeats"); do
  "$bin" run "$work/case.toml" --out "$work/plain$k" --quiet > /dev/null
  plain+=("$(rate "$work/plain$k")")
  "$bin" run "$work/case.toml" --out "$work/idle$k" --quiet --serve 0 > /dev/null
  idle+=("$(rate "$work/idle$k")")
  "$bin" run "$work/case.toml" --out "$work/read$k" --quiet --serve 0 > "$work/read$k.log" &
  pid=$!
  until url=$(grep -o 'http://127.0.0.1:[0-9]*/' "$work/read$k.log" 2>/dev/null); do sleep 0.05; done
  for r in 1 2 3; do curl -s -N "${url}api/events?since=0" > /dev/null & done
  (while kill -0 $pid 2>/dev/null; do curl -s "${url}api/state" > /dev/null; sleep 2; done) &
  wait $pid
  read+=("$(rate "$work/read$k")")
  kill $(jobs -p) 2>/dev/null || true
  wait 2>/dev/null || true
done
python3 - "${plain[*]}" "${idle[*]}" "${read[*]}" <<'PY'
import statistics, sys
runs = [[float(x) for x in a.split()] for a in sys.argv[1:4]]
names = ["without server", "served, no reader", "served, 4 readers"]
base = statistics.median(runs[0])
for n, r in zip(names, runs):
    m = statistics.median(r)
    print(f"{n:18s} median {m:.4g} particle-steps/s ({100 * (m / base - 1):+.2f} %), runs " + " ".join(f"{x:.4g}" for x in r))
PY
