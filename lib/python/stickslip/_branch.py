"""Branches of periodic orbits: the Branch a continuation returns (its columns read from the
library's one writer of result files, so they are the files' numbers) and the Continuation
stepped by hand."""

import csv as _csv
import io as _io

import numpy as _np

from . import _stickslip as _core
from ._inputs import _checked, _one_off_run, _pair, _steps

_TEXT_COLUMNS = ("label", "type", "test_function")
_INTEGER_COLUMNS = ("pt", "stable", "admissible", "stops", "sticks", "newton_iterations", "located")


def _read_table(text, text_columns=_TEXT_COLUMNS, integer_columns=_INTEGER_COLUMNS):
    """A result file's CSV text as {column: array}: numbers as float (int for counts and flags),
    the text columns as str arrays."""
    rows = list(_csv.reader(_io.StringIO(text)))
    header, body = rows[0], rows[1:]
    table = {}
    for k, name in enumerate(header):
        values = [row[k] for row in body]
        if name in text_columns:
            table[name] = _np.array(values, dtype=str)
        elif name in integer_columns:
            table[name] = _np.array([int(v) for v in values], dtype=int)
        else:
            table[name] = _np.array([float(v) for v in values], dtype=float)
    return table


class _Table:
    """What a branch and a trace share: their CSV table's columns as arrays by name (self._table) and
    the names of summary.json or trace.json (self.summary)."""

    @property
    def columns(self):
        return list(self._table)

    def __getitem__(self, column):
        if column not in self._table:
            raise KeyError(f"{column!r}: valid columns {', '.join(self._table)}")
        return self._table[column]

    def __contains__(self, column):
        return column in self._table

    def keys(self):
        return self._table.keys()

    @property
    def output(self):
        return self.summary["output"]

    @property
    def parameter(self):
        return self.summary["parameter"]

    @property
    def signature(self):
        """The orbit type (of a trace: its start's)."""
        return self.summary["signature"]


class Branch(_Table):
    """A branch of periodic orbits as its result files hold it.

    branch["omega"], branch["margin:G:3"], branch["stable"]: the columns of branch.csv as NumPy
    arrays (branch.columns lists them); branch.special_points: one dict per row of
    special-points.csv (type, test_function, located, label and every column);
    branch.to_pandas(): a pandas DataFrame (pandas is optional);
    branch.save(directory) / Branch.load(directory): the three files, written and read by the
    library's one writer and reader, the same bytes as the command line's for the same run.
    """

    def __init__(self, run, link=None):
        # A branch computed in this process also keeps the engine's special points and setup, from
        # which switch() starts; a loaded one (or a trace's) holds its files only.
        self._computed = run if isinstance(run, _core._ComputedRun) else None
        stored = run.stored if self._computed is not None else run
        self._stored = stored
        #: In a trace: how the branch began and ended ({name, chain, direction, signature, points,
        #: start, margin, switch, end, message}, as trace.json has it); None otherwise.
        self.link = link
        branch_csv, special_csv, summary = stored.files()
        self._files = {"branch.csv": branch_csv, "special-points.csv": special_csv, "summary.json": summary}
        self._table = _read_table(branch_csv)
        special = _read_table(special_csv)
        count = len(next(iter(special.values()))) if special else 0
        self.special_points = [{name: column[i].item() for name, column in special.items()} for i in range(count)]
        self.summary = stored.summary

    @classmethod
    def load(cls, directory):
        """The run stored in `directory` (branch.csv, special-points.csv, summary.json)."""
        return cls(_core._StoredRun.load(_checked(directory, "directory", "path")))

    def save(self, directory):
        """Writes the run's three files into `directory`, whose name becomes the run's output name
        (results/<name>/, as `--output name` would). The directory is replaced as a whole; other
        files in it are kept and their names returned. A directory that does not hold a stickslip
        run raises ValueError, and nothing is touched."""
        return self._stored.save(_checked(directory, "directory", "path"))

    def files(self):
        """{file name: text} of the three result files."""
        return dict(self._files)

    def __len__(self):
        return len(self._table["pt"])

    def sample(self, point, n=200):
        """(t, x) over one period of the orbit at branch point `point` (0-based, negative from the
        end): n >= 2 equally spaced times and the state (x1, x2, x1', x2') at each."""
        return self._stored.sample(_checked(point, "point", "index"), _checked(n, "n", "index"))

    def special_point(self, label):
        """The special point labelled `label` ("LP4")."""
        for s in self.special_points:
            if s["label"] == label:
                return s
        raise KeyError(f"{label!r}: valid labels {', '.join(s['label'] for s in self.special_points)}")

    @property
    def termination(self):
        return self.summary["termination"]

    @property
    def message(self):
        return self.summary["message"]

    def switch(self, label, side=1, *, range=None, output=None, ds=None, ds_min=None, ds_max=None, max_points=None):
        """Continues the branch that leaves the special point `label` of this branch (AUTO's ISW = -1):
        at a "PD" the period-2 orbits (the type unfolded over two periods), at an "SB" the orbits
        without the symmetry, at a "BP" the second branch through the point, of the same type. It
        starts from the point and the tangent the continuation computed (a BP needs that tangent,
        which result files do not keep: for a loaded branch use continue_orbit(point="RUN:LABEL",
        switch_branch=True) at a PD or an SB).

        side        +1 or -1: the two halves of the new branch (at a PD the same orbits shifted by
                    one period, at an SB mirror images; at a BP the two ways along it)
        range, ds, ds_min, ds_max, max_points, output: as continue_orbit's; left out, this branch's.
        Returns a Branch; raises ValueError for a label that is not a BP, PD or SB of this branch
        and where the new branch's first point (ds along it from the label) lies outside `range`,
        ConvergenceError if the new branch does not start.
        """
        if self._computed is None:
            raise ValueError(f"switch = {label!r} is invalid: valid on a branch computed in this process "
                             "(a loaded branch: continue_orbit(point='RUN:LABEL', switch_branch=True) at a PD or an SB)")
        options = _steps(ds, ds_min, ds_max, max_points)
        options["output"] = None if output is None else _checked(output, "output", "text")
        options["range"] = None if range is None else _pair(range, "range")
        if _checked(side, "side", "index", "+1 or -1") not in (1, -1):
            raise ValueError(f"side = {side!r} is invalid: valid range +1 or -1")
        return Branch(self._computed.switch(_checked(label, "label", "text"), int(side), options))

    def plot(self, **options):
        """The branch as a matplotlib Figure, as `stickslip plot` draws it: y over x (default
        amplitude:x2, max |x2| over a period, over the continued parameter; a curve in two
        parameters: its second parameter), stable solid, unstable dashed, special points labelled.
        Keywords: x, y, xscale, yscale ("linear", the default, or "log"), xlim, ylim, size
        (inches), title, legend, natural_frequencies (stickslip.plotting's options); bad ones
        raise ValueError. fig.savefig("branch.pdf") writes it."""
        from . import plotting
        return plotting.figure([self._plotting_result()], **options)

    def _plotting_result(self):
        from . import plotting
        return plotting.Branch.from_texts(self.output, self._files["branch.csv"], self._files["special-points.csv"],
                                          self._files["summary.json"])

    def to_pandas(self):
        """The branch as a pandas DataFrame, one row per point (needs pandas: python3-pandas)."""
        try:
            import pandas
        except ImportError as e:
            raise ImportError("Branch.to_pandas needs pandas (Debian: python3-pandas)") from e
        return pandas.DataFrame(self._table)

    def __repr__(self):
        types = " ".join(s["label"] for s in self.special_points)
        return (f"<stickslip.Branch '{self.signature}' in {self.parameter}: {len(self)} points, "
                f"{self.termination}; {types}>")


