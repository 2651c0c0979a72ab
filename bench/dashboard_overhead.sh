#!/usr/bin/env bash
# The dashboard's cost to the solver: the same run without a server, and with `--serve` and
# readers (3 event streams, as three open pages, and a client fetching /api/state every 2 s), alternated REPEATS times; prints each run's particle-steps per second and the medians.
#   bench/dashboard_overhead.sh POREPSH_BINARY [CASE] [REPEATS]
set -euo pipefail
bin=${1:?usage: bench/dashboard_overhead.sh POREPSH_BINARY [CASE] [REPEATS]}
case_file=${2:-$(dirname "$0")/../cases/drainage_2d.toml}
repeats=${3:-5}
work=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null || true; rm -rf "$work"' EXIT
sed 's/^end = .*/end = 0.03/' "$case_file" > "$work/case.toml"
rate() { python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['particle_steps_per_second'])" "$1/summary.json"; }
plain=() served=()
for k in $(seq "$repeats"); do
  "$bin" run "$work/case.toml" --out "$work/plain$k" --quiet > /dev/null
  plain+=("$(rate "$work/plain$k")")
  "$bin" run "$work/case.toml" --out "$work/served$k" --quiet --serve 0 > "$work/served$k.log" &
  pid=$!
  until url=$(grep -o 'http://127.0.0.1:[0-9]*/' "$work/served$k.log" 2>/dev/null); do sleep 0.05; done
  for r in 1 2 3; do curl -s -N "${url}api/events?since=0" > /dev/null & done
  (while kill -0 $pid 2>/dev/null; do curl -s "${url}api/state" > /dev/null; sleep 2; done) &
  wait $pid
  served+=("$(rate "$work/served$k")")
  kill $(jobs -p) 2>/dev/null || true
  wait 2>/dev/null || true
done
python3 - "${plain[*]}" "${served[*]}" <<'PY'
import statistics, sys
plain = [float(x) for x in sys.argv[1].split()]
served = [float(x) for x in sys.argv[2].split()]
print("without server:", " ".join(f"{x:.4g}" for x in plain))
print("served, 4 readers:", " ".join(f"{x:.4g}" for x in served))
mp, ms = statistics.median(plain), statistics.median(served)
print(f"median particle-steps/s: {mp:.4g} without, {ms:.4g} served: {100 * (ms / mp - 1):+.2f} %")
PY
