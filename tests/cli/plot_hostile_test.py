#!/usr/bin/python3
"""Hostile input to tools/stickslip_plot.py (what `stickslip plot` runs), each found drawing a
traceback, an empty figure or a file of the user's replaced before the fix:
- a title or a result name with '$' that is not valid mathtext (a run may be named 'a$\\b$');
- axis limits matplotlib widens silently (1,1+ulp) or overflows on (-1e308,1e308; a log axis over
  600 decades);
- a log axis where no value is positive (an empty figure, written without a word);
- a sweep's or map-sweep's CSV with nan, 1e309, a non-whole period or k, a short row, no cell;
- an existing file that stickslip did not write (thesis.pdf, an older figure) as --output: refused,
  untouched; a figure stickslip plot wrote is replaced;
- a full disk while the figure is written: the system's reason and the output's path;
every refusal exit 2, one line, nothing written; a drawing that fails exit 1, one line, no
traceback.

Usage: /usr/bin/python3 tests/cli/plot_hostile_test.py SOURCE_DIR (run by ctest)."""
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

SOURCE = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(SOURCE, "tools", "stickslip_plot.py")
RESULTS = os.path.join(SOURCE, "results")
RUN = os.path.join(RESULTS, "paper-5.1-omega-up")
SWEEP = os.path.join(RESULTS, "sweeps", "paper-4.1-omega.csv")
MAP = os.path.join(RESULTS, "maps", "paper-6-omega-u_r-brute-force.csv")
sys.path.insert(0, os.path.join(SOURCE, "tools"))


def run(*args):
    return subprocess.run(["/usr/bin/python3", SCRIPT, *args], capture_output=True, text=True, timeout=600)


