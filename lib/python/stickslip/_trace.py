"""A trace: the chain of orbit branches through the changes of orbit type, both ways from one
start (stickslip.trace), as its result files hold it: every branch a Branch, trace.csv's columns as
NumPy arrays, how each branch began and ended and how each direction ended (trace.json)."""

from . import _stickslip as _core
from ._branch import Branch, _read_table, _Table
from ._inputs import _checked


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
        return cls(_core._StoredTrace.load(_checked(directory, "directory", "path")))

    def save(self, directory):
        """Writes the trace's files into `directory`, whose name becomes the trace's output name. The
        directory is replaced as a whole; other files in it are kept and their names returned. A
        directory that holds neither a stickslip trace nor a run raises ValueError, and nothing is
        touched."""
        return self._stored.save(_checked(directory, "directory", "path"))

    def files(self):
        """{file name: text} of trace.csv and trace.json (each branch's: branch.files())."""
        return dict(self._files)

    def plot(self, **options):
        """The trace's frequency response as a matplotlib Figure, as `stickslip plot` draws it:
        every branch (and every branch followed at a bifurcation), each orbit type in its own
        colour, switches and special points marked and labelled, omega1 and omega2 marked where x
        is omega. Keywords: Branch.plot's. fig.savefig("trace.svg") writes it."""
        from . import plotting
        return plotting.figure([self._plotting_result()], **options)

    def _plotting_result(self):
        import tempfile
        from . import plotting
        # Through the files the command line writes (trace.json, every branch, the branches followed
        # at bifurcations), read by the one reader of the figures.
        with tempfile.TemporaryDirectory() as work:
            directory = f"{work}/{self.output}"
            self.save(directory)
            return plotting.load(directory)

    def to_pandas(self):
        """Every point of every branch as a pandas DataFrame, one row per point: the branch's name
        (branch), its orbit type (signature) and every column of its branch.csv, measures included
        (amplitude:x1, amplitude:x2, peak-to-peak:x2, stick-fraction, stops, sticks, friction-work,
        equivalent-damping), margins, multipliers; a column that a branch lacks, such as a duration
        it has not, is NaN there).
        Needs pandas (python3-pandas)."""
        try:
            import pandas
        except ImportError as e:
            raise ImportError("Trace.to_pandas needs pandas (Debian: python3-pandas)") from e
        frames = []
        for branch in self.branches:
            frame = pandas.DataFrame(branch._table)
            frame.insert(0, "signature", branch.signature)
            frame.insert(0, "branch", branch.link["name"] if branch.link else "")
            frames.append(frame)
        return pandas.concat(frames, ignore_index=True, sort=False)

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
