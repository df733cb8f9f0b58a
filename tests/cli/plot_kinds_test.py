#!/usr/bin/python3
"""The figures of tools/stickslip_plot.py (what `stickslip plot` and stickslip.plotting draw), on
small results made from the stored ones:
- every kind (branch, curve in two parameters, trace, trace with a branch followed at a
  bifurcation, sweep, brute-force map, orbit-type map, a [model]'s orbit-type map, overlays)
  renders to PNG, PDF and SVG, the file of the extension's format, at the size and dpi asked;
- no two texts of a figure overprint: the labels placed on points, the natural frequencies' labels,
  the title, the axis and tick labels and the legend's entries (boxes from matplotlib's renderer);
- axes are linear unless asked (no switching), limits and quantities as asked, the natural
  frequencies (eq. 56; a [model]'s from its trace) where they belong, a [model]'s units on the
  axes, titles in words (no internal end codes);
- each special point's legend entry by its code: a curve's resonances R1 to R4 and its fold-flip
  LPPD as such, never as a change of orbit type;
- an orbit-type map's region that is not uniform ("differing" > 0 in regions.json: a boundary is
  missing) hatched over its cells, its fill as before, and named in the legend; a map whose regions
  all have differing 0 draws as one written before the key existed (no key), byte for byte;
- every invalid option: exit 2, one line naming the option, the value and the valid range, nothing
  written; without matplotlib exit 3, nothing written.

Usage: /usr/bin/python3 tests/cli/plot_kinds_test.py SOURCE_DIR (run by ctest)."""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

SOURCE = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TOOLS = os.path.join(SOURCE, "tools")
SCRIPT = os.path.join(TOOLS, "stickslip_plot.py")
RESULTS = os.path.join(SOURCE, "results")
sys.path.insert(0, TOOLS)
import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import stickslip_plot as sp  # noqa: E402

MAGIC = {".png": b"\x89PNG\r\n\x1a\n", ".pdf": b"%PDF", ".svg": b"<?xml"}
INTERNAL_WORDS = ("no-adjacent-type", "not-confirmed", "parameter-bound", "terminal-event", "lambda_", "same-type-on")


def head_of_csv(source, target, keep):
    """The rows of a CSV for which keep(row as dict) holds, header kept."""
    import csv
    with open(source, newline="") as f, open(target, "w", newline="") as g:
        reader = csv.DictReader(f)
        writer = csv.DictWriter(g, fieldnames=reader.fieldnames, lineterminator="\n")
        writer.writeheader()
        for row in reader:
            if keep(row):
                writer.writerow(row)


