"""A trace: the chain of orbit branches through the changes of orbit type, both ways from one
start (stickslip.trace), as its result files hold it: every branch a Branch, trace.csv's columns as
NumPy arrays, how each branch began and ended and how each direction ended (trace.json)."""

from . import _stickslip as _core
from ._branch import Branch, _read_table, _Table


class Trace(_Table):
    """A trace as its result files hold it (`stickslip trace`, a run file with [trace]).

    trace.branches      the branches in file order (branch-1, branch-2, ...: the down chain first,
                        then the up chain, each in chain order), each a Branch whose `link` is how
                        it began and ended: {name, chain, direction, signature, points, start
                        (trace-start, switch, followed-past, admissible-again), margin, switch
                        (the confirmed switch: status, bifurcation, edit, adjacent, persists,
                        from_past; or None), end, message}
    trace.directions    {"down": {end, message, branches (their 1-based k)}, "up": {...}}
    trace.ends          {"down": end, "up": end}: parameter-bound, loop, resonance, not-confirmed,
                        no-adjacent-type, family-end, continuation-failed, max-points, max-branches
    trace.special_points  every branch's special points, each dict with its "branch" name
    trace["omega"], trace["signature"], trace["branch"], ...: the columns of trace.csv (one row per
                        point of every branch) as NumPy arrays; trace.columns lists them
    trace.save(directory) / Trace.load(directory): the files of `stickslip trace`, the same bytes
                        (trace.csv, trace.json, branch-<k>/).
    """

    def __init__(self, stored):
        self._stored = stored
        trace_csv, trace_json = stored.files()
        self._files = {"trace.csv": trace_csv, "trace.json": trace_json}
        self._table = _read_table(trace_csv, ("signature", "label"), ("branch", "pt", "stable", "admissible"))
        self.summary = stored.summary
        self.branches = [Branch(run, link) for run, link in zip(stored.runs, stored.branches)]
        self.directions = stored.directions
        self.special_points = [dict(s, branch=b.link["name"]) for b in self.branches for s in b.special_points]

    @classmethod
    def load(cls, directory):
        """The trace stored in `directory` (trace.json, trace.csv, branch-<k>/)."""
        return cls(_core._StoredTrace.load(str(directory)))

    def save(self, directory):
        """Writes the trace's files into `directory`, whose name becomes the trace's output name. The
        directory is replaced as a whole; other files in it are kept and their names returned. A
        directory that holds neither a stickslip trace nor a run raises ValueError, and nothing is
        touched."""
        return self._stored.save(str(directory))

    def files(self):
        """{file name: text} of trace.csv and trace.json (each branch's: branch.files())."""
        return dict(self._files)

    @property
    def ends(self):
        return {direction: d["end"] for direction, d in self.directions.items()}

    def __len__(self):
        return len(self.branches)

    def __iter__(self):
        return iter(self.branches)

    def __repr__(self):
        return (f"<stickslip.Trace '{self.signature}' in {self.parameter}: {len(self)} branches; "
                f"down {self.ends.get('down')}, up {self.ends.get('up')}>")
