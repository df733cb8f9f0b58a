"""An atlas: every periodic motion over a range of one parameter (stickslip.atlas), as its result
files hold it: the counts, every brute-force attractor with its fate, the traces (each a Trace),
the intervals of every branch (atlas-intervals.csv)."""
import csv as _csv
import io as _io
import json as _json
import os as _os

from . import _stickslip as _core
from ._inputs import _checked
from ._trace import Trace

_FILES = ("atlas.json", "atlas-intervals.csv", "brute-force.csv")


class Atlas:
    """An atlas as its result files hold it (`stickslip atlas`).

    atlas.counts        attractors, fates (how many on-branch, no-orbit-type, not-settled,
                        above-period-limit, incomplete, not-solved, off-branch), periodic_within_limit,
                        on_branches, unexplained, traces, branches, orbit_types
    atlas.attractors    one dict per brute-force attractor, with the grid value (value): status,
                        period, signature (the brute force's), starts, find (FindOrbit's status),
                        exact_signature, amplitude_x1, amplitude_x2, fate, branch
                        ("trace-<t>/branch-<k>"), point, started_trace, reason; a [model]'s
                        (atlas(model=...)) stops_per_period and sticks_per_period instead of the
                        signature, and amplitude:<coordinate> for each of its coordinates
    atlas.traces        the traces, each a Trace (trace-1, trace-2, ...)
    atlas.intervals     atlas-intervals.csv's rows as dicts (trace, branch, signature, from, to,
                        stable, admissible, first_label, last_label, branch_end)
    atlas.save(directory) / Atlas.load(directory): the files of `stickslip atlas`, the same bytes.
    atlas.plot(**options): its frequency response and coexistence strip (a matplotlib Figure).
    """

    def __init__(self, stored):
        self._stored = stored
        self._files = stored.files()
        self.json = _json.loads(self._files["atlas.json"])
        self.parameter = self.json["parameter"]
        self.counts = self.json["counts"]
        self.attractors = [dict(a, value=g["value"]) for g in self.json["grid"] for a in g["attractors"]]
        self.traces = [Trace(t) for t in stored.traces]
        self.intervals = list(_csv.DictReader(_io.StringIO(self._files["atlas-intervals.csv"])))

    @classmethod
    def load(cls, directory):
        """The atlas stored in `directory` (atlas.json, atlas-intervals.csv, brute-force.csv,
        trace-<t>/)."""
        directory = _checked(directory, "directory", "path")
        texts = []
        for name in _FILES:
            with open(_os.path.join(directory, name), newline="") as f:
                texts.append(f.read())
        traces = [_core._StoredTrace.load(_os.path.join(directory, t["name"])) for t in _json.loads(texts[0])["traces"]]
        return cls(_core._StoredAtlas(_os.path.basename(_os.path.normpath(directory)), traces, *texts))

    def save(self, directory):
        """Writes the atlas's files into `directory`, replaced as a whole; other files in it, at any
        depth, are kept and their names returned. A directory that holds neither a stickslip atlas nor
        a run raises ValueError, and nothing is touched."""
        return self._stored.save(_checked(directory, "directory", "path"))

    def files(self):
        """{file name: text} of atlas.json, atlas-intervals.csv and brute-force.csv (each trace's:
        trace.files())."""
        return dict(self._files)

    def plot(self, **options):
        """The atlas's frequency response as a matplotlib Figure, as `stickslip plot` draws it: every
        branch of every trace coloured by orbit type, the attractors' exact orbits as crosses, the
        natural frequencies, and below a strip of the stable motions that coexist at each grid value.
        Keywords: Branch.plot's (yscale="log" suits a resonance)."""
        import tempfile
        from . import plotting
        with tempfile.TemporaryDirectory() as work:
            directory = _os.path.join(work, self.json["output"] or "atlas")
            self.save(directory)
            return plotting.figure([plotting.load(directory)], **options)

    def __len__(self):
        return len(self.attractors)

    def __repr__(self):
        c = self.counts
        return (f"<stickslip.Atlas over {self.parameter} {self.json['range']}: {c['attractors']} attractors, "
                f"{c['on_branches']} on {c['branches']} branches of {len(c['orbit_types'])} orbit types>")