def write_model_map(work, name, units=None, trace="model-trace", differing=None):
    """A small orbit-type map of a [model] (Den Hartog's one mass, over (omega, F_s)), written as
    `stickslip map` writes one: regions.json on a 4 x 4 raster, curves.csv with the model's own
    parameters' columns (no chi, eta), curve-1/summary.json naming the model and, when given, its
    units; beside it its trace, whose trace.json lists the slip's natural frequency, 1 (inside the
    map's omega range). Without `differing` its regions have no "differing" key (a map written
    before it existed); with it, region 1 has differing 0 and region 2 (its cells (0, 2), (0, 3)
    and (1, 3), column and row) `differing` (> 0: not uniform). Returns the map's directory."""
    directory = os.path.join(work, name)
    os.makedirs(os.path.join(directory, "curve-1"))
    os.makedirs(os.path.join(work, "model-trace", "branch-1"), exist_ok=True)
    with open(os.path.join(work, "model-trace", "trace.json"), "w") as f:
        json.dump({"parameter": "omega", "signature": "slip+ / antisymmetric", "model": "linear-oscillator",
                   "natural_frequencies": [1.0], "directions": [], "branches": []}, f, indent=2)
    with open(os.path.join(work, "model-trace", "branch-1", "branch.csv"), "w") as f:
        f.write("pt,label,omega,F_k,F_s,v_b\n1,EP1,0.9,0.2,0.35,0\n")
    # The boundary F_s = omega - 0.5: the non-sticking orbit below it, a sticking one above.
    curve = [(0.8, 0.3), (1.0, 0.5), (1.1, 0.6)]
    with open(os.path.join(directory, "curves.csv"), "w") as f:
        f.write("curve,kind,from,direction,signature,pt,label,omega,F_s,stable,admissible,omega,F_k,F_s,v_b,phi,m1_0,"
                "durations\n")
        for k, (omega, static) in enumerate(curve, 1):
            f.write(f"1,margin:reversal:1,branch-1:SK2,1,slip+ / antisymmetric,{k},{'EP' + str(k) if k != 2 else ''},"
                    f"{omega},{static},1,1,{omega},0.2,{static},0,-3.0,-1.5,5.4\n")
    summary = {"run_file": "den-hartog.toml", "output": "curve-1", "signature": "slip+ / antisymmetric",
               "parameter": "omega", "shooting": "single", "model": "linear-oscillator", "points": 3,
               "termination": "parameter-bound", "message": "reached F_s = 0.6"}
    if units:
        summary["units"] = units
    with open(os.path.join(directory, "curve-1", "summary.json"), "w") as f:
        json.dump(summary, f, indent=2)
    cells = ["1 1 1 1", "1 1 1 1", "2 1 1 1", "2 2 1 1"]  # rows of F_s, lowest first; columns of omega
    regions = {"trace": trace, "first": "omega", "second": "F_s",
               "rectangle": {"first_min": 0.8, "first_max": 1.2, "second_min": 0.2, "second_max": 0.6},
               "raster": 4, "min_region": 0.002,
               "regions": [{"id": 1, "cells": 13, "omega": 1.05, "F_s": 0.35, "label": "slip+ / antisymmetric (stable)",
                            "stable_types": ["slip+ / antisymmetric"], "orbits": [], "failures": []},
                           {"id": 2, "cells": 3, "omega": 0.85, "F_s": 0.55,
                            "label": "slip+ stick / antisymmetric (stable)",
                            "stable_types": ["slip+ stick / antisymmetric"], "orbits": [], "failures": []}],
               "curves": [{"id": 1, "kind": "margin:reversal:1", "from": "branch-1:SK2", "direction": 1,
                           "directory": "curve-1", "points": 3, "end": "parameter-bound",
                           "message": "reached F_s = 0.6",
                           "special_points": [{"label": "EP1", "type": "EP", "test_function": "start", "omega": 0.8,
                                               "F_s": 0.3}]}],
               "skipped": 0, "comparison": None, "cells": cells}
    if differing is not None:
        first, second = regions["regions"]
        first.update(differing=0, elsewhere=[])
        second.update(differing=differing, elsewhere=[
            f"branch-1 pt {k} at (omega, F_s) = (0.8{k}, 0.55): slip+ / antisymmetric (stable)"
            for k in range(1, min(differing, 5) + 1)])
        if differing > 0:
            second["label"] = f"not uniform: slip+ stick / antisymmetric (stable), {differing} place(s) differ"
    with open(os.path.join(directory, "regions.json"), "w") as f:
        json.dump(regions, f, indent=2)
    return directory


