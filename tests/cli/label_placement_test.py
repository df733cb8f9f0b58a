#!/usr/bin/python3
"""The label placement of tools/stickslip_plot.py: no two labels overprint, and no label covers a
marker, (1) for clusters of random labels drawn from a seeded generator, and (2) on the
bifurcation diagram and on the figure of `stickslip plot` of every stored run under results/ (text
sizes and boxes measured by matplotlib's renderer).

Usage: /usr/bin/python3 tests/cli/label_placement_test.py SOURCE_DIR (run by ctest)."""
import os
import random
import sys

SOURCE = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(SOURCE, "tools"))
import stickslip_plot as bd  # noqa: E402

failed = 0
passed = 0


def check(condition, what):
    global failed, passed
    if condition:
        passed += 1
    else:
        failed += 1
        print("FAILED:", what)


def no_overlaps(boxes, markers, where):
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            if bd.overlap(a, b):
                check(False, f"{where}: labels {a} and {b} overlap")
                return
        for m in markers:
            if bd.overlap(a, m):
                check(False, f"{where}: label {a} covers marker {m}")
                return
    check(True, where)


def overlap_is_symmetric_and_strict():
    check(bd.overlap((0, 0, 2, 2), (1, 1, 3, 3)), "overlapping boxes")
    check(not bd.overlap((0, 0, 1, 1), (1, 0, 2, 1)), "boxes touching at an edge do not overlap")
    check(not bd.overlap((0, 0, 1, 1), (2, 2, 3, 3)), "apart")


def random_clusters():
    generator = random.Random(20261124)
    for trial in range(200):
        count = generator.randint(1, 12)
        centre = (generator.uniform(200, 600), generator.uniform(150, 450))
        anchors = [(centre[0] + generator.gauss(0, 15), centre[1] + generator.gauss(0, 10)) for _ in range(count)]
        sizes = [(generator.uniform(15, 40), generator.uniform(8, 12)) for _ in range(count)]
        markers = [(x - 4, y - 4, x + 4, y + 4) for x, y in anchors]
        placed = bd.place_labels(anchors, sizes, markers, bounds=(0, 0, 800, 600))
        boxes = [box for box, _ in placed]
        for (x0, y0, x1, y1), (w, h) in zip(boxes, sizes):
            check(abs((x1 - x0) - w) < 1e-9 and abs((y1 - y0) - h) < 1e-9, "a placed box keeps its label's size")
        no_overlaps(boxes, markers, f"cluster {trial} of {count} labels")


def stored_runs():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    results = os.path.join(SOURCE, "results")
    runs = sorted(r for r in os.listdir(results) if os.path.isfile(os.path.join(results, r, "summary.json")))
    check(len(runs) >= 19, f"{len(runs)} stored runs")
    for run in runs:
        directory = os.path.join(results, run)
        figure, top, _, canvas = bd.diagram(directory)
        bd.finish_diagram(figure, top, canvas, run)
        figure.canvas.draw()
        anchors = [top.transData.transform((x, y)) for _, x, y in canvas.labels]
        no_overlaps(bd.label_boxes(figure), [(x - 4, y - 4, x + 4, y + 4) for x, y in anchors], f"{run} (diagram)")
        plt.close(figure)
        figure = bd.figure([directory])
        figure.canvas.draw()
        ax = figure.axes[0]
        anchors = [ax.transData.transform(t.xy) for t in ax.texts if t.get_gid() == "stickslip-label"]
        scale = figure.dpi / 100
        no_overlaps(bd.label_boxes(figure), [(x - 4 * scale, y - 4 * scale, x + 4 * scale, y + 4 * scale)
                                             for x, y in anchors], f"{run} (stickslip plot)")
        plt.close(figure)


overlap_is_symmetric_and_strict()
random_clusters()
stored_runs()
print(f"{passed} passed, {failed} failed")
sys.exit(1 if failed else 0)