class Continuation:
    """A continuation stepped by hand, as the engine's Continuation::Step:

        cont = stickslip.Continuation("omega", (0.3, 0.9), preset="paper-5.1")
        cont.step()                # the corrected start; then one accepted point per step
        for point in cont:         # every new point (special points located on the way included)
            if point["omega"] > 0.58: break
        cont.point(-1), len(cont), cont.ended, cont.branch()   # inspect, then go on
        branch = cont.run()        # step to the end

    Takes continue_orbit()'s arguments, or Continuation.from_run_file(path). Each point is a dict
    of the branch.csv columns. A start that does not converge raises ConvergenceError.
    """

    def __init__(self, parameter, range, **keywords):
        self._stepper = _core._Stepper(_one_off_run(parameter, range, **keywords))
        self._yielded = 0

    @classmethod
    def from_run_file(cls, path, results="results"):
        """The continuation a run file describes, to be stepped."""
        self = cls.__new__(cls)
        self._stepper = _core._Stepper(_core._run_file(_checked(path, "path", "path"), _checked(results, "results", "path")))
        self._yielded = 0
        return self

    def step(self):
        """Computes the next accepted point (the corrected start on the first call), with every
        special point located on the way; False once the branch has ended."""
        return self._stepper.step()

    def __iter__(self):
        while True:
            while self._yielded < len(self._stepper):
                self._yielded += 1
                yield self._stepper.point(self._yielded - 1)
            if self._stepper.ended or not self._stepper.step():
                while self._yielded < len(self._stepper):
                    self._yielded += 1
                    yield self._stepper.point(self._yielded - 1)
                return

    def __len__(self):
        return len(self._stepper)

    def point(self, index):
        """Point `index` (negative from the end) as {column: value}."""
        return self._stepper.point(index)

    @property
    def ended(self):
        return self._stepper.ended

    @property
    def end(self):
        """Why the branch ended ("terminal-event", "parameter-bound", ...), or "running"."""
        return self._stepper.end

    @property
    def end_message(self):
        return self._stepper.end_message

    def branch(self):
        """The branch so far (or the whole branch once ended) as a Branch."""
        return Branch(self._stepper.stored())

    def run(self):
        """Steps to the end and returns the Branch."""
        while self._stepper.step():
            pass
        return self.branch()