class Small:
    """Small results in a temporary directory, one per kind."""

    def __init__(self, work):
        self.work = work
        self.branch = os.path.join(RESULTS, "paper-5.1-omega-up")
        self.curve = os.path.join(RESULTS, "paper-5.1-fold-curve")
        self.trace = os.path.join(RESULTS, "paper-4.1-omega-trace")
        # A trace whose PD3 was followed (trace.json names the followed branch's directory).
        self.followed = os.path.join(work, "followed-trace")
        shutil.copytree(os.path.join(RESULTS, "paper-5.2-omega-trace"), self.followed)
        shutil.copytree(os.path.join(RESULTS, "paper-5.2-period-2"), os.path.join(self.followed, "branch-2-PD3"))
        with open(os.path.join(self.followed, "trace.json")) as f:
            trace = json.load(f)
        for entry in trace["branches"]:
            for bifurcation in entry["bifurcations"]:
                if entry["name"] == "branch-2" and bifurcation["label"] == "PD3":
                    bifurcation["followed"] = "branch-2-PD3"
        with open(os.path.join(self.followed, "trace.json"), "w") as f:
            json.dump(trace, f, indent=2)
        self.sweep = os.path.join(work, "sweep.csv")
        head_of_csv(os.path.join(RESULTS, "sweeps", "paper-5.1-omega.csv"), self.sweep, lambda r: int(r["step"]) % 5 == 0)
        self.map_sweep = os.path.join(work, "map-sweep.csv")
        head_of_csv(os.path.join(RESULTS, "maps", "paper-6-omega-u_r-brute-force.csv"), self.map_sweep,
                    lambda r: int(r["i"]) % 3 == 0)
        self.orbit_type_map = os.path.join(RESULTS, "maps", "paper-6-omega-u_r")
        self.orbit_type_map_51 = os.path.join(RESULTS, "maps", "paper-5.1-omega-u_r")
        self.model_map = write_model_map(work, "model-map", units={"length": "mm", "time": "ms", "force": "kN"})
        # Its region 2 not uniform (a boundary the map lacks crosses it).
        self.not_uniform_map = write_model_map(work, "not-uniform-map", differing=3)

    def kinds(self):
        """(name, inputs, options) of every kind and overlay."""
        return [("branch", [self.branch], []), ("curve", [self.curve], []), ("trace", [self.trace], []),
                ("trace-followed", [self.followed], []), ("sweep", [self.sweep], []),
                ("map-sweep", [self.map_sweep], []), ("orbit-type-map", [self.orbit_type_map], []),
                ("model-orbit-type-map", [self.model_map], []),
                ("not-uniform-orbit-type-map", [self.not_uniform_map], []),
                ("branches-and-sweep", [self.branch, os.path.join(RESULTS, "paper-5.1-omega-down"), self.sweep], []),
                ("map-with-brute-force-and-curve", [self.orbit_type_map_51, self.curve], []),
                ("orbit-type-map-and-map-sweep", [self.orbit_type_map, self.map_sweep], []),
                ("sweep-section", [self.sweep], ["--y", "x2"])]


class Done:
    def __init__(self, returncode, stdout, stderr):
        self.returncode, self.stdout, self.stderr = returncode, stdout, stderr


def run(*arguments, env=None):
    """The script's command line: in this process (fast), or with `env` in a new one."""
    if env is not None:
        return subprocess.run(["/usr/bin/python3", SCRIPT, *arguments], capture_output=True, text=True, env=env)
    import contextlib
    import io
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = sp.main([SCRIPT, *arguments])
    plt.close("all")
    return Done(code, out.getvalue(), err.getvalue())


def run_process(*arguments):
    return subprocess.run(["/usr/bin/python3", SCRIPT, *arguments], capture_output=True, text=True)


