#!/usr/bin/python3
"""Figures from stickslip's output, as PNG files in <results>/figures/.

For each paper example: the phase portraits (x1, x1') and (x2, x2') with the overshooting part
(x2' > 0) drawn heavy (the paper's Figs. 2, 3, 4, 7, 10), x2'(t) (Figs. 5, 8, 11) and, for the
sticking orbits, the stick constraints G and G1 over the stick (Figs. 6, 9, 12).
For each continuation run in <results>/: a bifurcation diagram over the continuation parameter,
x20 and the durations, stable solid and unstable dashed, special points marked and labelled, and
the brute-force sweep of the family (results/sweeps/) overlaid.
For each trace in <results>/: its frequency response (stickslip_plot.py, as `stickslip plot`), max |x2| over the period
on every branch, and the brute force's max |x2| over its settled periods (the family's sweeps and
results/sweeps/traces/) where the trace holds the sweep's data (not where u_s = u_r is solved).

Usage: /usr/bin/python3 tools/plot_figures.py [--stickslip PROGRAM] [--results DIR]
"""
import argparse
import csv
import glob
import json
import math
import os
import subprocess
import tempfile
import tomllib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import stickslip_plot as sp  # noqa: E402
from stickslip_plot import holds_data, read_trace, runs_of  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SIZE = (8, 6)  # inches, at 100 dpi: 800 x 600 pixels (the paper's figures)
STYLE = {"slip-": dict(color="black", lw=0.8), "slip+": dict(color="black", lw=2.6),
         "stick": dict(color="0.6", lw=1.6)}


def save(figure, path, dpi=100):
    sp.save(figure, path, dpi)
    print("wrote", path)


def paper_figures(program, preset, paper_choice, out):
    solve = [program, "solve", "--preset", preset, "--json"] + (["--paper-choice"] if paper_choice else [])
    # Exit code 4: the solution is no motion of the system (the printed data of section 5.2); it is
    # drawn all the same, as what the paper's data give.
    solved = subprocess.run(solve, capture_output=True, text=True)
    if solved.returncode not in (0, 4):
        raise subprocess.CalledProcessError(solved.returncode, solve, solved.stdout, solved.stderr)
    orbit = json.loads(solved.stdout)
    p = orbit["parameters"]
    with tempfile.TemporaryDirectory() as work:
        series = os.path.join(work, "series.csv")
        keys = {"chi": p["chi"], "eta": p["eta"], "omega": p["omega"], "u_s": p["u_s"], "u_r": p["u_r"],
                "x10": orbit["x10"], "x20": orbit["x20"], "v10": orbit["v10"], "v20": 0.0, "phi": orbit["phi"]}
        command = [program, "simulate", "--periods", "1", "--samples-per-period", "2000", "--csv", series]
        for key, value in keys.items():
            command += ["--set", f"{key}={value!r}"]
        subprocess.run(command, check=True, capture_output=True)
        rows = [{k: (v if k == "mode" else float(v)) for k, v in r.items()} for r in csv.DictReader(open(series))]
    title = f"{preset}" + (" (paper's choice: phi held, u_r solved)" if paper_choice else "")
    figure, axes = plt.subplots(1, 2, figsize=SIZE)
    for piece in runs_of(rows, "mode"):
        mode = piece[1]["mode"] if len(piece) > 1 else piece[0]["mode"]
        axes[0].plot([r["x1"] for r in piece], [r["v1"] for r in piece], **STYLE[mode])
        axes[1].plot([r["x2"] for r in piece], [r["v2"] for r in piece], **STYLE[mode])
    for ax, name in zip(axes, ("1", "2")):
        ax.set_xlabel(f"x{name}")
        ax.set_ylabel(f"x{name}'")
        ax.grid(alpha=0.3)
    figure.suptitle(f"Phase portraits, {title}\nheavy: x2' > 0 (overshooting), thin: x2' < 0, grey: stick")
    save(figure, os.path.join(out, f"{preset}-phase.png"))

    figure, ax = plt.subplots(figsize=SIZE)
    for piece in runs_of(rows, "mode"):
        mode = piece[1]["mode"] if len(piece) > 1 else piece[0]["mode"]
        ax.plot([r["t"] for r in piece], [r["v2"] for r in piece], **STYLE[mode])
    ax.axhline(0.0, color="0.8", lw=0.8)
    ax.set_xlabel("t (scaled time)")
    ax.set_ylabel("x2'")
    ax.set_title(f"x2'(t) over one period, {title}")
    save(figure, os.path.join(out, f"{preset}-velocity.png"))

    sticks = [piece for piece in runs_of(rows, "mode") if piece[0]["mode"] == "stick" or
              (len(piece) > 1 and piece[1]["mode"] == "stick")]
    if not sticks:
        return
    stick = sticks[0]
    t0 = stick[0]["t"]
    chi, eta, omega, u_r, phi = p["chi"], p["eta"], p["omega"], p["u_r"], orbit["phi"]
    force = [chi * eta * (r["x2"] - r["x1"]) - math.cos(omega * r["t"] + phi) for r in stick]
    figure, ax = plt.subplots(figsize=SIZE)
    ax.plot([r["t"] - t0 for r in stick], [s + eta * u_r for s in force], label="G = chi eta (x2 - x1) - cos + eta u_r")
    ax.plot([r["t"] - t0 for r in stick], [-s + eta * u_r for s in force], label="G1 = -chi eta (x2 - x1) + cos + eta u_r")
    ax.axhline(0.0, color="black", lw=0.8)
    ax.set_xlabel("time since the stick began")
    ax.set_ylabel("constraint (eq. 35)")
    ax.set_title(f"Stick constraints, {title}")
    ax.legend()
    save(figure, os.path.join(out, f"{preset}-constraints.png"))


