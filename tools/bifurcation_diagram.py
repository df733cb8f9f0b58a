"""The bifurcation diagram of one continuation run, drawn by `stickslip plot RUN` and by
tools/plot_figures.py (which overlays the brute-force sweeps).

Top: x20 (the orbit's origin) over the continued parameter; bottom: the segment durations.
Stable stretches solid, unstable dashed; stretches where the orbit is no motion of the system
(a margin <= 0, past a type change) thin, grey (x20) or faded (the durations), whatever their
stability; the point where
stability or admissibility changes is repeated in both pieces, so the curve has no gap. Special
points are marked by kind and labelled, each label placed where it overprints no other label and
no marker (place_labels, a greedy search over positions around the point).

Usage (what `stickslip plot` runs): /usr/bin/python3 bifurcation_diagram.py RUN_DIRECTORY OUTPUT.png
Exit codes: 0 written; 3 matplotlib cannot be imported; 1 the drawing failed (nothing written).
"""
import csv
import json
import os
import sys

SIZE = (8, 6)  # inches, at 100 dpi: 800 x 600 pixels
INADMISSIBLE = dict(color="0.65", lw=0.9)
# Marker and colour by kind of special point: smooth bifurcations, user values, ends, and the
# nonsmooth orbit-type changes (SK, GR, ... : every other code).
MARKERS = {"LP": ("s", "red"), "BP": ("^", "red"), "SB": ("^", "red"), "PD": ("v", "red"), "TR": ("D", "red"),
           "NS": ("D", "red"), "UZ": ("o", "C0"), "EP": ("o", "black")}
TYPE_CHANGE_MARKER = ("o", "darkorange")


def runs_of(rows, key):
    """Consecutive pieces of rows with the same key (a column name or a function of the row), the
    boundary row repeated in both pieces."""
    value = key if callable(key) else (lambda row: row[key])
    pieces, current = [], []
    for row in rows:
        if current and value(row) != value(current[-1]):
            current.append(row)
            pieces.append(current)
            current = [row]
        else:
            current.append(row)
    if current:
        pieces.append(current)
    return pieces


def save(figure, path):
    """Writes the PNG whole or not at all (a temporary file beside it, then renamed), without
    volatile metadata."""
    import matplotlib.pyplot as plt
    directory, name = os.path.split(os.path.abspath(path))
    temporary = os.path.join(directory, f".{name}.tmp.{os.getpid()}.png")
    try:
        figure.savefig(temporary, dpi=100, metadata={"Software": None})
        os.replace(temporary, path)
    finally:
        plt.close(figure)
        if os.path.exists(temporary):
            os.remove(temporary)
    print("wrote", path)


def overlap(a, b):
    """Whether boxes (x0, y0, x1, y1) overlap with a positive area."""
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def candidate_boxes(anchor, size, rings=8, gap=5.0, step=9.0):
    """Boxes of a label of `size` (w, h) around `anchor` (x, y), nearest first: above right, above
    left, below right, below left, right, left, above, below, then the same further out."""
    x, y = anchor
    w, h = size
    for ring in range(rings):
        g = gap + step * ring
        for dx, dy in ((g, g), (-g - w, g), (g, -g - h), (-g - w, -g - h), (g, -h / 2), (-g - w, -h / 2),
                       (-w / 2, g), (-w / 2, -g - h)):
            yield (x + dx, y + dy, x + dx + w, y + dy + h), ring


def place_labels(anchors, sizes, obstacles=(), bounds=None, rings=8):
    """Greedy label placement: each label in turn takes the nearest candidate box
    (candidate_boxes) that overlaps no label placed before it and no obstacle (the markers), and
    lies inside `bounds` (x0, y0, x1, y1) when given; where every candidate collides, the one with
    the least overlap. Returns (box, ring) per label, in display units."""
    placed = []
    for anchor, size in zip(anchors, sizes):
        best, best_cost = None, None
        for box, ring in candidate_boxes(anchor, size, rings):
            inside = bounds is None or (box[0] >= bounds[0] and box[1] >= bounds[1] and
                                        box[2] <= bounds[2] and box[3] <= bounds[3])
            cost = sum(overlap_area(box, other) for other, _ in placed) + sum(
                overlap_area(box, o) for o in obstacles) + (0.0 if inside else 1e9)
            if cost == 0.0:
                best = (box, ring)
                break
            if best_cost is None or cost < best_cost:
                best, best_cost = (box, ring), cost
        placed.append(best)
    return placed


def overlap_area(a, b):
    return max(0.0, min(a[2], b[2]) - max(a[0], b[0])) * max(0.0, min(a[3], b[3]) - max(a[1], b[1]))


def read_run(directory):
    summary = json.load(open(os.path.join(directory, "summary.json")))
    rows = list(csv.DictReader(open(os.path.join(directory, "branch.csv"))))
    special = list(csv.DictReader(open(os.path.join(directory, "special-points.csv"))))
    return summary, rows, special


