#!/usr/bin/python3
"""The frequency response of a trace (tools/trace_figure.py) and the intervals of its orbit types
(tools/trace_intervals.py), on the stored traces under results/:
- every stored trace gives a 1150 x 600 PNG whose labels overprint no label and no marker;
- a sweep is overlaid only at the trace's own data (not for section 4.2, whose u_s = u_r is
  solved along the trace), and a sweep made before the amplitude:x2 column is refused;
- without matplotlib the script exits 3 and writes nothing (what `stickslip plot` reports);
- the intervals of section 4.1's sticking orbit end at the located points of its special-point
  files: admissible from the grazing GR to the crossing-sliding SK, stable between the two TRs.

Usage: /usr/bin/python3 tests/cli/trace_figure_test.py SOURCE_DIR (run by ctest)."""
import csv
import os
import subprocess
import sys
import tempfile
import unittest

SOURCE = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TOOLS = os.path.join(SOURCE, "tools")
sys.path.insert(0, TOOLS)
import bifurcation_diagram as bd  # noqa: E402
import trace_figure as tf  # noqa: E402
import trace_intervals as ti  # noqa: E402

RESULTS = os.path.join(SOURCE, "results")


def traces():
    return sorted(r for r in os.listdir(RESULTS) if os.path.isfile(os.path.join(RESULTS, r, "trace.json")))


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
            figure, ax, labels, placed = tf.frequency_response(os.path.join(RESULTS, run))
            boxes = [box for box, _ in placed]
            markers = [(x - 4, y - 4, x + 4, y + 4) for x, y in (ax.transData.transform((x, y)) for _, x, y in labels)]
            clear = all(not bd.overlap(a, b) for i, a in enumerate(boxes) for b in boxes[i + 1:]) and all(
                not bd.overlap(a, m) for a in boxes for m in markers)
            self.assertTrue(clear, f"{run}: labels overprint")
            plt.close(figure)
            output = os.path.join(self.work, f"{run}.png")
            tf.plot_trace(os.path.join(RESULTS, run), output)
            height, width = image.imread(output).shape[:2]
            self.assertEqual((width, height), (1150, 600), run)

    def test_sweeps_only_at_the_traces_data(self):
        work = self.work
        _, branches_42 = tf.read_trace(os.path.join(RESULTS, "paper-4.2-omega-trace"))
        _, branches_41 = tf.read_trace(os.path.join(RESULTS, "paper-4.1-omega-trace"))
        self.assertFalse(tf.holds_data(branches_42), "section 4.2's trace solves u_s = u_r: no sweep of fixed data fits")
        self.assertTrue(tf.holds_data(branches_41), "section 4.1's trace holds its data")
        old = os.path.join(work, "old-sweep.csv")
        with open(old, "w") as f:
            f.write("chain,pass,step,omega,section_phase,k,x1,x2,v1,v2,stops_per_period,sticks_per_period,period\n"
                    "0,up,0,0.55,0.39,0,1,2,3,0,2,2,1\n")
        with self.assertRaisesRegex(ValueError, "amplitude:x2"):
            tf.plot_trace(os.path.join(RESULTS, "paper-4.1-omega-trace"), os.path.join(work, "x.png"), [old])
        self.assertFalse(os.path.exists(os.path.join(work, "x.png")), "nothing written for a refused sweep")

    def test_without_matplotlib_exit_3(self):
        work = self.work
        fake = os.path.join(work, "fake", "matplotlib")
        os.makedirs(fake)
        with open(os.path.join(fake, "__init__.py"), "w") as f:
            f.write('raise ImportError("No module named matplotlib (test)")\n')
        output = os.path.join(work, "none.png")
        done = subprocess.run(["/usr/bin/python3", os.path.join(TOOLS, "trace_figure.py"),
                               os.path.join(RESULTS, "paper-4.1-omega-trace"), output],
                              env=dict(os.environ, PYTHONPATH=os.path.join(work, "fake")), capture_output=True)
        self.assertEqual(done.returncode, 3, "the exit code without matplotlib")
        self.assertFalse(os.path.exists(output), "nothing written without matplotlib")

    @staticmethod
    def located(run, branch, kind):
        rows = csv.DictReader(open(os.path.join(RESULTS, run, branch, "special-points.csv")))
        return sorted(float(r["omega"]) for r in rows if r["type"] == kind)

    def test_intervals_end_at_the_located_points(self):
        run = "paper-4.1-omega-trace"
        trace, branches = tf.read_trace(os.path.join(RESULTS, run))
        found = ti.type_intervals(trace, branches)
        admissible, stable = found["slip- stick / antisymmetric"]
        sk, gr, tr = (self.located(run, branch, kind) for branch, kind in
                      (("branch-1", "SK"), ("branch-2", "GR"), ("branch-2", "TR")))
        self.assertEqual(admissible, [[gr[0], sk[0]]], "from the grazing GR to the crossing-sliding SK")
        self.assertEqual(stable, [[tr[0], tr[1]]], "between the two torus points")
        self.assertEqual(ti.joined([(0, 1), (1, 2), (3, 4), (3.5, 3.7)]), [[0, 2], [3, 4]])


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
