"""The frequency response of one trace (results/<trace>/, `stickslip trace`), drawn by
`stickslip plot TRACE` and by tools/plot_figures.py (which overlays the brute-force sweeps).

max |x2| over the period (each branch's exact `amplitude:x2` column) against the continued
parameter over every branch of the trace: each orbit type in its own colour with its signature in
the legend, stable solid, unstable dashed, stretches that are no motion of the system (followed
past a change of type that switched nowhere, `admissible` = 0) thin grey. Every switch to the
adjacent type (a star), every change of type that did not switch, and every fold, torus point,
period doubling, symmetry breaking and branch point is marked and labelled by its code, without
overprinting (bifurcation_diagram.label_points). The brute force, where sweeps are given: each
settled point's max |x2| over its recorded periods (the sweep's exact `amplitude:x2` column), the
same quantity as the branches', by the period the sweep found on its section.

Usage (what `stickslip plot` runs): /usr/bin/python3 trace_figure.py TRACE_DIRECTORY OUTPUT.png [SWEEP.csv ...]
Exit codes: 0 written; 3 matplotlib cannot be imported; 1 the drawing failed (nothing written).
"""
import csv
import json
import os
import sys

from bifurcation_diagram import INADMISSIBLE, MARKERS, TYPE_CHANGE_MARKER, label_points, read_run, runs_of, save

SIZE = (11.5, 6)  # inches, at 100 dpi: 1150 x 600 pixels, the legend beside the axes
# One colour per orbit type, in the order the trace meets them (red is kept for the markers).
COLOURS = ["C0", "C2", "C1", "C4", "C9", "C5", "C6", "C8", "C7"]
SWITCH_MARKER = ("*", "gold")
# The smooth bifurcations and the family's end, by code; every other code of a special point is a
# change of orbit type (GR, T0, S0, NS, SK: the README's table).
SMOOTH = {"LP": "fold (LP)", "TR": "torus (TR)", "PD": "period doubling (PD)", "SB": "symmetry breaking (SB)",
          "BP": "branch point (BP)", "UZ": "user value (UZ)", "EP": "end of the family (EP)"}
# Special points that are not drawn: a branch's start (the previous branch's end, drawn there) and
# the range's bounds (the axis ends).
SKIPPED_TESTS = ("start", "lambda_min", "lambda_max")
# The brute force's points by the period found on the section: 1, 2, more, none (not periodic
# over the recorded periods).
SWEEP_STYLES = {1: ("o", "0.35", 2.5, "period 1"), 2: ("s", "C3", 2.5, "period 2"),
                3: ("D", "C5", 2.5, "period 3 or more"), 0: ("x", "0.6", 2.5, "not periodic")}


def read_trace(directory):
    """trace.json and, per branch in the order of the file, (entry, summary, rows, special)."""
    trace = json.load(open(os.path.join(directory, "trace.json")))
    branches = []
    for entry in trace["branches"]:
        summary, rows, special = read_run(os.path.join(directory, entry["name"]))
        branches.append((entry, summary, rows, special))
    return trace, branches


def holds_data(branches):
    """Whether the model's data (chi, eta, u_s, u_r) are the same at every point of the trace, so
    that a sweep at those data is a brute force of the same system (not where u_s = u_r is solved)."""
    values = {(r["chi"], r["eta"], r["u_s"], r["u_r"]) for _, _, rows, _ in branches for r in rows}
    return len(values) == 1