class PlotKinds(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls._directory = tempfile.TemporaryDirectory()
        cls.work = cls._directory.name
        cls.small = Small(cls.work)

    @classmethod
    def tearDownClass(cls):
        cls._directory.cleanup()

    def test_every_kind_in_every_format(self):
        for name, inputs, options in self.small.kinds():
            for extension in (".png", ".pdf", ".svg"):
                output = os.path.join(self.work, f"{name}{extension}")
                done = run("--output", output, *options, *inputs)
                self.assertEqual(done.returncode, 0, f"{name}{extension}: {done.stderr}")
                with open(output, "rb") as f:
                    self.assertTrue(f.read(8).startswith(MAGIC[extension]), f"{name}{extension}")

    def test_size_and_dpi(self):
        import matplotlib.image as image
        output = os.path.join(self.work, "sized.png")
        done = run("--output", output, "--size", "4,3", "--dpi", "200", self.small.branch)
        self.assertEqual(done.returncode, 0, done.stderr)
        height, width = image.imread(output).shape[:2]
        self.assertEqual((width, height), (800, 600))

    def test_texts_do_not_overprint(self):
        for name, inputs, options in self.small.kinds():
            keywords = dict(zip((o[2:] for o in options[::2]), options[1::2]))
            for size in (None, (6.0, 4.0)):
                fig = sp.figure(inputs, size=size, **keywords)
                texts = sp.text_boxes(fig)
                labels = sp.label_boxes(fig)
                self.assertTrue(labels or name in ("sweep", "map-sweep", "sweep-section", "orbit-type-map-and-map-sweep",
                                                   "orbit-type-map"), f"{name}: labels placed")
                for k, a in enumerate(labels):
                    for b in labels[k + 1:]:
                        self.assertFalse(sp.overlap(a, b), f"{name} at {size}: labels {a} and {b} overprint")
                # Every text inside the figure (a title wider than the figure is wrapped).
                width, height = fig.canvas.get_width_height()
                for text, (x0, y0, x1, y1) in texts:
                    self.assertTrue(x0 >= -1 and y0 >= -1 and x1 <= width + 1 and y1 <= height + 1,
                                    f"{name} at {size}: '{text}' ({x0:.0f}, {y0:.0f}, {x1:.0f}, {y1:.0f}) leaves the "
                                    f"figure ({width} x {height})")
                # Each placed label against every other text of the figure (titles, axis and tick
                # labels, the legend's entries).
                others = [(text, box) for text, box in texts if box not in labels]
                for a in labels:
                    for text, b in others:
                        self.assertFalse(sp.overlap(a, b), f"{name} at {size}: a label {a} overprints '{text}' {b}")
                plt.close(fig)

    def test_axes_as_asked_and_titles_in_words(self):
        # The trace's resonance grows by a decade and more: still linear unless asked.
        fig = sp.figure([self.small.trace])
        ax = fig.axes[0]
        self.assertEqual((ax.get_xscale(), ax.get_yscale()), ("linear", "linear"))
        title = fig._suptitle.get_text()
        for word in INTERNAL_WORDS:
            self.assertNotIn(word, title)
        self.assertIn("no adjacent orbit type confirmed by simulation", title)
        plt.close(fig)
        fig = sp.figure([self.small.trace], yscale="log", xlim=(0.3, 0.8), ylim=(0.1, 100), y="peak-to-peak:x2",
                        title="My title")
        ax = fig.axes[0]
        self.assertEqual(ax.get_yscale(), "log")
        self.assertEqual(ax.get_xlim(), (0.3, 0.8))
        self.assertEqual(ax.get_ylim(), (0.1, 100))
        self.assertIn("peak-to-peak", ax.get_ylabel())
        self.assertEqual(fig._suptitle.get_text(), "My title")
        # omega1 = 0.7012 of chi = 0.3, eta = 4 inside the limits: a dotted line, labelled.
        omega1, omega2 = sp.natural_frequencies(0.3, 4.0)
        self.assertTrue(any(line.get_linestyle() == ":" and abs(line.get_xdata()[0] - omega1) < 1e-12
                            for line in ax.get_lines()))
        self.assertIn(r"$\omega_1$", [t.get_text() for t in ax.texts])
        plt.close(fig)
        fig = sp.figure([self.small.trace], natural_frequencies=False, xlim=(0.3, 0.8), title="")
        self.assertFalse(any(line.get_linestyle() == ":" for line in fig.axes[0].get_lines()))
        self.assertTrue(fig._suptitle is None or fig._suptitle.get_text() == "")
        plt.close(fig)
        for run_name in ("paper-5.1-omega-up", "paper-6-u_r-up", "paper-4.2-u_s-up"):
            fig = sp.figure([os.path.join(RESULTS, run_name)])
            for word in INTERNAL_WORDS:
                self.assertNotIn(word, fig._suptitle.get_text())
            plt.close(fig)

    def test_axis_labels_carry_a_models_units(self):
        # A [model]'s runs in SI (their summaries from before units could be declared say none), in
        # the units a copy's summaries declare, and the paper's scaled model without any.
        model_trace = os.path.join(RESULTS, "models", "five-mass-chain-omega-trace")
        fig = sp.figure([model_trace])
        self.assertEqual(fig.axes[0].get_xlabel(), r"forcing frequency $\omega$ (rad/s)")
        self.assertTrue(fig.axes[0].get_ylabel().endswith("over a period (m)"), fig.axes[0].get_ylabel())
        plt.close(fig)
        declared = os.path.join(self.work, "declared-units-trace")
        shutil.copytree(model_trace, declared)
        for branch in ("branch-1", "branch-2"):
            path = os.path.join(declared, branch, "summary.json")
            with open(path) as f:
                summary = json.load(f)
            summary["units"] = {"length": "mm", "time": "ms", "force": "kN"}
            with open(path, "w") as f:
                json.dump(summary, f, indent=2)
        fig = sp.figure([os.path.join(declared, "branch-1")], y="friction-work")
        self.assertEqual(fig.axes[0].get_xlabel(), r"forcing frequency $\omega$ (rad/ms)")
        self.assertEqual(fig.axes[0].get_ylabel(), "energy dissipated by friction per period (kN mm)")
        plt.close(fig)
        fig = sp.diagram(sp.load(os.path.join(declared, "branch-1")), y="equivalent-damping")[0]
        self.assertEqual(fig.axes[0].get_ylabel(), "equivalent viscous damping (kN ms/mm)")
        self.assertEqual(fig.axes[1].get_xlabel(), r"forcing frequency $\omega$ (rad/ms)")
        self.assertEqual(fig.axes[1].get_ylabel(), "segment durations (ms)")
        plt.close(fig)
        # Branches of one trace in two units: no unit is common, none is shown.
        fig = sp.figure([declared])
        self.assertEqual(fig.axes[0].get_xlabel(), r"forcing frequency $\omega$")
        plt.close(fig)
        fig = sp.figure([os.path.join(RESULTS, "atlases", "five-mass-chain-omega")])
        self.assertIn("(rad/s)", [ax.get_xlabel() for ax in fig.axes][-1])
        plt.close(fig)
        fig = sp.figure([self.small.trace, self.small.sweep])
        self.assertNotIn("(", fig.axes[0].get_xlabel() + fig.axes[0].get_ylabel())
        plt.close(fig)
        # Runs in different units overlaid: the axes name none, and a note says why.
        import contextlib
        import io
        err = io.StringIO()
        with contextlib.redirect_stderr(err):
            fig = sp.figure([model_trace, os.path.join(declared, "branch-1")])
        self.assertEqual(fig.axes[0].get_xlabel(), r"forcing frequency $\omega$")
        self.assertEqual(err.getvalue(), "note: the inputs are in different units (m, s, N; mm, ms, kN): the axes name none\n")
        plt.close(fig)
        # A sweep's CSV does not say its units: drawn with a [model]'s trace, it takes the trace's.
        fig = sp.figure([model_trace, os.path.join(RESULTS, "models", "five-mass-chain-omega-sweep.csv")])
        self.assertEqual(fig.axes[0].get_xlabel(), r"forcing frequency $\omega$ (rad/s)")
        plt.close(fig)

    def test_a_models_orbit_type_map(self):
        # Its curves.csv has the model's columns (no chi, eta); its curves' summaries give the units
        # (SI where they name the model but no units; none for the paper's scaled model).
        fig = sp.figure([self.small.model_map])
        ax = fig.axes[0]
        self.assertEqual(ax.get_xlabel(), r"forcing frequency $\omega$ (rad/ms)")
        self.assertEqual(ax.get_ylabel(), r"static friction force $F_s$ (kN)")
        # The slip's natural frequency from the trace's trace.json, as a [model]'s trace figure marks it.
        self.assertTrue(any(line.get_linestyle() == ":" and line.get_xdata()[0] == 1.0 for line in ax.get_lines()))
        self.assertIn(r"$\omega_1$", [t.get_text() for t in ax.texts])
        legend = [t.get_text() for t in ax.get_legend().get_texts()]
        self.assertIn("natural frequency of the slip (undamped)", legend)
        self.assertIn("the trace's start", legend)
        plt.close(fig)
        si = write_model_map(self.work, "model-map-si")
        self.assertEqual(sp.load(si).units(), sp.SI_UNITS)
        fig = sp.figure([si])
        self.assertEqual((fig.axes[0].get_xlabel(), fig.axes[0].get_ylabel()),
                         (r"forcing frequency $\omega$ (rad/s)", r"static friction force $F_s$ (N)"))
        plt.close(fig)
        self.assertIsNone(sp.load(self.small.orbit_type_map).units())
        # Its trace not found: drawn without the natural frequencies, without a word.
        lost = write_model_map(self.work, "model-map-without-trace", trace="no-such-trace")
        output = os.path.join(self.work, "model-map-without-trace.png")
        done = run("--output", output, lost)
        self.assertEqual((done.returncode, done.stderr), (0, ""))
        fig = sp.figure([lost])
        self.assertFalse(any(line.get_linestyle() == ":" for line in fig.axes[0].get_lines()))
        plt.close(fig)

    def test_a_region_not_uniform_is_hatched(self):
        # Region 2 (differing 3) hatched over its cells and nothing else: one patch with a hatch,
        # covering its three cells (0.1 x 0.1 each, from (0.8, 0.2)) and none of region 1's.
        not_uniform = "not uniform: a boundary is missing"

        def hatched_patches(fig):
            return [p for p in fig.axes[0].patches if p.get_hatch()]

        fig = sp.figure([self.small.not_uniform_map])
        hatched = hatched_patches(fig)
        self.assertEqual(len(hatched), 1)
        path = hatched[0].get_path().transformed(hatched[0].get_patch_transform())
        for x, y, inside in ((0.85, 0.45, True), (0.85, 0.55, True), (0.95, 0.55, True), (0.95, 0.45, False),
                             (1.05, 0.55, False), (0.85, 0.35, False), (1.15, 0.25, False)):
            self.assertEqual(path.contains_point((x, y)), inside, (x, y))
        # Its fill as before (the cells' colour under the hatch: the patch has no face).
        self.assertEqual(hatched[0].get_facecolor()[3], 0.0)
        legend = fig.axes[0].get_legend()
        texts = [t.get_text() for t in legend.get_texts()]
        self.assertEqual(texts.count(not_uniform), 1, texts)
        handles = getattr(legend, "legend_handles", None) or legend.legendHandles
        self.assertTrue(handles[texts.index(not_uniform)].get_hatch())
        plt.close(fig)
        # Drawn with a brute-force map beside it: the legend (beside the last panel) still names it.
        fig = sp.figure([self.small.orbit_type_map, self.small.map_sweep])
        regions = sp.load(self.small.orbit_type_map).regions["regions"]
        expected = sum(1 for r in regions if r.get("differing", 0) > 0)
        self.assertEqual(len(hatched_patches(fig)), expected)
        self.assertEqual([t.get_text() for t in fig.axes[-1].get_legend().get_texts()].count(not_uniform),
                         1 if expected else 0)
        plt.close(fig)
        # Maps without "differing" keys, and with every region's 0: drawn, nothing hatched, no entry.
        for path in (self.small.model_map, write_model_map(self.work, "uniform-map", differing=0)):
            fig = sp.figure([path])
            self.assertEqual(hatched_patches(fig), [])
            self.assertNotIn(not_uniform, [t.get_text() for t in fig.axes[0].get_legend().get_texts()])
            plt.close(fig)
        # Byte for byte the same figure: the same map (its name is in the title) with and without
        # the keys, all 0.
        pictures = []
        for directory, differing in (("without-keys", None), ("all-zero", 0)):
            path = write_model_map(os.path.join(self.work, directory), "map", differing=differing)
            output = os.path.join(self.work, directory, "map.png")
            done = run("--output", output, path)
            self.assertEqual((done.returncode, done.stderr), (0, ""))
            with open(output, "rb") as f:
                pictures.append(f.read())
        self.assertEqual(pictures[0], pictures[1])

    def test_natural_frequencies_solve_eq_56(self):
        import numpy
        for chi, eta in ((0.3, 4.0), (0.22, 4.2), (0.7, 1.1)):
            omega1, omega2 = sp.natural_frequencies(chi, eta)
            roots = sorted(numpy.sqrt(numpy.roots([1.0, -(1 + chi * eta), chi * eta * (1 - chi)]).real))
            self.assertAlmostEqual(omega1, roots[0], places=12)
            self.assertAlmostEqual(omega2, roots[1], places=12)

    def test_followed_branches_are_drawn(self):
        fig = sp.figure([self.small.followed])
        legend = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
        period_2 = sp.load(os.path.join(RESULTS, "paper-5.2-period-2")).signature
        self.assertIn(period_2, legend)
        plt.close(fig)

    def test_codimension_two_points_have_their_legend_entry(self):
        # A curve's LPPD and resonances R1 to R4 are bifurcations of the curve, never a "change of
        # orbit type" (the nonsmooth codes: SK, GR, T0, S0, NS).
        for code, entry in (("R1", "1:1 resonance (R1)"), ("R2", "1:2 resonance (R2)"), ("R3", "1:3 resonance (R3)"),
                            ("R4", "1:4 resonance (R4)"), ("LPPD", "fold-flip (LPPD)")):
            self.assertEqual(sp.legend_entry(code), entry)
        for code in ("SK", "GR", "T0", "S0", "NS"):
            self.assertEqual(sp.legend_entry(code), "change of orbit type", code)

        def legend_of(path):
            fig = sp.figure([path])
            texts = [t.get_text() for t in fig.axes[0].get_legend().get_texts()]
            plt.close(fig)
            return texts

        # The stored curves: section 5.1's fold curve passes an R1, section 5.2's flip curve an LPPD.
        legend = legend_of(self.small.curve)
        self.assertIn("1:1 resonance (R1)", legend)
        self.assertNotIn("change of orbit type", legend)
        self.assertIn("fold-flip (LPPD)", legend_of(os.path.join(RESULTS, "paper-5.2-pd-curve")))
        # The same curve with its R1 relabelled R3: the legend follows the code.
        relabelled = os.path.join(self.work, "fold-curve-r3")
        shutil.copytree(self.small.curve, relabelled, dirs_exist_ok=True)
        points = os.path.join(relabelled, "special-points.csv")
        with open(points) as f:
            text = f.read()
        self.assertIn(",R1,", text)
        with open(points, "w") as f:
            f.write(text.replace(",R1,", ",R3,").replace(",R12,", ",R32,"))
        legend = legend_of(relabelled)
        self.assertIn("1:3 resonance (R3)", legend)
        self.assertNotIn("1:1 resonance (R1)", legend)

    def test_invalid_options(self):
        output = os.path.join(self.work, "refused.png")
        branch, trace = self.small.branch, self.small.trace
        cases = [
            (["--dpi", "5"], "--dpi = '5' is invalid: valid 10 to 1200"),
            (["--dpi", "many"], "--dpi = 'many' is invalid: valid 10 to 1200"),
            (["--size", "40,30", "--dpi", "1000"], "--dpi = '1000' is invalid: valid at most 20000 pixels a side"),
            (["--size", "0,3"], "--size = '0,3' is invalid: valid WIDTH,HEIGHT in inches, each 1 to 40"),
            (["--size", "5"], "--size = '5' is invalid: valid WIDTH,HEIGHT"),
            (["--xscale", "logarithmic"], "--xscale = 'logarithmic' is invalid: valid linear or log"),
            (["--yscale", "LOG"], "--yscale = 'LOG' is invalid: valid linear or log"),
            (["--xlim", "0.6,0.5"], "--xlim = '0.6,0.5' is invalid: valid LOW,HIGH: two finite numbers, low < high"),
            (["--ylim", "nan,1"], "--ylim = 'nan,1' is invalid: valid LOW,HIGH"),
            (["--yscale", "log", "--ylim", "0,10"], "--ylim = '0,10' is invalid: valid LOW,HIGH: two finite numbers, "
                                                    "low < high and low > 0 on a log axis"),
            (["--y", "amplitude:x3"], "--y = 'amplitude:x3' is invalid: valid a numeric column of every input: "),
            (["--x", "signature"], "--x = 'signature' is invalid: valid a numeric column"),
            (["--legend", "top"], "--legend = 'top' is invalid: valid right, inside or none"),
            (["--colour", "red"], "option = '--colour' is invalid: valid one of --output"),
        ]
        for options, message in cases:
            done = run("--output", output, *options, branch)
            self.assertEqual(done.returncode, 2, f"{options}: exit {done.returncode}, {done.stderr}")
            self.assertEqual(done.stderr.count("\n"), 1, f"{options}: one line: {done.stderr!r}")
            self.assertTrue(done.stderr.startswith("error: " + message), f"{options}: {done.stderr!r}")
            self.assertFalse(os.path.exists(output), f"{options}: nothing written")
        for inputs, message in (([branch, self.small.orbit_type_map], "inputs = 'paper-5.1-omega-up' (branch) is invalid"),
                                ([self.small.orbit_type_map], None), ([os.path.join(self.work, "nothing.csv")], "input = '"),
                                ([os.path.join(RESULTS, "runs.md")], "input = '")):
            done = run("--output", output, "--y", "amplitude:x2", *inputs)
            if message is None:  # a map's axes are its parameters
                message = "--y = 'amplitude:x2' is invalid: valid u_r (a map's axes are its two parameters"
            self.assertEqual(done.returncode, 2, f"{inputs}: {done.stderr}")
            self.assertEqual(done.stderr.count("\n"), 1, done.stderr)
            self.assertIn(message, done.stderr)
            self.assertFalse(os.path.exists(output))
        # The script itself, as `stickslip plot` runs it: exit 2, one line, nothing written.
        done = run_process("--output", output, "--dpi", "0", branch)
        self.assertEqual((done.returncode, done.stderr), (2, "error: --dpi = '0' is invalid: valid 10 to 1200 dots "
                                                             "per inch (default 150)\n"))
        self.assertFalse(os.path.exists(output))
        for extension in (".jpg", ".png.txt", ""):
            done = run("--output", output + extension, trace)
            if extension == "":
                continue
            self.assertEqual(done.returncode, 2, done.stderr)
            self.assertIn("is invalid: valid a file name ending in .png, .pdf or .svg", done.stderr)
            self.assertFalse(os.path.exists(output + extension))

    def test_without_matplotlib_exit_3(self):
        fake = os.path.join(self.work, "fake", "matplotlib")
        os.makedirs(fake, exist_ok=True)
        with open(os.path.join(fake, "__init__.py"), "w") as f:
            f.write('raise ImportError("No module named matplotlib (test)")\n')
        output = os.path.join(self.work, "none.png")
        done = run("--output", output, self.small.trace, env=dict(os.environ, PYTHONPATH=os.path.join(self.work, "fake")))
        self.assertEqual(done.returncode, 3, done.stderr)
        self.assertFalse(os.path.exists(output))


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
