#!/bin/bash
# The mixed-precision build (build/<preset>/mixed, tests/mixed_precision.cmake) through its real
# binary beside the double one: it says its precision in log.txt, summary.json and its HDF5
# checkpoints (velocities float32, positions float64); a double checkpoint continues in mixed and a
# mixed one in double, converted and said in log.txt; and the mixed continuation of the double run
# ends where the double run ends, to float's digits; the claystone cell (a 4e-8 m support: its
# engine runs in a length unit of 2^-25 m, core/length_unit.hpp) starts as in double, and its
# mixed checkpoint is in SI.
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

# The claystone cell's 4e-8 m support: 10 steps in both builds, monitors and checkpoints only.
clay=(run "$src/cases/claystone_drainage.toml" --set time.end=1e-7 --set output.extract_interval=0
      --set output.checkpoint_interval=1e-7 --quiet)
"$mixed" "${clay[@]}" --out clay_mixed > /dev/null 2>&1 || fail "the mixed build failed the claystone cell: $(tail -3 clay_mixed/log.txt)"
"$double" "${clay[@]}" --out clay_double > /dev/null 2>&1 || fail "the double build failed the claystone cell"
grep -q "the engine runs in a length unit of 2^-25 m" clay_mixed/log.txt || fail "log.txt does not say the engine's unit"

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
# The claystone cell: the same kinetic energy and largest density deviation to 1 % after 10 steps
# (its first pressure wave), and a mixed checkpoint in metres (the engine's unit stays inside).
a, b = last_row("clay_double"), last_row("clay_mixed")
for key in ("kinetic_energy", "density_deviation_max"):
    va, vb = float(a[key]), float(b[key])
    assert abs(va - vb) <= 0.01 * va, f"claystone {key}: mixed {vb}, double {va}"
last = sorted(glob.glob(work + "/clay_mixed/checkpoints/*.h5"))[-1]
with h5py.File(last) as f:
    x = f["fields/position"][...]
    assert 0 < abs(x).max() < 1e-5, f"claystone positions up to {abs(x).max()}: not in metres"
    assert abs(f.attrs["time"] - 1e-7) < 1e-15, f.attrs["time"]
print(f"claystone kinetic energy: double {a['kinetic_energy']}, mixed {b['kinetic_energy']}")
EOF
exit 0
