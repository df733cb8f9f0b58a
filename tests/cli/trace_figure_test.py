#!/usr/bin/python3
"""The frequency response of a trace (tools/stickslip_plot.py, as `stickslip plot TRACE` draws it)
and the intervals of its orbit types (tools/trace_intervals.py), on the stored traces under results/:
- every stored trace gives a PNG of the default size (9 x 5 inches at 150 dpi) whose labels
  overprint no label and no marker;
- a sweep is overlaid only at the trace's own data (not for section 4.2, whose u_s = u_r is
  solved along the trace), and a sweep made before the amplitude:x2 column is refused;
- the intervals of section 4.1's sticking orbit end at the located points of its special-point
  files: admissible from the grazing GR to the crossing-sliding SK, stable between the two TRs.

Usage: /usr/bin/python3 tests/cli/trace_figure_test.py SOURCE_DIR (run by ctest)."""
import contextlib
import csv
import io
import os
import sys
import tempfile
import unittest

SOURCE = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TOOLS = os.path.join(SOURCE, "tools")
sys.path.insert(0, TOOLS)
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import stickslip_plot as sp  # noqa: E402
import trace_intervals as ti  # noqa: E402

RESULTS = os.path.join(SOURCE, "results")


def traces():
    return sorted(r for r in os.listdir(RESULTS) if os.path.isfile(os.path.join(RESULTS, r, "trace.json")))


def plot(*arguments):
    err = io.StringIO()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
        code = sp.main(["stickslip_plot.py", *arguments])
    return code, err.getvalue()


class TraceFigure(unittest.TestCase):
    def setUp(self):
        self._directory = tempfile.TemporaryDirectory()
        self.work = self._directory.name

    def tearDown(self):
        self._directory.cleanup()

    def test_every_stored_trace_is_drawn_without_overprinting(self):
        import matplotlib.image as image
        import matplotlib.pyplot as plt
        self.assertGreaterEqual(len(traces()), 5)
        for run in traces():
            figure = sp.figure([os.path.join(RESULTS, run)])
            figure.canvas.draw()
            ax = figure.axes[0]
            boxes = sp.label_boxes(figure)
            scale = figure.dpi / 100
            markers = [(x - 4 * scale, y - 4 * scale, x + 4 * scale, y + 4 * scale) for x, y in
                       (ax.transData.transform(t.xy) for t in ax.texts if t.get_gid() == "stickslip-label")]
            clear = all(not sp.overlap(a, b) for i, a in enumerate(boxes) for b in boxes[i + 1:]) and all(
                not sp.overlap(a, m) for a in boxes for m in markers)
            self.assertTrue(clear, f"{run}: labels overprint")
            plt.close(figure)
            output = os.path.join(self.work, f"{run}.png")
            self.assertEqual(plot("--output", output, os.path.join(RESULTS, run))[0], 0)
            height, width = image.imread(output).shape[:2]
            self.assertEqual((width, height), (1350, 750), run)

    def test_sweeps_only_at_the_traces_data(self):
        work = self.work
        _, branches_42 = sp.read_trace(os.path.join(RESULTS, "paper-4.2-omega-trace"))
        _, branches_41 = sp.read_trace(os.path.join(RESULTS, "paper-4.1-omega-trace"))
        self.assertFalse(sp.holds_data(branches_42), "section 4.2's trace solves u_s = u_r: no sweep of fixed data fits")
        self.assertTrue(sp.holds_data(branches_41), "section 4.1's trace holds its data")
        old = os.path.join(work, "old-sweep.csv")
        with open(old, "w") as f:
            f.write("chain,pass,step,omega,section_phase,k,x1,x2,v1,v2,stops_per_period,sticks_per_period,period\n"
                    "0,up,0,0.55,0.39,0,1,2,3,0,2,2,1\n")
        code, message = plot("--output", os.path.join(work, "x.png"), os.path.join(RESULTS, "paper-4.1-omega-trace"), old)
        self.assertEqual(code, 2)
        self.assertIn("y = 'amplitude:x2' is invalid", message)
        self.assertFalse(os.path.exists(os.path.join(work, "x.png")), "nothing written for a refused sweep")

    @staticmethod
    def located(run, branch, kind):
        rows = csv.DictReader(open(os.path.join(RESULTS, run, branch, "special-points.csv")))
        return sorted(float(r["omega"]) for r in rows if r["type"] == kind)

    def test_intervals_end_at_the_located_points(self):
        run = "paper-4.1-omega-trace"
        trace, branches = sp.read_trace(os.path.join(RESULTS, run))
        found = ti.type_intervals(trace, branches)
        admissible, stable = found["slip- stick / antisymmetric"]
        sk, gr, tr = (self.located(run, branch, kind) for branch, kind in
                      (("branch-1", "SK"), ("branch-2", "GR"), ("branch-2", "TR")))
        self.assertEqual(admissible, [[gr[0], sk[0]]], "from the grazing GR to the crossing-sliding SK")
        self.assertEqual(stable, [[tr[0], tr[1]]], "between the two torus points")
        self.assertEqual(ti.joined([(0, 1), (1, 2), (3, 4), (3.5, 3.7)]), [[0, 2], [3, 4]])


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