def section_x2(program, row, phase):
    """x2 of the continued orbit at forcing phase `phase`: one period simulated from its origin,
    finely sampled, and interpolated at the time where omega t + phi reaches that phase."""
    omega, phi = float(row["omega"]), float(row["phi"])
    t = ((phase - phi) % (2 * math.pi)) / omega
    with tempfile.TemporaryDirectory() as work:
        series = os.path.join(work, "s.csv")
        command = [program, "simulate", "--periods", "1", "--samples-per-period", "4000", "--csv", series,
                   "--set", "v20=0"]
        for key in ("chi", "eta", "omega", "u_s", "u_r", "x10", "x20", "v10", "phi"):
            command += ["--set", f"{key}={row[key]}"]
        subprocess.run(command, check=True, capture_output=True)
        samples = [(float(r["t"]), float(r["x2"])) for r in csv.DictReader(open(series))]
    for (t0, x0), (t1, x1) in zip(samples, samples[1:]):
        if t0 <= t <= t1:
            return x0 + (x1 - x0) * (t - t0) / (t1 - t0)
    return samples[-1][1]


def family_sweeps(results, run, parameter, traced=False):
    """Every sweep of the run's family over this parameter: sweeps/<family>-<parameter>[-<what>].csv,
    and with `traced` those over a trace's range, sweeps/traces/<family>-<parameter>[-<what>].csv."""
    family = run.split("-")[0] + "-" + run.split("-")[1]
    return (glob.glob(os.path.join(results, "sweeps", f"{family}-{parameter}.csv")) +
            sorted(glob.glob(os.path.join(results, "sweeps", f"{family}-{parameter}-*.csv"))) +
            (sorted(glob.glob(os.path.join(results, "sweeps", "traces", f"{family}-{parameter}*.csv"))) if traced else []))


def frequency_response_figure(results, run, out):
    """The trace's frequency response, with the family's sweeps and those over the trace's range
    (sweeps/traces/) where the trace holds their data."""
    directory = os.path.join(results, run)
    trace, branches = read_trace(directory)
    sweeps = family_sweeps(results, run, trace["parameter"], traced=True) if holds_data(branches) else []
    save(sp.figure([directory] + sweeps), os.path.join(out, f"{run}-frequency-response.png"), sp.DEFAULT_DPI)


def curve_restart(summary):
    """The run file's restart of a curve in two parameters (restart = {run, label, boundary}), or
    None for a branch."""
    path = os.path.join(ROOT, summary["run_file"])
    if not os.path.isfile(path):
        return None
    with open(path, "rb") as f:
        restart = tomllib.load(f).get("start", {}).get("restart", {})
    return restart if "boundary" in restart else None


