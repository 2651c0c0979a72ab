#!/usr/bin/env bash
# What in-situ figures cost the solver: the same run (CASE shortened to END simulated seconds) without
# pipelines, with PIPELINES at the default cadence (a fiftieth of the run) rendered on their own
# thread (the default: frames the renderer has no time for are dropped), and with every frame
# rendered (`visualisation.every_frame`, the solver waits), alternated REPEATS times. Prints each
# run's stepping rate, steps over the wall time less Catalyst's start-up, its first frame (which
# builds the pipelines while the solver waits) and the wait for the last frames at the end, and
# the medians against the run without pipelines.
#   bench/insitu_overhead.sh POREPSH_BINARY CASE END "PIPELINE..." [REPEATS]
set -euo pipefail
bin=${1:?usage: bench/insitu_overhead.sh POREPSH_BINARY CASE END \"PIPELINE...\" [REPEATS]}
case_file=${2:?case file}
end=${3:?end time}
pipelines=${4:?pipelines}
repeats=${5:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sed "s/^end = .*/end = $end/" "$case_file" > "$work/case.toml"
args=()
for p in $pipelines; do args+=(--pipeline "$p"); done
rate() {
  python3 - "$1/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
i = s.get("insitu", {})
busy = s["wall_seconds"] - i.get("startup_seconds", 0) - i.get("first_frame_seconds", 0) - i.get("drain_seconds", 0)
print(f"{s['steps'] / busy:.6g} {i.get('frames', 0)} {i.get('dropped_frames', 0)} {s['wall_seconds']:.4g}")
PY
}
for k in $(seq "$repeats"); do
  "$bin" run "$work/case.toml" --out "$work/plain$k" --quiet > /dev/null
  echo "plain $(rate "$work/plain$k")" >> "$work/rates"
  "$bin" run "$work/case.toml" --out "$work/thread$k" --quiet "${args[@]}" > /dev/null
  echo "thread $(rate "$work/thread$k")" >> "$work/rates"
  "$bin" run "$work/case.toml" --out "$work/every$k" --quiet "${args[@]}" --set visualisation.every_frame=true > /dev/null
  echo "every $(rate "$work/every$k")" >> "$work/rates"
done
python3 - "$work/rates" <<'PY'
import statistics, sys
runs = {}
for line in open(sys.argv[1]):
    name, rate, frames, dropped, wall = line.split()
    runs.setdefault(name, []).append((float(rate), int(frames), int(dropped), float(wall)))
base = statistics.median(r[0] for r in runs["plain"])
labels = {"plain": "no pipelines", "thread": "render thread (default)", "every": "every frame (solver waits)"}
for name, rs in runs.items():
    m = statistics.median(r[0] for r in rs)
    print(f"{labels[name]:28s} median {m:.4g} steps/s ({100 * (m / base - 1):+.1f} %); runs (steps/s, frames rendered, "
          "dropped, wall s): " + "; ".join(f"{r[0]:.4g} {r[1]} {r[2]} {r[3]:.3g}" for r in rs))
PY
