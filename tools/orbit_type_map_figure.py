#!/usr/bin/python3
"""The figure of an orbit-type map (stickslip map's directory) as a PNG: (a) the rectangle's regions
shaded by their stable motions (the admissible stable orbit types found at each region's interior
point; white where none), the curves coloured by kind (solid where the orbit on the curve is
admissible apart from the curve's own condition, dashed where not), their special points (folds,
codimension-two points: not the starts, the rectangle's edges or BP) marked and labelled, each region's
interior point numbered, and the paper's example (the trace's start) starred; (b) with a brute-force
map (stickslip map-sweep's CSV), its cells coloured by the stable period-1 types found there (the
same colours; grey for other motions only) with the curves overlaid.

Usage: /usr/bin/python3 tools/orbit_type_map_figure.py MAPDIR OUT.png [BRUTE.csv]
"""
import csv
import json
import os
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def canonical(sig):
    """The orbit type up to a cyclic shift of its segments (as analysis/map_comparison.hpp)."""
    head, sep, tail = sig.partition(" /")
    tokens = head.split()
    rotations = [tokens[k:] + tokens[:k] for k in range(len(tokens))] or [tokens]
    return " ".join(min(rotations)) + (sep + tail if sep else "")


def kind_name(kind):
    return kind[len("margin:"):] if kind.startswith("margin:") else kind


def read_curves(path):
    curves = defaultdict(lambda: dict(x=[], y=[], adm=[], kind=""))
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        first, second = header[7], header[8]
        for row in reader:
            c = curves[int(row[0])]
            c["kind"] = row[1]
            c["x"].append(float(row[7]))
            c["y"].append(float(row[8]))
            c["adm"].append(row[10] == "1")
    return first, second, curves


def read_brute(path):
    cells = {}
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    header = list(rows[0].keys())
    first, second = header[4], header[5]
    for r in rows:
        if r["k"] != "0":
            continue
        cell = cells.setdefault((int(r["i"]), int(r["j"])), dict(x=float(r[first]), y=float(r[second]), types=set(), other=False))
        if r["status"] == "periodic" and r["period"] == "1" and r["signature"]:
            cell["types"].add(canonical(r["signature"]))
        else:
            cell["other"] = True
    return cells


def trace_start(trace, first, second):
    try:
        with open(os.path.join(trace, "branch-1", "branch.csv"), newline="") as f:
            row = next(csv.DictReader(f))
        return float(row[first]), float(row[second])
    except (OSError, StopIteration, KeyError):
        return None


def draw_curves(ax, curves, colours, special, label_points):
    seen = set()
    for cid, c in sorted(curves.items()):
        colour = colours[c["kind"]]
        x, y, adm = np.array(c["x"]), np.array(c["y"]), np.array(c["adm"])
        for solid in (True, False):
            xs, ys = x.copy(), y.copy()
            mask = adm if solid else ~adm
            # a segment is drawn in the style of its first point
            keep = mask.copy()
            keep[1:] |= mask[:-1]
            xs[~keep], ys[~keep] = np.nan, np.nan
            label = kind_name(c["kind"]) if solid and c["kind"] not in seen else None
            ax.plot(xs, ys, color=colour, lw=1.6 if solid else 1.0, ls="-" if solid else "--", label=label)
        seen.add(c["kind"])
    if label_points:
        # Each label at the first of a few offsets whose box (display pixels, estimated from its
        # length) overlaps no label placed before; the same label at the same point once.
        fig = ax.figure
        fig.canvas.draw()
        boxes, done = [], set()
        offsets = [(6, 6), (6, -14), (-8, 6), (-8, -14), (6, 20), (6, -28), (-8, 20), (-8, -28)]
        for x, y, text in sorted(special):
            key = (round(x, 6), round(y, 6), text)
            if key in done:
                continue
            done.add(key)
            ax.plot(x, y, "o", ms=5, mfc="white", mec="black", zorder=5)
            px, py = ax.transData.transform((x, y))
            width, height = 5.2 * len(text), 10
            for dx, dy in offsets:
                left = px + dx if dx > 0 else px + dx - width
                box = (left, py + dy, left + width, py + dy + height)
                if not any(b[0] < box[2] and box[0] < b[2] and b[1] < box[3] and box[1] < b[3] for b in boxes):
                    break
            boxes.append(box)
            ax.annotate(text, (x, y), textcoords="offset points", xytext=(dx * 72 / fig.dpi, dy * 72 / fig.dpi),
                        ha="left" if dx > 0 else "right", fontsize=7, zorder=6,
                        bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.7))


