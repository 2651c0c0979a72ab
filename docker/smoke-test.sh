#!/usr/bin/env bash
# The runtime stage's own test (docker/Dockerfile*), run as the image's user in an empty folder:
# the installed poresph checks a case, runs a short dam break that renders a figure through its
# own Xvfb and writes VTK extracts, passes one validation, and serves the dashboard's front-end.
# A missing library, pipeline module or front-end file fails the image's build.
set -euo pipefail
cases=/opt/poresph/cases
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

if ldd "$(command -v poresph)" | grep "not found"; then
  echo "smoke-test: poresph misses the libraries above" >&2
  exit 1
fi
poresph check "$cases/dam_break_3d.toml"
sed -e 's/^end = 20.0/end = 0.01/' -e 's/^extract_interval = 1.0/extract_interval = 0.01/' \
  "$cases/dam_break_3d.toml" >db.toml
printf '\n[visualisation]\npipelines = ["phases"]\ninterval = 0.01\nimage_size = [320, 240]\n' >>db.toml
poresph run db.toml --out run --quiet
for f in run/summary.json run/monitors.csv run/images/phases/3d_000000.png; do
  [[ -s $f ]] || { echo "smoke-test: $f is missing" >&2; exit 1; }
done
ls run/extracts/*.vtp >/dev/null

poresph validate poiseuille_couette --json >validate.json
python3 - validate.json <<'PY'
import json, sys
records = json.load(open(sys.argv[1]))
assert records and all(r["passed"] for r in records), records
PY

poresph serve run --port 18080 >serve.log 2>&1 &
server=$!
python3 - <<'PY'
import time, urllib.request
for _ in range(100):
    try:
        page = urllib.request.urlopen("http://127.0.0.1:18080/", timeout=2).read().decode()
        break
    except OSError:
        time.sleep(0.1)
else:
    raise SystemExit("smoke-test: the dashboard did not answer on 127.0.0.1:18080")
assert "<script" in page and "without its web front-end" not in page, page[:300]
PY
kill "$server"
echo "smoke-test: poresph runs, renders, validates and serves in this image"