def draw_run(top, bottom, directory, y="x20", stable=lambda row: row["stable"] == "1"):
    """Draws the run's branch on the two axes: the column `y` (x20; the second parameter of a curve
    in two parameters) on `top`, the durations on `bottom`, and the special points' markers on
    `top`, and the durations' legend; `stable` says which rows are. Returns the labels to place
    (label_points, once every other artist is drawn, since the placement depends on the axes'
    final limits) and the legend handles of the branch's styles for `top`."""
    summary, rows, special = read_run(directory)
    parameter = summary["parameter"]
    durations = [c for c in rows[0] if c.startswith("d") and c[1:].isdigit()]
    kinds = set()  # (stable, admissible) pairs drawn, for the legend
    for piece in runs_of(rows, lambda r: (stable(r), r["admissible"])):
        is_stable, admissible = stable(piece[0]), piece[0]["admissible"] == "1"
        if len(piece) > 1:  # a piece of one point (a last point past a type change) draws nothing
            kinds.add((is_stable, admissible))
        style = "-" if is_stable else "--"
        xs = [float(r[parameter]) for r in piece]
        top.plot(xs, [float(r[y]) for r in piece], style, **(dict(color="C0", lw=1.5) if admissible else INADMISSIBLE))
        for k, d in enumerate(durations):
            # The durations keep their colours where the orbit is no motion, faded and thin.
            bottom.plot(xs, [float(r[d]) for r in piece], style, color=f"C{k + 1}",
                        **(dict(lw=1.5) if admissible else dict(lw=0.9, alpha=0.4)))
    from matplotlib.lines import Line2D
    legend = [Line2D([], [], ls="-", color="C0", lw=1.5, label="stable")] if (True, True) in kinds else []
    legend += [Line2D([], [], ls="--", color="C0", lw=1.5, label="unstable")] if (False, True) in kinds else []
    legend += [Line2D([], [], ls="-", **INADMISSIBLE, label="no motion (a margin < 0)")] if any(
        not a for _, a in kinds) else []
    bottom.legend(handles=[Line2D([], [], color=f"C{k + 1}", lw=1.5, label=d) for k, d in enumerate(durations)],
                  fontsize=7, loc="best", ncol=min(len(durations), 4))
    labels = []
    for row in special:
        if row["test_function"] in ("start", summary["termination"]):
            continue
        at = float(row[parameter]), float(row[y])
        marker, color = MARKERS.get(row["type"], TYPE_CHANGE_MARKER)
        top.plot(*at, marker, color=color, ms=5, mec="black", mew=0.5, zorder=5)
        labels.append((row["label"], *at))
    return labels, legend


def label_points(figure, ax, labels, fontsize=8):
    """Places each (label, x, y) by place_labels so that no two labels, no label and marker, and
    where it can be helped no label and curve or legend overprint; a label pushed away from its
    point gets a thin leader line."""
    if not labels:
        return []
    ax.set_xlim(ax.get_xlim())  # the limits the placement is computed for
    ax.set_ylim(ax.get_ylim())
    renderer = figure.canvas.get_renderer()
    anchors, sizes = [], []
    for text, x, y in labels:
        anchors.append(tuple(ax.transData.transform((x, y))))
        probe = ax.text(0, 0, text, fontsize=fontsize)
        extent = probe.get_window_extent(renderer)
        probe.remove()
        sizes.append((extent.width + 2, extent.height + 2))
    obstacles = [(ax_x - 4, ax_y - 4, ax_x + 4, ax_y + 4) for ax_x, ax_y in anchors]
    for line in ax.get_lines():  # the curves, point by point
        for px, py in ax.transData.transform(line.get_xydata()):
            obstacles.append((px - 1.5, py - 1.5, px + 1.5, py + 1.5))
    if ax.get_legend() is not None:
        obstacles.append(tuple(ax.get_legend().get_window_extent(renderer).extents))
    bounds = tuple(ax.get_window_extent(renderer).extents)
    placed = place_labels(anchors, sizes, obstacles, bounds)
    for (text, x, y), anchor, (box, ring) in zip(labels, anchors, placed):
        offset = (box[0] + 1 - anchor[0], box[1] + 1 - anchor[1])
        ax.annotate(text, (x, y), xytext=offset, textcoords="offset pixels", ha="left", va="bottom",
                    fontsize=fontsize, zorder=6,
                    arrowprops=dict(arrowstyle="-", color="0.4", lw=0.5, shrinkA=0, shrinkB=3) if ring > 0 else None)
    return placed


def plot_run(directory, output):
    """The diagram of the run in `directory`, written to `output` (PNG, 800 x 600)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    summary, _, _ = read_run(directory)
    figure, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=SIZE)
    labels, legend = draw_run(top, bottom, directory)
    top.legend(handles=legend, fontsize=7, loc="best")
    top.set_ylabel("x20 (orbit origin)")
    top.grid(alpha=0.3)
    bottom.grid(alpha=0.3)
    bottom.set_ylabel("segment durations")
    bottom.set_xlabel(summary["parameter"])
    top.set_title(f"{summary['output']}: {summary['signature']}\n"
                  f"solid stable, dashed unstable, grey no motion; ended: {summary['termination']}", fontsize=10)
    figure.tight_layout()
    label_points(figure, top, labels)
    save(figure, output)


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 1
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        return 3  # stickslip plot says what to install
    plot_run(argv[1], argv[2])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
