#!/usr/bin/python3
"""The figure of a brute-force map (stickslip map-sweep's CSV) as a PNG: two panels over the grid
of the two parameters, (a) the number of coexisting attractors found in each cell, (b) the period
(in forcing periods) of each cell's periodic attractors that move, the largest of them shown, and
whether they stick: cells with a sticking attractor marked with a dot. Cells where some run did not
settle (or stopped at the simulator's event guard) are marked with a cross.

Usage: /usr/bin/python3 tools/map_figure.py MAP.csv OUT.png
"""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read_map(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise SystemExit(f"error: map = '{path}' is invalid: valid a map file with at least one cell")
    header = list(rows[0].keys())
    first, second = header[4], header[5]
    ni, nj = int(rows[0]["ni"]), int(rows[0]["nj"])
    cells = {}
    for r in rows:
        if r["k"] != "0":
            continue
        cell = cells.setdefault((int(r["i"]), int(r["j"])), dict(x=float(r[first]), y=float(r[second]), attractors=[]))
        cell["attractors"].append(dict(status=r["status"], period=int(r["period"]),
                                       stops=float(r["stops_per_period"]), sticks=float(r["sticks_per_period"])))
    return first, second, ni, nj, cells


def main(path, out):
    first, second, ni, nj, cells = read_map(path)
    count = np.full((nj, ni), np.nan)
    period = np.full((nj, ni), np.nan)
    xs, ys = np.full(ni, np.nan), np.full(nj, np.nan)
    sticking, unsettled = [], []
    for (i, j), cell in cells.items():
        xs[i], ys[j] = cell["x"], cell["y"]
        count[j, i] = len(cell["attractors"])
        moving = [a for a in cell["attractors"] if a["status"] == "periodic" and a["stops"] > 0]
        period[j, i] = max((a["period"] for a in moving), default=0)
        if any(a["sticks"] > 0 for a in moving):
            sticking.append((cell["x"], cell["y"]))
        if any(a["status"] != "periodic" for a in cell["attractors"]):
            unsettled.append((cell["x"], cell["y"]))
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), constrained_layout=True)
    extent = None
    if ni > 1 and nj > 1:
        dx, dy = (xs[-1] - xs[0]) / (ni - 1), (ys[-1] - ys[0]) / (nj - 1)
        extent = (xs[0] - dx / 2, xs[-1] + dx / 2, ys[0] - dy / 2, ys[-1] + dy / 2)
    for ax, values, title in ((axes[0], count, "(a) coexisting attractors"),
                              (axes[1], period, "(b) largest period of a moving attractor (0: none)")):
        top = int(np.nanmax(values))  # whole numbers: one colour each
        image = ax.imshow(values, origin="lower", aspect="auto", extent=extent, interpolation="nearest",
                          cmap=plt.get_cmap("tab20", top + 1), vmin=-0.5, vmax=top + 0.5)
        fig.colorbar(image, ax=ax, ticks=range(0, top + 1, max(1, (top + 1) // 10)))
        ax.set_xlabel(first)
        ax.set_ylabel(second)
        ax.set_title(title, fontsize=10)
    if sticking:
        axes[1].plot(*zip(*sticking), ".", color="white", ms=3, label="sticks")
    if unsettled:
        axes[0].plot(*zip(*unsettled), "x", color="red", ms=4, label="a run did not settle")
    for ax in axes:
        if ax.get_legend_handles_labels()[0]:
            ax.legend(loc="upper right", fontsize=8)
    fig.suptitle(f"brute-force map: {os.path.basename(path)}", fontsize=10)
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    main(sys.argv[1], sys.argv[2])