class PlotHostile(unittest.TestCase):
    def setUp(self):
        self.work = tempfile.mkdtemp(prefix="stickslip-plot-hostile-")
        self.output = os.path.join(self.work, "figure.png")

    def tearDown(self):
        shutil.rmtree(self.work)

    def refused(self, message, *args, output=None):
        output = output or self.output
        done = run("--output", output, *args)
        self.assertEqual(done.returncode, 2, f"{args}: exit {done.returncode}: {done.stderr[-400:]}")
        self.assertEqual(done.stderr.count("\n"), 1, f"{args}: one line: {done.stderr!r}")
        self.assertTrue(done.stderr.startswith("error: "), done.stderr)
        self.assertIn(message, done.stderr)
        self.assertNotIn("Traceback", done.stderr)
        if output == self.output:
            self.assertFalse(os.path.exists(output), f"{args}: nothing written")
        self.assertEqual([f for f in os.listdir(os.path.dirname(output)) if ".tmp." in f], [], "no temporary left")

    def drawn(self, *args, output=None):
        output = output or self.output
        done = run("--output", output, *args)
        self.assertEqual(done.returncode, 0, f"{args}: {done.stderr[-400:]}")
        self.assertTrue(os.path.getsize(output) > 0)

    def csv_file(self, source, rows, name="damaged.csv"):
        with open(source) as f:
            header = f.readline()
        path = os.path.join(self.work, name)
        with open(path, "w") as f:
            f.write(header + "".join(r + "\n" for r in rows))
        return path

    def test_mathtext(self):
        self.refused("--title = '$\\foo$' is invalid: valid a text whose $...$ parts are valid mathtext",
                     "--title", "$\\foo$", "--", RUN)
        named = os.path.join(self.work, "a$\\b$c")
        shutil.copytree(RUN, named)
        self.drawn("--", named)
        os.remove(self.output)
        self.drawn("--", named, RUN)

    def test_limits(self):
        for option, value in (("--xlim", "1,1.0000000000000002"), ("--xlim", "-1e308,1e308"), ("--xlim", "1e300,1e301"),
                              ("--xlim", "0.55,inf"), ("--xlim", "1,1")):
            self.refused(f"{option} = '{value}' is invalid: valid LOW,HIGH: two finite numbers, low < high", option, value,
                         "--", RUN)
        self.refused("--ylim = '1e-300,1e300' is invalid", "--yscale", "log", "--ylim", "1e-300,1e300", "--", RUN)
        self.drawn("--xlim", "-1e300,1e300", "--", RUN)

    def test_pixels(self):
        # 40 x 40 inches at 500 dpi passed the 20000-a-side rule and took 3.3 GB to rasterize; the
        # default size of a map at 1200 dpi is checked too (18600 x 6720 pixels).
        self.refused("--dpi = '500' is invalid: valid at most 20000 pixels a side and 60 million pixels: dpi <= 193",
                     "--size", "40,40", "--dpi", "500", "--", RUN)
        self.refused("--dpi = '1200' is invalid: valid at most 20000 pixels a side and 60 million pixels",
                     "--dpi", "1200", "--", MAP)
        self.drawn("--size", "3.5,2.5", "--dpi", "1200", "--", RUN)

    def test_log_axis_without_positive_values(self):
        # x10 < 0 all along the 5.1 branch: a log axis would draw nothing.
        self.refused("--yscale = 'log' is invalid: valid linear, or log where some value of x10 is > 0",
                     "--y", "x10", "--yscale", "log", "--", RUN)

    def test_damaged_sweep(self):
        good = "0,up,0,0.55,0.3925,0,1.5,3.1,0.1,0,2,2,1,3.1"
        for row, message in ((good.replace("0.55", "nan"), "column 'omega' = 'nan'"),
                             (good.replace("0.55", "1e309"), "column 'omega' = '1e309'"),
                             (good.replace(",2,2,1,", ",2,2,x,"), "column 'period' = 'x'"),
                             (good.replace("0.3925,0,", "0.3925,1.5,"), "column 'k' = '1.5'"),
                             (good.rsplit(",", 1)[0], "line 2 is invalid: valid a row of 14 fields"),
                             (good.replace(",2,2,1,", ",-2,2,1,"), "column 'stops_per_period' = '-2'")):
            self.refused(message, "--", self.csv_file(SWEEP, [row]))
        self.drawn("--", self.csv_file(SWEEP, [good]))

    def test_damaged_map_sweep(self):
        good = "0,0,1,1,0.54,1.2,3,c0,1,0,periodic,1,0,0,1,,0,0,0,0,0"
        for row, message in ((good.replace("0.54", "nan"), "column 'omega' = 'nan'"),
                             (good.replace("periodic,1,", "periodic,x,"), "column 'period' = 'x'"),
                             (good.replace("0.54,1.2", "-5,1.2"), "column 'omega' = '-5'"),
                             (good[:-len(",0,0,0,0,0")] + ",1,0,0,0,0", "a map-sweep file with at least one cell")):
            self.refused(message, "--", self.csv_file(MAP, [row]))
        self.drawn("--", self.csv_file(MAP, [good]))

    def test_files_not_written_by_stickslip_are_kept(self):
        for name, content in (("thesis.pdf", b"%PDF-1.4 my thesis\n"), ("photo.png", b"\x89PNG\r\n\x1a\nmine"),
                              ("drawing.svg", b"<?xml version='1.0'?><svg/>")):
            path = os.path.join(self.work, name)
            with open(path, "wb") as f:
                f.write(content)
            self.refused(f"--output = '{path}' is invalid: valid a new file or a figure stickslip plot wrote", "--", RUN,
                         output=path)
            with open(path, "rb") as f:
                self.assertEqual(f.read(), content, f"{name} untouched")
        # A figure stickslip plot wrote is replaced, in every format.
        for extension in (".png", ".pdf", ".svg"):
            path = os.path.join(self.work, "again" + extension)
            self.drawn("--", RUN, output=path)
            self.drawn("--title", "again", "--", RUN, output=path)
        import stickslip_plot as sp
        with self.assertRaises(sp.BadInput):
            sp.check_replaceable(os.path.join(self.work, "thesis.pdf"))
        sp.check_replaceable(os.path.join(self.work, "thesis.pdf"), force=True)
        # A missing directory is bad input before the drawing (stickslip.plot(output=) raised
        # FileNotFoundError naming its temporary file after drawing).
        with self.assertRaisesRegex(sp.BadInput, "a file in an existing directory"):
            sp.check_replaceable(os.path.join(self.work, "missing", "figure.png"), force=True)

    def main_with_stderr(self, sp):
        """The plotting module's main on RUN to self.output: its exit status and what it wrote to stderr."""
        stderr = tempfile.TemporaryFile(mode="w+")
        saved, sys.stderr = sys.stderr, stderr
        try:
            status = sp.main(["stickslip_plot.py", "--output", self.output, "--", RUN])
        finally:
            sys.stderr = saved
        stderr.seek(0)
        return status, stderr.read()

    def test_failed_drawing_is_one_line(self):
        # Whatever matplotlib raises while drawing or writing: exit 1, one line, no traceback.
        import stickslip_plot as sp
        original = sp.save

        def failing(*args, **keywords):
            raise OverflowError("cannot convert float infinity to integer")
        sp.save = failing
        try:
            status, text = self.main_with_stderr(sp)
        finally:
            sp.save = original
        self.assertEqual(status, 1)
        self.assertEqual(text.count("\n"), 1, text)
        self.assertIn("OverflowError", text)
        self.assertFalse(os.path.exists(self.output))


    def test_a_full_disk_is_one_line_naming_the_output(self):
        # ENOSPC while the figure is written, as on a full disk (before the fix: exit 1, the reason
        # without a path, and a second line from stickslip plot): exit 2, one line with the system's
        # reason and the user's path, not the temporary one; nothing written, nothing left.
        import errno
        import matplotlib.figure
        import stickslip_plot as sp
        original = matplotlib.figure.Figure.savefig

        def full(fig, name, **keywords):
            with open(name, "wb") as f:
                f.write(b"half a figure")
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), name)
        matplotlib.figure.Figure.savefig = full
        try:
            status, text = self.main_with_stderr(sp)
        finally:
            matplotlib.figure.Figure.savefig = original
        self.assertEqual(status, 2)
        self.assertEqual(text, f"error: cannot write '{self.output}': No space left on device\n")
        self.assertEqual(os.listdir(self.work), [])


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