def draw_branches(ax, trace, branches):
    """The branches' curves and the special points' markers on `ax`. Returns the labels to place
    (label_points) and the legend handles: the orbit types, the line styles, the marker kinds."""
    from matplotlib.lines import Line2D
    parameter = trace["parameter"]
    colours, spans, markers, labels, drawn = {}, {}, {}, [], set()

    def mark(kind, x, y, marker, face, size, name):
        # One mark for one point met twice: by two branches (chains that meet), or by two margins
        # through zero together (a grazing born at the stick's exit that moves inside it).
        key = (kind, f"{x:.6g}", f"{y:.5g}")
        if key in drawn:
            return
        drawn.add(key)
        # A switch over the other marks at its point (several margins may reach zero there).
        ax.plot(x, y, marker, color=face, ms=size, mec="black", mew=0.6, zorder=6 if marker == SWITCH_MARKER[0] else 5)
        markers.setdefault(name, Line2D([], [], ls="", marker=marker, color=face, ms=size, mec="black", mew=0.6,
                                        label=name))
        if kind:
            labels.append((kind, x, y))

    # The margin each branch switched at: the next branch of its chain began there by a switch.
    switched_at = {}
    for direction in trace["directions"]:
        for k, following in zip(direction["branches"], direction["branches"][1:]):
            entry = branches[following - 1][0]
            if entry["start"] == "switch":
                switched_at[branches[k - 1][0]["name"]] = "margin:" + entry["margin"]
    for entry, summary, rows, special in branches:
        signature = entry["signature"]
        colour = colours.setdefault(signature, COLOURS[len(colours) % len(COLOURS)])
        xs_all = [float(r[parameter]) for r in rows]
        for piece in runs_of(rows, lambda r: (r["stable"], r["admissible"])):
            key = (piece[0]["stable"] == "1", piece[0]["admissible"] == "1")
            xs = [float(r[parameter]) for r in piece]
            spans[key] = max(spans.get(key, 0.0), max(xs) - min(xs))
            ax.plot(xs, [float(r["amplitude:x2"]) for r in piece], "-" if key[0] else "--",
                    **(dict(color=colour, lw=1.8) if key[1] else INADMISSIBLE))
        switch = ([None] + [r for r in special if r["test_function"] == switched_at.get(entry["name"])])[-1]
        if entry["start"] == "trace-start":
            mark("", xs_all[0], float(rows[0]["amplitude:x2"]), "o", "white", 7, "the trace's start")
        for row in special:
            if row["test_function"] in SKIPPED_TESTS + (summary["termination"],):
                continue
            kind, x, y = row["type"], float(row[parameter]), float(row["amplitude:x2"])
            if kind in SMOOTH:
                mark(kind, x, y, *MARKERS[kind], 6, SMOOTH[kind])
            elif row is switch:
                mark(kind, x, y, *SWITCH_MARKER, 12, "switch to the adjacent type")
            else:
                mark(kind, x, y, *TYPE_CHANGE_MARKER, 6, "change of type, not switched")
    # A style is in the legend where it is drawn over more than a rounding's width (a branch's
    # located end is on the boundary, its flags decided by rounding).
    width = max(max(float(r[parameter]) for r in rows) for _, _, rows, _ in branches) - min(
        min(float(r[parameter]) for r in rows) for _, _, rows, _ in branches)
    shown = {key for key, span in spans.items() if span > 1e-6 * width}
    handles = [Line2D([], [], color=c, lw=1.8, label=s) for s, c in colours.items()]
    handles += [Line2D([], [], ls=ls, color="black", lw=1.5, label=name) for ls, name, key in
                (("-", "stable", (True, True)), ("--", "unstable", (False, True))) if key in shown]
    if any(not a for _, a in shown):
        handles.append(Line2D([], [], ls="-", **INADMISSIBLE, label="no motion (a margin < 0)"))
    return labels, handles + list(markers.values())


def draw_sweeps(ax, parameter, sweeps):
    """Each sweep point's max |x2| over its recorded periods, by period. Returns legend handles.
    A sweep without the amplitude:x2 column (made before it existed) is refused."""
    from matplotlib.lines import Line2D
    points = {}
    recorded = 0
    for sweep in sweeps:
        rows = list(csv.DictReader(open(sweep)))
        if rows and "amplitude:x2" not in rows[0]:
            raise ValueError(f"{sweep} has no amplitude:x2 column: run the sweep again")
        recorded = max([recorded] + [int(r["k"]) + 1 for r in rows])
        for r in rows:
            if r["k"] == "0":
                period = min(int(r["period"]), 3)
                points.setdefault(period, []).append((float(r[parameter]), float(r["amplitude:x2"])))
    handles = []
    for period, (marker, colour, size, name) in SWEEP_STYLES.items():
        if period in points:
            xs, ys = zip(*points[period])
            ax.plot(xs, ys, marker, color=colour, ms=size, mew=0.6, zorder=2, alpha=0.8)
            handles.append(Line2D([], [], ls="", marker=marker, color=colour, ms=4,
                                  label=f"brute force, {name}"))
    if handles:
        handles.insert(0, Line2D([], [], ls="", label=f"(max |x2| over {recorded} settled periods)"))
    return handles


def frequency_response(directory, sweeps=()):
    """The figure of the trace in `directory` and its axes, the labels and where they were placed
    (label_points)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    trace, branches = read_trace(directory)
    parameter = trace["parameter"]
    figure, ax = plt.subplots(figsize=SIZE)
    sweep_handles = draw_sweeps(ax, parameter, sweeps)
    labels, handles = draw_branches(ax, trace, branches)
    amplitudes = [float(r["amplitude:x2"]) for _, _, rows, _ in branches for r in rows]
    if min(amplitudes) > 0 and max(amplitudes) > 20 * min(amplitudes):
        ax.set_yscale("log")  # a resonance beside small sticking orbits
    ax.legend(handles=handles + sweep_handles, fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0),
              borderaxespad=0.0)
    ax.set_xlabel(parameter)
    ax.set_ylabel("max |x2| over a period")
    ax.grid(alpha=0.3, which="both")
    ends = "; ".join(f"{d['direction']}: {d['end']}" for d in trace["directions"])
    ax.set_title(f"{trace['output']}: frequency response from '{trace['signature']}'\n"
                 f"{len(branches)} branches; ended {ends}", fontsize=10)
    figure.tight_layout()
    return figure, ax, labels, label_points(figure, ax, labels)


def plot_trace(directory, output, sweeps=()):
    """The frequency response of the trace in `directory`, written to `output` (PNG, 1150 x 600)."""
    save(frequency_response(directory, sweeps)[0], output)


def main(argv):
    if len(argv) < 3:
        print(__doc__, file=sys.stderr)
        return 1
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        return 3  # stickslip plot says what to install
    plot_trace(argv[1], argv[2], argv[3:])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