def resonance_end(ax, rows, parameter, y):
    """A branch that ended at a resonance (its amplitude passed max_amplitude): over omega, the
    natural frequency it nears (eq. 56) as a dotted line; its last point marked. Returns the label
    to place."""
    last = rows[-1]
    if parameter == "omega":
        naturals = sp.natural_frequencies(float(last["chi"]), float(last["eta"]))
        for k, natural in enumerate(naturals, 1):
            if abs(natural - float(last["omega"])) < 0.05 * natural:
                ax.axvline(natural, ls=":", color="0.3", lw=1.0, label=f"natural frequency omega{k} = {natural:.5f}")
    ax.plot(float(last[parameter]), float(last[y]), "v", color="C3", ms=6, mec="black", mew=0.5, zorder=5)
    return [(f"resonance (max |x| = {max(float(last['amplitude:x1']), float(last['amplitude:x2'])):.4g})",
             float(last[parameter]), float(last[y]))]


def bifurcation_figure(program, results, run, out):
    directory = os.path.join(results, run)
    branch = sp.load(directory)
    parameter = branch.parameter
    curve = curve_restart(branch.summary)
    if curve:
        condition = curve["label"].rstrip("0123456789")
        y = curve["boundary"]
        figure, top, bottom, canvas = sp.diagram(branch, y=y, stable=sp.stable_off_the_curve(condition))
    else:
        y = "x20"
        figure, top, bottom, canvas = sp.diagram(branch)
    rows = branch.rows
    # A curve in two parameters: the sweeps, at one value of the second, do not compare.
    sweeps = [] if curve else family_sweeps(results, run, parameter)
    phases_drawn = set()
    for number, sweep in enumerate(sweeps):
        # Compare like with like: x2 at the sweep's section phase, for the brute-force motions
        # that repeat every period and for every fifth admissible point of the branch.
        points = [r for r in csv.DictReader(open(sweep)) if r["period"] == "1"]
        if not points:
            continue
        phase = float(points[0]["section_phase"])
        if phase not in phases_drawn:
            phases_drawn.add(phase)
            chosen = [r for r in rows[::5] if r["admissible"] == "1"]
            top.plot([float(r[parameter]) for r in chosen], [section_x2(program, r, phase) for r in chosen],
                     "x" if len(phases_drawn) == 1 else "+", color="C0" if len(phases_drawn) == 1 else "C3", ms=5,
                     label=f"orbit: x2 at forcing phase {phase:.4g}")
        name = os.path.splitext(os.path.basename(sweep))[0]
        top.plot([float(r[parameter]) for r in points], [float(r["x2"]) for r in points], ".",
                 color="0.4" if number == 0 else "C3", ms=3 if number == 0 else 4,
                 label=f"brute force {name}: x2 at phase {phase:.4g} (period 1)")
    if branch.summary["termination"] == "stopped" and branch.summary["message"].startswith("resonance"):
        canvas.labels += resonance_end(top, rows, parameter, y)
    # Linear axes always (the user's choice on the command line: stickslip plot --yscale log).
    canvas.extra += [h for h in top.get_legend_handles_labels()[0]]
    what = f"the curve of {curve['run']}:{curve['label']} in ({parameter}, {curve['boundary']}), " if curve else ""
    title = f"{run}: {what}'{branch.signature}'\n{sp._ends_in_words(branch)}"
    sp.finish_diagram(figure, top, canvas, title)
    save(figure, os.path.join(out, f"{run}-bifurcation.png"))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--stickslip", default=os.path.join(ROOT, "build", "release", "tools", "stickslip"))
    parser.add_argument("--results", default=os.path.join(ROOT, "results"))
    args = parser.parse_args()
    out = os.path.join(args.results, "figures")
    os.makedirs(out, exist_ok=True)
    for preset in ("paper-4.1", "paper-4.2", "paper-5.1", "paper-6"):
        paper_figures(args.stickslip, preset, False, out)
    paper_figures(args.stickslip, "paper-5.2", True, out)  # at the printed data it is no motion
    for run in sorted(os.listdir(args.results)):
        if os.path.isfile(os.path.join(args.results, run, "summary.json")):
            bifurcation_figure(args.stickslip, args.results, run, out)
        elif os.path.isfile(os.path.join(args.results, run, "trace.json")):
            frequency_response_figure(args.results, run, out)


if __name__ == "__main__":
    main()