def main(directory, out, brute_path=None):
    with open(os.path.join(directory, "regions.json")) as f:
        regions = json.load(f)
    first, second = regions["first"], regions["second"]
    rect = regions["rectangle"]
    extent = (rect["first_min"], rect["first_max"], rect["second_min"], rect["second_max"])
    _, _, curves = read_curves(os.path.join(directory, "curves.csv"))
    labels = sorted({" + ".join(canonical(t) for t in r["stable_types"]) or "none" for r in regions["regions"]})
    brute = read_brute(brute_path) if brute_path else {}
    for cell in brute.values():
        labels.append(" + ".join(sorted(cell["types"])) or "none")
    labels = sorted(set(labels) - {"none"})
    palette = plt.get_cmap("Pastel1").colors + plt.get_cmap("Pastel2").colors
    shade = {lab: palette[k % len(palette)] for k, lab in enumerate(labels)}
    shade["none"] = (1.0, 1.0, 1.0)
    kinds = sorted({c["kind"] for c in curves.values()})
    strong = plt.get_cmap("tab10").colors
    colours = {k: strong[n % len(strong)] for n, k in enumerate(kinds)}
    # The curves' codimension-two points (not their ends, EP, nor the bordered determinant's sign
    # changes, BP), one label per place: the types met there and the curves' kinds ("SK (LP, PD)"),
    # points within 1/60 of the axes' ranges taken as one place.
    places = {}
    for c in regions["curves"]:
        for p in c["special_points"]:
            if p["type"] in ("EP", "BP"):
                continue
            key = (round(p[first] / (extent[1] - extent[0]) * 60), round(p[second] / (extent[3] - extent[2]) * 60))
            place = places.setdefault(key, dict(x=p[first], y=p[second], types=set(), kinds=set()))
            place["types"].add(p["type"])
            place["kinds"].add(kind_name(c["kind"]))
    special = [(q["x"], q["y"], f'{"/".join(sorted(q["types"]))} ({", ".join(sorted(q["kinds"]))})') for q in places.values()]
    start = trace_start(regions["trace"], first, second)

    panels = 2 if brute else 1
    fig, axes = plt.subplots(1, panels, figsize=(6.8 * panels + 2.6, 5.6), constrained_layout=True, squeeze=False)
    ax = axes[0][0]
    rows = [[int(v) for v in row.split()] for row in regions["cells"]]
    n = regions["raster"]
    image = np.ones((n, n, 3))
    by_id = {r["id"]: r for r in regions["regions"]}
    for j in range(n):
        for i in range(n):
            rid = rows[j][i]
            if rid > 0:
                lab = " + ".join(canonical(t) for t in by_id[rid]["stable_types"]) or "none"
                image[j, i] = shade[lab]
            else:
                image[j, i] = (0.85, 0.85, 0.85) if rid == -2 else (1.0, 1.0, 1.0)
    ax.imshow(image, origin="lower", extent=extent, aspect="auto", interpolation="nearest")
    ax.set_xlim(extent[0], extent[1])
    ax.set_ylim(extent[2], extent[3])
    draw_curves(ax, curves, colours, special, False)
    for r in regions["regions"]:
        ax.annotate(str(r["id"]), (r[first], r[second]), fontsize=7, ha="center", va="center", color="0.3")
    if start:
        ax.plot(*start, marker="*", ms=12, color="gold", mec="black", ls="none", label="paper example", zorder=6)
    for lab in labels:
        ax.plot([], [], "s", ms=9, color=shade[lab], label=f"stable: {lab}")
    ax.set_xlabel(first)
    ax.set_ylabel(second)
    ax.set_title(f"(a) orbit-type map from {os.path.basename(regions['trace'].rstrip('/'))}", fontsize=10)
    # The legend beside the last panel, clear of the curves' labels.
    handles, names = ax.get_legend_handles_labels()
    axes[0][-1].legend(handles, names, fontsize=7, loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)
    draw_curves(axes[0][0], {}, colours, special, True)  # labelled last, the axes' limits fixed
    if brute:
        ax = axes[0][1]
        xs = sorted({c["x"] for c in brute.values()})
        ys = sorted({c["y"] for c in brute.values()})
        dx = (xs[-1] - xs[0]) / max(1, len(xs) - 1)
        dy = (ys[-1] - ys[0]) / max(1, len(ys) - 1)
        # Other motions marked per cell where the cells are large enough to show a mark.
        marks = len(xs) <= 40 and len(ys) <= 40
        for cell in brute.values():
            lab = " + ".join(sorted(cell["types"])) or "none"
            colour = shade[lab] if lab != "none" else ((0.7, 0.7, 0.7) if cell["other"] else (1, 1, 1))
            ax.add_patch(plt.Rectangle((cell["x"] - dx / 2, cell["y"] - dy / 2), dx, dy, color=colour, lw=0))
            if cell["other"] and marks:
                ax.plot(cell["x"], cell["y"], "x", color="0.35", ms=3)
        ax.set_xlim(extent[0], extent[1])
        ax.set_ylim(extent[2], extent[3])
        draw_curves(ax, curves, colours, special, False)
        if start:
            ax.plot(*start, marker="*", ms=12, color="gold", mec="black", ls="none")
        ax.set_xlabel(first)
        ax.set_ylabel(second)
        other = "x: other motions" if marks else "grey: other motions only"
        ax.set_title(f"(b) brute force ({len(xs)} x {len(ys)} cells): stable period-1 types ({other})", fontsize=10)
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4):
        raise SystemExit(__doc__)
    main(*sys.argv[1:])
