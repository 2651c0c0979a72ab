#!/usr/bin/env python3
# poresph report: the curves of one run or of several (a sweep) from their monitors.csv, as PNG
# plots with matplotlib (Agg: no display needed). Two-phase runs: saturations against time with
# the percolation time marked (Pazdniakou 2018 Fig. 9), the mean phase pressures and the capillary
# pressure against time (Fig. 13a), the capillary pressure against the gas saturation (Fig. 13b),
# the porosity (Deptulski 2021 Fig. 5.6a) and the seepage velocities along the flow axis (Fig. 12).
# Runs with damage: the damaged particles and the total damage (Fig. 10). Every run: the kinetic
# energy and the time step. Prints a table of percolation times and writes it to percolation.md.
#   report_plots.py OUTDIR RUNDIR...
import csv
import json
import math
import os
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.stderr.write("poresph report: matplotlib is missing (apt-get install python3-matplotlib, "
                     "or scripts/install-deps.sh)\n")
    sys.exit(4)


def read_run(run_dir):
    path = os.path.join(run_dir, "monitors.csv")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise ValueError(path + ": no monitor rows")
    columns = {k: [float(r[k]) if r[k] not in ("", None) else math.nan for r in rows] for k in rows[0] if k != "dt_limit"}
    summary = {}
    try:
        with open(os.path.join(run_dir, "summary.json")) as f:
            summary = json.load(f)
    except (OSError, ValueError):
        pass  # a run still going has none yet
    return {"dir": run_dir, "name": os.path.basename(os.path.normpath(run_dir)), "col": columns, "summary": summary}


def flow_axis(run):
    axis = run["summary"].get("two_phase", {}).get("flow_axis")
    if axis:
        return axis
    return next((a for a in "zyx" if "velocity_gas_" + a in run["col"]), "x")  # the last axis the run has


def percolation(run):
    t = [x for x in run["col"].get("percolation_time", []) if not math.isnan(x)]
    if not t:
        return None, None
    times, sg = run["col"]["time"], run["col"]["saturation_gas"]
    i = min(range(len(times)), key=lambda k: abs(times[k] - t[0]))
    return t[0], sg[i]


def figure(title, xlabel, ylabel):
    fig, ax = plt.subplots(figsize=(6.4, 4.2), dpi=100)
    ax.set_title(title)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(True, alpha=0.3)
    return fig, ax


def save(fig, ax, out, name, legend=True):
    if legend and ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize=8)
    fig.tight_layout()
    path = os.path.join(out, name)
    fig.savefig(path + ".tmp.png")
    os.replace(path + ".tmp.png", path)  # whole, or not at all
    plt.close(fig)
    print("  " + path)


def plot_two_phase(runs, out):
    fig, ax = figure("Saturations in the sample", "time (s)", "saturation")
    for r in runs:
        c = r["col"]
        line, = ax.plot(c["time"], c["saturation_gas"], label=r["name"] + ": gas")
        ax.plot(c["time"], c["saturation_liquid"], "--", color=line.get_color(), label=r["name"] + ": water")
        tp, _ = percolation(r)
        if tp is not None:
            ax.axvline(tp, color=line.get_color(), lw=0.8, ls=":")
    ax.set_ylim(0, 1)
    save(fig, ax, out, "saturation.png")
    fig, ax = figure("Mean phase pressures in the sample", "time (s)", "pressure (Pa)")
    for r in runs:
        c = r["col"]
        line, = ax.plot(c["time"], c["pressure_gas"], label=r["name"] + ": gas")
        ax.plot(c["time"], c["pressure_liquid"], "--", color=line.get_color(), label=r["name"] + ": water")
        ax.plot(c["time"], c["capillary_pressure"], ":", color=line.get_color(), label=r["name"] + ": p_gas - p_water")
    save(fig, ax, out, "pressure.png")
    fig, ax = figure("Capillary pressure against gas saturation (drainage)", "gas saturation S_g",
                     "capillary pressure p_gas - p_water (Pa)")
    for r in runs:
        c = r["col"]
        ax.plot(c["saturation_gas"], c["capillary_pressure"], ".-", ms=3, lw=0.8, label=r["name"])
        tp, sg = percolation(r)
        if tp is not None:
            i = c["time"].index(min(c["time"], key=lambda t: abs(t - tp)))
            ax.plot([c["saturation_gas"][i]], [c["capillary_pressure"][i]], "k*", ms=9)
    ax.set_xlim(0, 1)
    save(fig, ax, out, "capillary_pressure.png")
    with_porosity = [r for r in runs if "porosity" in r["col"]]
    if with_porosity:
        fig, ax = figure("Porosity of the sample (fluid volume / sample volume)", "time (s)", "porosity")
        for r in with_porosity:
            ax.plot(r["col"]["time"], r["col"]["porosity"], label=r["name"])
        save(fig, ax, out, "porosity.png")
    fig, ax = figure("Seepage velocities along the flow axis (phase means)", "time (s)",
                     "velocity (m/s)")
    for r in runs:
        a, c = flow_axis(r), r["col"]
        if "velocity_gas_" + a not in c:
            continue
        line, = ax.plot(c["time"], c["velocity_gas_" + a], label=r["name"] + ": gas")
        ax.plot(c["time"], c["velocity_liquid_" + a], "--", color=line.get_color(), label=r["name"] + ": water")
    save(fig, ax, out, "seepage_velocity.png")


