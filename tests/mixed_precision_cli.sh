#!/bin/bash
# The mixed-precision build (build/<preset>/mixed, tests/mixed_precision.cmake) through its real
# binary beside the double one: it says its precision in log.txt, summary.json and its HDF5
# checkpoints (velocities float32, positions float64); a double checkpoint continues in mixed and a
# mixed one in double, converted and said in log.txt; and the mixed continuation of the double run
# ends where the double run ends, to float's digits; a case whose kernel derivatives pass float's
# range (the claystone cell's nanometre support) is refused by the mixed build at check.
# With MPIEXEC, a mixed two-phase run over 2 processes, its domain cut anew at every list build,
# writes exactly one process's monitors (migrations and halos carry the double positions).
# Usage: mixed_precision_cli.sh PORESPH_DOUBLE PORESPH_MIXED SRC WORK [MPIEXEC]
set -u
double=$(realpath "$1") mixed=$(realpath "$2") src=$(realpath "$3") work=$4 mpiexec=${5:-}
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fail() { echo "mixed precision: $*" >&2; exit 1; }
export OMP_NUM_THREADS=1
# Monitors and checkpoints only: the mixed build here has no ParaView (no extracts).
sed 's/^end = 0.5/end = 0.02/; s/^extract_interval = .*/extract_interval = 0/' "$src/cases/poiseuille_2d.toml" > short.toml
sed 's/^end = 0.5/end = 0.04/; s/^extract_interval = .*/extract_interval = 0/' "$src/cases/poiseuille_2d.toml" > longer.toml

"$double" run longer.toml --out double --quiet > /dev/null || fail "the double run failed"
"$double" run short.toml --out double_first --quiet > /dev/null || fail "the short double run failed"
"$mixed" run short.toml --out mixed_first --quiet > /dev/null || fail "the short mixed run failed"
grep -q "mixed precision" mixed_first/log.txt || fail "log.txt does not say mixed: $(head -5 mixed_first/log.txt)"
grep -q '"precision": "mixed"' mixed_first/summary.json || fail "summary.json does not say mixed"
if [ -n "$mpiexec" ]; then  # the domain cut anew at every list build: particles migrate
  drop=(run "$src/cases/sessile_drop_2d.toml" --set time.end=0.02 --set solver.rebalance_imbalance=1.0
        --set output.extract_interval=0 --quiet)
  OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 \
    timeout 120 "$mpiexec" -n 2 "$mixed" "${drop[@]}" --out mixed_two > /dev/null 2>&1 || fail "the mixed run on 2 processes failed or hung"
  "$mixed" "${drop[@]}" --out mixed_one > /dev/null || fail "the mixed run on 1 process failed"
  grep -q '"rebalances": [1-9]' mixed_two/summary.json || fail "the 2-process run never cut the domain anew"
  cmp -s mixed_one/monitors.csv mixed_two/monitors.csv || fail "mixed: 2 processes' monitors.csv differs from one's"
fi

"$mixed" run longer.toml --restart double_first --out mixed_resumed --quiet > /dev/null || fail "the mixed restart of a double checkpoint failed"
grep -q "written in double precision: its real fields converted to mixed" mixed_resumed/log.txt ||
  fail "the mixed restart does not say it converted: $(cat mixed_resumed/log.txt)"
"$double" run longer.toml --restart mixed_first --out double_resumed --quiet > /dev/null || fail "the double restart of a mixed checkpoint failed"
grep -q "written in mixed precision: its real fields converted to double" double_resumed/log.txt ||
  fail "the double restart does not say it converted: $(cat double_resumed/log.txt)"

# The claystone cell's 4e-8 m support: kernel derivatives past float's range, refused at check.
"$mixed" check "$src/cases/claystone_drainage.toml" > /dev/null 2> refused.txt
[ $? = 2 ] || fail "the mixed build did not refuse the claystone cell (exit 2): $(cat refused.txt)"
grep -q "discretisation.support_radius: expected at least .* m in this mixed-precision build" refused.txt ||
  fail "the refusal does not name the key and the bound: $(cat refused.txt)"
"$double" check "$src/cases/claystone_drainage.toml" > /dev/null 2>&1 || fail "the double build refused the claystone cell"

/usr/bin/python3 - "$work" <<'EOF' || fail "checkpoint types or final state"
import csv, glob, sys
import h5py
work = sys.argv[1]
last = sorted(glob.glob(work + "/mixed_resumed/checkpoints/*.h5"))[-1]
with h5py.File(last) as f:
    assert f.attrs["precision"] in (b"mixed", "mixed"), f.attrs["precision"]
    assert f["fields/velocity"].dtype == "float32", f["fields/velocity"].dtype
    assert f["fields/position"].dtype == "float64", f["fields/position"].dtype
def last_row(run):
    with open(f"{work}/{run}/monitors.csv") as fh:
        rows = list(csv.DictReader(fh))
    return rows[-1]
a, b = last_row("double"), last_row("mixed_resumed")
assert a["time"] == b["time"] or abs(float(a["time"]) - float(b["time"])) < 1e-12, (a["time"], b["time"])
va, vb = float(a["v_max"]), float(b["v_max"])
assert abs(va - vb) <= 1e-5 * va, f"v_max {vb} after the mixed continuation, {va} in double"
print(f"v_max: double {va}, double then mixed {vb}")
EOF
exit 0