def plot_damage(runs, out):
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10.4, 4.2), dpi=100)
    ax1.set_title("Damaged particles (D > 1e-3)")
    ax2.set_title("Total damage (sum of D)")
    for ax in (ax1, ax2):
        ax.set_xlabel("time (s)")
        ax.grid(True, alpha=0.3)
    for r in runs:
        c = r["col"]
        line, = ax1.plot(c["time"], c["damaged_particles"], label=r["name"])
        ax2.plot(c["time"], c["total_damage"], color=line.get_color(), label=r["name"])
        tp, _ = percolation(r)
        if tp is not None:
            for ax in (ax1, ax2):
                ax.axvline(tp, color=line.get_color(), lw=0.8, ls=":")
    save(fig, ax1, out, "damage.png")


def percolation_table(runs, out):
    head = "| run | percolation time (s) | gas saturation then | porosity at start | porosity at end | damaged particles at end |"
    lines = [head, "|" + "---|" * 6]

    def last(values, fmt):  # a run still writing may end on an empty cell
        v = [x for x in values if not math.isnan(x)]
        return fmt % v[-1] if v else ""

    for r in runs:
        tp, sg = percolation(r)
        c = r["col"]
        por = c.get("porosity", [])
        dmg = c.get("damaged_particles", [])
        lines.append("| %s | %s | %s | %s | %s | %s |" % (
            r["name"], "none" if tp is None else "%.6g" % tp, "" if sg is None else "%.4f" % sg,
            last(por[:1], "%.4f"), last(por, "%.4f"), last(dmg, "%d")))
    path = os.path.join(out, "percolation.md")
    with open(path + ".tmp", "w") as f:
        f.write("\n".join(lines) + "\n")
    os.replace(path + ".tmp", path)
    print("  " + path)


def plot_run(runs, out):
    fig, ax = figure("Kinetic energy and time step", "time (s)", "kinetic energy (J)")
    for r in runs:
        ax.semilogy(r["col"]["time"], [max(x, 1e-300) for x in r["col"]["kinetic_energy"]], label=r["name"])
    ax2 = ax.twinx()
    for r in runs:
        ax2.plot(r["col"]["time"], r["col"]["dt"], ":", lw=0.8)
    ax2.set_ylabel("time step (s), dotted")
    save(fig, ax, out, "run.png")


def main():
    if len(sys.argv) < 3:
        sys.stderr.write("usage: report_plots.py OUTDIR RUNDIR...\n")
        return 2
    out, dirs = sys.argv[1], sys.argv[2:]
    try:
        runs = [read_run(d) for d in dirs]
    except (OSError, ValueError, KeyError) as e:
        sys.stderr.write("poresph report: %s\n" % e)
        return 2
    os.makedirs(out, exist_ok=True)
    print("poresph report: plots in " + out)
    plot_run(runs, out)
    two_phase = [r for r in runs if "saturation_gas" in r["col"]]
    damaged = [r for r in runs if "damaged_particles" in r["col"]]
    if damaged:
        plot_damage(damaged, out)
    if two_phase:
        plot_two_phase(two_phase, out)
        percolation_table(two_phase, out)
        print("%-32s %18s %22s" % ("run", "percolation (s)", "gas saturation then"))
        for r in two_phase:
            tp, sg = percolation(r)
            print("%-32s %18s %22s" % (r["name"], "none" if tp is None else "%.6g" % tp, "" if sg is None else "%.4f" % sg))
    return 0


if __name__ == "__main__":
    sys.exit(main())
