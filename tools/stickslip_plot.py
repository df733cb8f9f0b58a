#!/usr/bin/python3
"""stickslip's figures: one module that draws every kind of result, used by `stickslip plot`, by
the Python package (stickslip.plotting: Branch.plot(), Trace.plot(), SweepResult.plot(),
MapSweepResult.plot()) and by the figure scripts of tools/ (plot_figures.py, ...).

Results it reads (by the files the command line writes):
  branch            a run's directory (summary.json, branch.csv, special-points.csv)
  curve             a run continued in two parameters (a type boundary, a fold or torus curve): a
                    branch along which a second parameter varies
  trace             a trace's directory (trace.json, trace.csv, branch-<k>/, and the branches
                    followed at bifurcations, <branch>-<label>/)
  sweep             a brute-force sweep's CSV (stickslip sweep --output)
  map-sweep         a brute-force map's CSV (stickslip map-sweep --output)
  orbit-type map    an orbit-type map's directory (stickslip map: regions.json, curves.csv)
  atlas             an atlas's directory (stickslip atlas: atlas.json, trace-<t>/): its frequency
                    response, every branch of every trace coloured by orbit type, the exact orbits
                    of the brute force's attractors overlaid, and below it a strip of the stable
                    motions that coexist at each grid value

Several results are drawn on one set of axes (an overlay): branches, curves, traces and sweeps
over the same x quantity; an orbit-type map and/or a brute-force map with two-parameter curves
over the maps' plane.

Options (the same names on the command line and, with underscores, as keywords):
  x, y        the quantities on the axes: any numeric column of the inputs (the parameter, x20,
              amplitude:x1, amplitude:x2, peak-to-peak:x2, stick-fraction, d1, a margin, ...).
              Default x: the continued (swept) parameter; y: amplitude:x2 (max |x2| over a
              period); for two-parameter curves only, the second parameter. A map's axes are its
              two parameters.
  xscale, yscale  "linear" (the default) or "log"; never switched automatically. On a log axis
              values <= 0 are not drawn.
  xlim, ylim  (low, high), low < high, finite (> 0 on a log axis); default: the data's range.
  size        (width, height) in inches, each 1 to 40; default by kind (DEFAULT_SIZES).
  dpi         10 to 1200 (default 150), at most 20000 pixels a side; PNG only (PDF and SVG are
              vector, their text and lines independent of it).
  title       the title; default a sentence saying what is drawn and how each branch ended;
              "" for none.
  legend      "right" (beside the axes, the default), "inside" (where it covers least) or "none".
  natural_frequencies  mark omega1 and omega2 where x (or a map's axis) is omega (default on):
              a dotted line inside the axes, else a legend line giving their values. The paper's
              from its chi and eta (eq. 56); a [model]'s as its trace (trace.json) lists them.

Command line (what `stickslip plot` runs; it checks the inputs' names and the output file first):
  /usr/bin/python3 stickslip_plot.py --output FILE.{png,pdf,svg} [--x COL] [--y COL]
      [--xscale linear|log] [--yscale linear|log] [--xlim LO,HI] [--ylim LO,HI] [--size W,H]
      [--dpi N] [--title TEXT] [--legend right|inside|none] [--no-natural-frequencies] [--force] INPUT...
An existing output file is replaced only if it is a figure stickslip plot wrote (MARKER in its
metadata), or with --force; any other is bad input.
Exit codes: 0 written; 2 bad input (one line: the option, its value and the valid range; nothing
written); 3 matplotlib cannot be imported; 1 the drawing failed (nothing written).
"""
import csv
import io
import json
import math
import os
import sys

# A field as long as the files may hold (the command line's readers bound the numbers, not their
# text's length): the csv module's default limit would fail on a valid file with a traceback.
csv.field_size_limit(2**31 - 1)

PARAMETERS = ("chi", "eta", "omega", "u_s", "u_r")
FORMATS = (".png", ".pdf", ".svg")
DEFAULT_DPI = 150
SIZE_RANGE = (1.0, 40.0)
DPI_RANGE = (10, 1200)
MAX_PIXELS = 20000
# At most this many pixels in a PNG: rasterizing takes about 8 bytes a pixel (20000 x 20000 took
# 3.3 GB), so 60 million pixels stay near half a gigabyte; 7 x 4 inches at 1200 dpi is 40 million.
MAX_AREA = 60_000_000
# Axis limits: magnitudes (and a log axis's decades) matplotlib's ticks survive, and the smallest
# relative range it does not widen.
LIMIT_RANGE = (1e-300, 1e300)
LIMIT_RESOLUTION = 1e-12
# Inches (width, height) by what is drawn: the legend stands beside the axes.
DEFAULT_SIZES = {"response": (9.0, 5.0), "map-sweep": (11.0, 4.6), "orbit-type-map": (9.4, 5.6),
                 "orbit-type-map+map-sweep": (15.5, 5.6), "diagram": (11.5, 6.0),
                 "atlas": (10.0, 6.6)}
INADMISSIBLE = dict(color="0.65", lw=0.9)
# One colour per orbit type, in the order met (red is kept for the markers).
COLOURS = ["C0", "C2", "C1", "C4", "C9", "C5", "C6", "C8", "C7",
           "#aec7e8", "#98df8a", "#ffbb78", "#c5b0d5", "#9edae5", "#c49c94", "#f7b6d2", "#dbdb8d", "black"]
# Marker and colour by kind of special point: smooth bifurcations, the codimension-two points of
# a curve in two parameters, user values, ends, and the nonsmooth orbit-type changes (SK, GR, T0,
# S0, NS, ...: every other code; NS is x2' touching zero in a slip, lib/README.md, not a torus).
MARKERS = {"LP": ("s", "red"), "BP": ("^", "red"), "SB": ("^", "red"), "PD": ("v", "red"), "TR": ("D", "red"),
           "LPPD": ("X", "purple"), "R1": ("P", "purple"), "R2": ("P", "purple"), "R3": ("P", "purple"),
           "R4": ("P", "purple"), "UZ": ("o", "C0"), "EP": ("o", "black")}
TYPE_CHANGE_MARKER = ("o", "darkorange")
SWITCH_MARKER = ("*", "gold")
# Legend entry by code. On a fold, flip or torus curve (lib/src/branches/floquet_condition.cpp, AUTO's
# names): LPPD a fold-flip, R1 to R4 the strong resonances 1:1 to 1:4 (a multiplier pair at
# exp(±2πi/k)): bifurcations of the curve, not changes of orbit type.
SMOOTH = {"LP": "fold (LP)", "TR": "torus (TR)", "PD": "period doubling (PD)", "SB": "symmetry breaking (SB)",
          "BP": "branch point (BP)", "UZ": "user value (UZ)", "EP": "end of the family (EP)",
          "LPPD": "fold-flip (LPPD)", "R1": "1:1 resonance (R1)", "R2": "1:2 resonance (R2)",
          "R3": "1:3 resonance (R3)", "R4": "1:4 resonance (R4)"}


def legend_entry(code):
    """The legend's name for a special point of type `code` ("R1" -> "1:1 resonance (R1)"); every
    code not listed in SMOOTH is a change of orbit type (SK, GR, T0, S0, NS, ...)."""
    return SMOOTH.get(code, "change of orbit type")
# Special points not drawn: a branch's start (the previous branch's end, drawn there) and the
# range's bounds (the axis ends).
SKIPPED_TESTS = ("start", "lambda_min", "lambda_max")
# The brute force's points by the period found on the section: 1, 2, more, none.
SWEEP_STYLES = {1: ("o", "0.35", 2.5, "period 1"), 2: ("s", "C3", 2.5, "period 2"),
                3: ("D", "C5", 2.5, "period 3 or more"), 0: ("x", "0.6", 2.5, "not periodic")}
TEXT_COLUMNS = ("label", "type", "test_function", "signature", "pass", "direction", "status", "run", "durations", "kind", "from")
SECTION_COLUMNS = ("x1", "x2", "v1", "v2")

# How a trace's direction or a branch ended, in words ({p}: the parameter, {v}: its last value).
TRACE_ENDS = {
    "parameter-bound": "reached {p} = {v}", "loop": "came back to an orbit it had met (a loop) at {p} = {v}",
    "resonance": "a resonance (the amplitude grew past max_amplitude) at {p} = {v}",
    "not-confirmed": "no adjacent orbit type confirmed by simulation at {p} = {v}",
    "no-adjacent-type": "no adjacent orbit type at {p} = {v}", "family-end": "the family ends at {p} = {v}",
    "continuation-failed": "continuation failed at {p} = {v}", "max-points": "stopped at the point limit, {p} = {v}",
    "max-branches": "stopped at the branch limit, {p} = {v}"}
BRANCH_ENDS = {
    "parameter-bound": "reached {p} = {v}", "terminal-event": "changes orbit type at {p} = {v}",
    "stopped": "stopped at {p} = {v}", "max-points": "stopped at the point limit, {p} = {v}",
    "step-too-small": "step size fell below its minimum at {p} = {v}", "closed-loop": "closed a loop",
    "start-failed": "did not start", "start-outside-range": "starts outside its range",
    "fold-at-start": "a fold at its start"}


class BadInput(ValueError):
    """Bad input to the figure: the one-line message of the command line,
    "<field> = <value> is invalid: valid <range>"."""

    def __init__(self, field, value, valid):
        super().__init__(f"{field} = {value} is invalid: valid {valid}")


class CannotWrite(OSError):
    """The figure could not be written (a full disk, a directory that became read-only): the
    one-line message "cannot write '<path>': <the system's reason>"."""

    def __init__(self, path, error):
        super().__init__(error.errno, error.strerror, os.fspath(path))

    def __str__(self):
        return f"cannot write '{self.filename}': {self.strerror}"


# ---------------------------------------------------------------- the results, read

class Result:
    kind = ""
    name = ""
    parameter = ""

    def columns(self):
        return []

    def units(self):
        """A [model]'s units {length, time, force}, or None: the paper's (scaled) model, or a file that
        does not say (a sweep's or a map-sweep's CSV)."""
        return None


def _second_parameter(rows, parameter):
    """The parameter other than `parameter` that varies along a branch (a curve in two
    parameters), or None. One held equal to `parameter` (a tie) is not a second parameter. The parameters
    are the columns between `label` and `phi` (the paper's chi .. u_r, a [model]'s omega, F_k, ...)."""
    if not rows:
        return None
    columns = list(rows[0])
    names = columns[columns.index("label") + 1:columns.index("phi")] if "label" in columns and "phi" in columns else PARAMETERS
    for p in names:
        if p == parameter or p not in rows[0] or len({r[p] for r in rows}) < 2:
            continue
        if all(r[p] == r[parameter] for r in rows):  # tied to it (u_r = u_s, F_s = F_k)
            continue
        return p
    return None


def _curve_condition(rows):
    """What holds along a curve in two parameters whose orbit has a multiplier on the unit circle:
    "LP" (det(M - I) = 0, a fold curve), "PD" (det(M + I) = 0), "TR" (a torus curve), else ""
    (a type boundary: the stored stability flag holds)."""
    for condition, column in (("LP", "floquet:det(M-I)"), ("PD", "floquet:det(M+I)"), ("TR", "floquet:torus")):
        values = sorted(abs(_number(r.get(column))) for r in rows)
        if values and values[len(values) // 2] < 1e-7:
            return condition
    return ""


class Branch(Result):
    """A branch (summary.json, branch.csv, special-points.csv); a curve where a second parameter
    varies along it."""

    def __init__(self, name, summary, rows, special):
        self.name, self.summary, self.rows, self.special = name, summary, rows, special
        if not rows:
            raise BadInput("run", f"'{name}'", "a run with at least one point in branch.csv")
        self.parameter = summary["parameter"]
        self.signature = summary["signature"]
        self.second = _second_parameter(rows, self.parameter)
        self.kind = "curve" if self.second else "branch"
        self.condition = _curve_condition(rows) if self.second else ""

    @classmethod
    def from_texts(cls, name, branch_csv, special_csv, summary_json):
        return cls(name, json.loads(summary_json), _rows(branch_csv), _rows(special_csv))

    def units(self):
        return summary_units(self.summary)

    def columns(self):
        return list(self.rows[0])


class Trace(Result):
    """A trace (trace.json and its branches); `branches` [(entry, Branch)] in file order,
    `followed` [(entry, bifurcation, Branch)]: the branches followed at bifurcations."""
    kind = "trace"

    def __init__(self, name, trace, branches, followed=()):
        self.name, self.trace, self.branches, self.followed = name, trace, branches, list(followed)
        self.parameter = trace["parameter"]
        self.signature = trace["signature"]

    def columns(self):
        seen = {}
        for _, b in self.branches:
            seen.update(dict.fromkeys(b.columns()))
        return list(seen)

    def units(self):
        return common_units([b for _, b in self.branches])


class Sweep(Result):
    """A brute-force sweep's CSV: one row per chain, pass, step and recorded period k."""
    kind = "sweep"

    def __init__(self, name, rows, header):
        self.name, self.rows, self.header = name, rows, header
        # chain,direction,step,<parameter>,...: the paper's or a model's (sweep --model) parameter
        self.parameter = header[3] if len(header) > 3 else ""

    def columns(self):
        return list(self.header)


class MapSweep(Result):
    """A brute-force map's CSV: one row per cell, attractor and recorded period k."""
    kind = "map-sweep"

    def __init__(self, name, rows, header):
        self.name, self.rows, self.header = name, rows, header
        self.first, self.second = header[4], header[5]  # i,j,ni,nj,<first>,<second>,... (any model's names)
        self.parameter = self.first

    def columns(self):
        return [self.first, self.second]


class OrbitTypeMap(Result):
    """An orbit-type map (regions.json, curves.csv); `summaries`: its curves' summary.json (curve-<k>/),
    which say whose model it is and in what units."""
    kind = "orbit-type-map"

    def __init__(self, name, regions, curves, chi_eta, summaries=()):
        self.name, self.regions, self.curves, self.chi_eta = name, regions, curves, chi_eta
        self.summaries = list(summaries)
        self.first, self.second = regions["first"], regions["second"]
        self.parameter = self.first
        self.path = ""

    def columns(self):
        return [self.first, self.second]

    def units(self):
        return shared_units(summary_units(s) for s in self.summaries)


class Atlas(Result):
    """An atlas (atlas.json and its traces, trace-<t>/): `traces` [Trace] in file order."""
    kind = "atlas"

    def __init__(self, name, atlas, traces):
        self.name, self.atlas, self.traces = name, atlas, traces
        self.parameter = atlas["parameter"]

    def columns(self):
        seen = {}
        for t in self.traces:
            seen.update(dict.fromkeys(t.columns()))
        return list(seen)

    def units(self):
        return common_units(self.traces)


def _rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def _read(path):
    with open(path, newline="") as f:
        return f.read()


def _read_branch(directory, name=None):
    return Branch.from_texts(name or os.path.basename(os.path.normpath(directory)),
                             _read(os.path.join(directory, "branch.csv")),
                             _read(os.path.join(directory, "special-points.csv")),
                             _read(os.path.join(directory, "summary.json")))


def _read_trace(directory):
    trace = json.loads(_read(os.path.join(directory, "trace.json")))
    branches, followed = [], []
    for entry in trace["branches"]:
        branch = _read_branch(os.path.join(directory, entry["name"]))
        branches.append((entry, branch))
        for bifurcation in entry.get("bifurcations", []):
            if bifurcation.get("followed"):
                followed.append((entry, bifurcation, _read_branch(os.path.join(directory, bifurcation["followed"]))))
    return Trace(os.path.basename(os.path.normpath(directory)), trace, branches, followed)


def _read_atlas(directory):
    atlas = json.loads(_read(os.path.join(directory, "atlas.json")))
    traces = [_read_trace(os.path.join(directory, t["name"])) for t in atlas["traces"]]
    return Atlas(os.path.basename(os.path.normpath(directory)), atlas, traces)


def _read_curves(path):
    """curves.csv of an orbit-type map (its parameters' columns come twice: read by position) and
    the paper's (chi, eta) along its curves, which give the natural frequencies; a [model]'s map
    has its own parameters' columns instead, and no (chi, eta)."""
    curves, chi_eta = {}, set()
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        paper = "chi" in header and "eta" in header
        for row in reader:
            c = curves.setdefault(int(row[0]), dict(x=[], y=[], adm=[], kind=row[1]))
            c["x"].append(float(row[7]))
            c["y"].append(float(row[8]))
            c["adm"].append(row[10] == "1")
            if paper:
                chi_eta.add((float(row[header.index("chi")]), float(row[header.index("eta")])))
    return curves, chi_eta


def _read_curve_summaries(directory, regions):
    """The summary.json of each of the map's curves whose directory is there (a map copied without
    them draws in the paper's scaled quantities: nothing says otherwise)."""
    summaries = []
    for c in regions.get("curves", []):
        path = os.path.join(directory, c.get("directory", f"curve-{c['id']}"), "summary.json")
        if os.path.isfile(path):
            summaries.append(json.loads(_read(path)))
    return summaries


def _read_orbit_type_map(directory):
    regions = json.loads(_read(os.path.join(directory, "regions.json")))
    curves, chi_eta = _read_curves(os.path.join(directory, "curves.csv"))
    result = OrbitTypeMap(os.path.basename(os.path.normpath(directory)), regions, curves, chi_eta,
                          _read_curve_summaries(directory, regions))
    result.path = os.path.abspath(directory)
    return result


# The numeric columns of a sweep's and a map-sweep's CSV by kind: whole numbers >= 0, numbers >= 0,
# finite numbers (every other column named here). A model parameter is finite and > 0 (u_s, u_r:
# finite). Text columns (pass, run, status, signature) are not checked.
_WHOLE = ("i", "j", "ni", "nj", "attractors", "attractor", "period", "starts", "k", "chain", "step")
_NON_NEGATIVE = ("stops_per_period", "sticks_per_period", "amplitude:x2", "amplitude:x1", "peak-to-peak:x2",
                 "peak-to-peak:x1")
_FINITE = ("section_phase", "x1", "x2", "v1", "v2") + PARAMETERS


def _sweep_state_columns(header):
    """A sweep's parameter and state columns (chain,direction,step,<parameter>,section_phase,k,
    <state...>,stops_per_period,...), whatever the model: finite numbers."""
    if "k" in header and "stops_per_period" in header and header.index("k") < header.index("stops_per_period"):
        return header[3:4] + header[header.index("k") + 1:header.index("stops_per_period")]
    return []


def _check_csv_columns(rows, header, shown, finite=()):
    """Every row of a sweep's or map-sweep's CSV has the header's fields, each numeric one of its
    kind (BadInput naming the file, the line and the column): what the figure reads is never a
    silent nan or a traceback. `finite`: more columns that are finite numbers."""
    for line, row in enumerate(rows, 2):
        if None in row or any(v is None for v in row.values()):
            raise BadInput("input", f"'{shown}' line {line}", f"a row of {len(header)} fields, as its header")
        for column in header:
            text = row[column]
            if column in _WHOLE:
                valid = "a whole number >= 0"
                ok = text.isdigit() and text.isascii() and len(text) <= 18
            elif column in _NON_NEGATIVE or column in _FINITE or column in finite or column.startswith("amplitude:"):
                non_negative = column in _NON_NEGATIVE or column.startswith("amplitude:")
                valid = "a finite number >= 0" if non_negative else (
                    "a finite number > 0" if column in ("chi", "eta", "omega") else "a finite number")
                try:
                    v = float(text)
                except ValueError:
                    v = math.nan
                ok = math.isfinite(v) and (v >= 0 if non_negative else True) and (
                    v > 0 if column in ("chi", "eta", "omega") else True)
                if column.startswith("amplitude:") and text == "nan":  # the brute force's, not computed
                    ok, valid = True, "a finite number >= 0 or nan"
            else:
                continue
            if not ok:
                raise BadInput(f"input '{shown}' line {line} column '{column}'", f"'{text}'", valid)


def csv_result(name, text, shown=None):
    """A sweep or map-sweep from its CSV text (what SweepResult.csv() returns); `shown`: how
    messages name it (default its name)."""
    shown = shown or name
    rows = _rows(text)
    header = next(csv.reader(io.StringIO(text)), [])
    if {"i", "j", "ni", "nj", "attractor"} <= set(header):
        _check_csv_columns(rows, header, shown)
        if not any(r["k"] == "0" for r in rows):
            raise BadInput("input", f"'{shown}'", "a map-sweep file with at least one cell (a row with k = 0)")
        return MapSweep(name, rows, header)
    if {"chain", "step", "k", "period"} <= set(header):
        _check_csv_columns(rows, header, shown, _sweep_state_columns(header))
        if not rows:
            raise BadInput("input", f"'{shown}'", "a sweep file with at least one point")
        return Sweep(name, rows, header)
    raise BadInput("input", f"'{shown}'", "a run, trace or orbit-type map directory or a sweep or map-sweep CSV (its "
                   "header: chain,direction,step,... or i,j,ni,nj,...)")


def load(path):
    """The result stored at `path`: a run's, trace's or orbit-type map's directory (or one of its
    files), a sweep's or map-sweep's CSV. Raises BadInput for anything else."""
    valid = ("a run, trace, atlas or orbit-type map directory (summary.json, trace.json, atlas.json, regions.json) "
             "or a sweep or map-sweep CSV")
    path = os.fspath(path)
    if os.path.isfile(path) and os.path.basename(path) in ("branch.csv", "special-points.csv", "summary.json",
                                                           "trace.csv", "trace.json", "regions.json", "curves.csv",
                                                           "atlas.json"):
        path = os.path.dirname(os.path.abspath(path))
    try:
        if os.path.isdir(path):
            if os.path.isfile(os.path.join(path, "atlas.json")):
                return _read_atlas(path)
            if os.path.isfile(os.path.join(path, "trace.json")):
                return _read_trace(path)
            if os.path.isfile(os.path.join(path, "summary.json")):
                return _read_branch(path)
            if os.path.isfile(os.path.join(path, "regions.json")):
                return _read_orbit_type_map(path)
            raise BadInput("input", f"'{path}'", valid)
        if os.path.isfile(path):
            return csv_result(os.path.splitext(os.path.basename(path))[0], _read(path), path)
    except (OSError, KeyError, ValueError, IndexError, StopIteration, UnicodeDecodeError) as e:
        if isinstance(e, BadInput):
            raise
        raise BadInput("input", f"'{path}'", f"{valid} (cannot read it: {e})") from None
    raise BadInput("input", f"'{path}'", f"{valid}; it does not exist")


# ---------------------------------------------------------------- quantities in words

def natural_frequencies(chi, eta):
    """(omega1, omega2): the roots of s^4 - (1 + chi eta) s^2 + chi eta (1 - chi) = 0 (Pascal
    2014, eq. 56), as lib/include/stickslip/model/pascal_2014/modal.hpp's NaturalFrequencies computes them
    (omega1^2 as det/omega2^2, free of cancellation)."""
    trace = 1.0 + chi * eta
    root = math.sqrt((1.0 - chi * eta) ** 2 + 4.0 * chi * chi * eta)
    omega2_sq = 0.5 * (trace + root)
    omega1_sq = chi * eta * (1.0 - chi) / omega2_sq
    return math.sqrt(omega1_sq), math.sqrt(omega2_sq)


SYMBOLS = {"omega": r"$\omega$", "chi": r"$\chi$", "eta": r"$\eta$", "u_s": r"$u_s$", "u_r": r"$u_r$",
           "phi": r"$\varphi$", "F_k": r"$F_k$", "F_s": r"$F_s$", "v_b": r"$v_b$"}


def symbol(name):
    return SYMBOLS.get(name, name)


SI_UNITS = {"length": "m", "time": "s", "force": "N"}


def summary_units(summary):
    """A run's units by its summary.json: a [model]'s ("model" present) as declared, SI for runs
    made before units could be declared; None for the paper's scaled model (no "model")."""
    if summary.get("model") is None:
        return None
    return summary.get("units", SI_UNITS)


def shared_units(units):
    """The units every one of `units` is in, or None (none, or not the same)."""
    units = list(units)
    return units[0] if units and all(u == units[0] for u in units) else None


def common_units(results):
    """The units the results share, or None (none, or not the same); sweeps and map-sweeps, whose
    CSV files do not say, take those of the runs they are drawn with."""
    return shared_units(r.units() for r in results if r.kind not in ("sweep", "map-sweep"))


def unit_of(name, units):
    """A column's unit from a [model]'s units (Result.units), or None: scaled, or not known."""
    if not units:
        return None
    length, time, force = units["length"], units["time"], units["force"]
    by_name = {"omega": f"rad/{time}", "F_k": force, "F_s": force, "v_b": f"{length}/{time}", "phi": "rad",
               "friction-work": "J" if units == SI_UNITS else f"{force} {length}",
               "equivalent-damping": f"{force} {time}/{length}"}
    if name in by_name:
        return by_name[name]
    if name.startswith(("amplitude:", "peak-to-peak:")):
        return length
    if name[:1] == "d" and name[1:].isdigit():
        return time
    return None


def quantity_label(name, units=None):
    """An axis label for a column, in words, with its unit where `units` (Result.units) give it."""
    unit = unit_of(name, units)
    label = _quantity_words(name)
    return f"{label} ({unit})" if unit else label


def _quantity_words(name):
    words = {"omega": r"forcing frequency $\omega$", "chi": r"stiffness ratio $\chi$", "eta": r"mass ratio $\eta$",
             "u_s": r"sliding friction level $u_s$", "u_r": r"static friction level $u_r$", "phi": r"forcing phase $\varphi$",
             "x10": r"$x_1(0)$", "x20": r"$x_2(0)$", "v10": r"$\dot x_1(0)$", "stick-fraction": "fraction of the period stuck",
             "stops": "stops per period", "sticks": "sticks per period",
             "friction-work": "energy dissipated by friction per period",
             "equivalent-damping": "equivalent viscous damping", "stops_per_period": "stops per period",
             "sticks_per_period": "sticks per period", "period": "period (forcing periods)",
             "x1": r"$x_1$ on the section", "x2": r"$x_2$ on the section", "v1": r"$\dot x_1$ on the section",
             "v2": r"$\dot x_2$ on the section", "v_b": r"belt speed $v_b$", "F_k": r"kinetic friction force $F_k$",
             "F_s": r"static friction force $F_s$"}
    if name in words:
        return words[name]
    for prefix, text in (("amplitude:", "max $|{}|$ over a period"), ("peak-to-peak:", "peak-to-peak ${}$")):
        if name.startswith(prefix):
            coordinate = name[len(prefix):]
            if len(coordinate) == 2 and coordinate[1].isdigit():
                coordinate = f"{coordinate[0]}_{coordinate[1]}"
            return text.format(coordinate)
    if name[:1] == "d" and name[1:].isdigit():
        return f"duration of segment {name[1:]}"
    return name.replace("$", r"\$")


def _value(v):
    return f"{float(v):.4g}"


def _number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return math.nan


# ---------------------------------------------------------------- label placement

def overlap(a, b):
    """Whether boxes (x0, y0, x1, y1) overlap with a positive area."""
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def overlap_area(a, b):
    return max(0.0, min(a[2], b[2]) - max(a[0], b[0])) * max(0.0, min(a[3], b[3]) - max(a[1], b[1]))


def candidate_boxes(anchor, size, rings=8, gap=5.0, step=9.0):
    """Boxes of a label of `size` (w, h) around `anchor` (x, y), nearest first: above right, above
    left, below right, below left, right, left, above, below, then the same further out."""
    x, y = anchor
    w, h = size
    for ring in range(rings):
        g = gap + step * ring
        for dx, dy in ((g, g), (-g - w, g), (g, -g - h), (-g - w, -g - h), (g, -h / 2), (-g - w, -h / 2),
                       (-w / 2, g), (-w / 2, -g - h)):
            yield (x + dx, y + dy, x + dx + w, y + dy + h), ring


def place_labels(anchors, sizes, obstacles=(), bounds=None, rings=8, hard=()):
    """Greedy label placement: each label in turn takes the nearest candidate box
    (candidate_boxes) that overlaps no label placed before it and no obstacle (the markers, the
    curves), and lies inside `bounds` (x0, y0, x1, y1) when given; where every candidate collides,
    the one with the least overlap, labels and `hard` obstacles (markers) weighing most. Returns
    (box, ring) per label, in display units."""
    import numpy as np

    def total_overlap(box, boxes):
        if len(boxes) == 0:
            return 0.0
        width = np.minimum(box[2], boxes[:, 2]) - np.maximum(box[0], boxes[:, 0])
        height = np.minimum(box[3], boxes[:, 3]) - np.maximum(box[1], boxes[:, 1])
        return float(np.sum(np.clip(width, 0.0, None) * np.clip(height, 0.0, None)))

    soft = np.array(list(obstacles), dtype=float).reshape(-1, 4)
    firm = np.array(list(hard), dtype=float).reshape(-1, 4)
    placed = []
    for anchor, size in zip(anchors, sizes):
        best, best_cost = None, None
        others = np.array([other for other, _ in placed], dtype=float).reshape(-1, 4)
        for box, ring in candidate_boxes(anchor, size, rings):
            inside = is_inside(box, bounds)
            cost = 1e6 * total_overlap(box, others) + 1e6 * total_overlap(box, firm) + total_overlap(box, soft) + (
                0.0 if inside else 1e12)
            if cost == 0.0:
                best = (box, ring)
                break
            if best_cost is None or cost < best_cost:
                best, best_cost = (box, ring), cost
        placed.append(best)
    return placed


def is_inside(box, bounds):
    return bounds is None or (box[0] >= bounds[0] and box[1] >= bounds[1] and box[2] <= bounds[2] and
                              box[3] <= bounds[3])


def clamp(box, bounds):
    """The box moved (not resized) to lie inside `bounds` as far as it can."""
    dx = max(0.0, bounds[0] - box[0]) - max(0.0, box[2] - bounds[2])
    dy = max(0.0, bounds[1] - box[1]) - max(0.0, box[3] - bounds[3])
    return (box[0] + dx, box[1] + dy, box[2] + dx, box[3] + dy)


def label_points(figure, ax, labels, fontsize=None):
    """Places each (label, x, y) by place_labels so that no two labels, no label and marker, and
    where it can be helped no label and curve or legend overprint; a label pushed away from its
    point gets a thin leader line. Call once the axes' limits and the layout are final."""
    if not labels:
        return []
    fontsize = fontsize or pt(8)
    ax.set_xlim(ax.get_xlim())  # the limits the placement is computed for
    ax.set_ylim(ax.get_ylim())
    renderer = figure.canvas.get_renderer()

    def size_of(text):
        probe = ax.text(0, 0, text, fontsize=fontsize)
        extent = probe.get_window_extent(renderer)
        probe.remove()
        return extent.width + 2, extent.height + 2

    # A label may carry a short form (label, x, y, short), used where the long one finds no room
    # inside the axes.
    labels = [tuple(label) + (None,) if len(label) == 3 else tuple(label) for label in labels]
    anchors, sizes = [], []
    for text, x, y, _ in labels:
        anchors.append(tuple(ax.transData.transform((x, y))))
        sizes.append(size_of(text))
    scale = figure.dpi / 100.0
    markers = [(px - 4 * scale, py - 4 * scale, px + 4 * scale, py + 4 * scale) for px, py in anchors]
    obstacles = []
    for line in ax.get_lines():  # the curves, point by point
        if not line.get_visible():
            continue
        for px, py in line.get_transform().transform(line.get_xydata()):
            if math.isfinite(px) and math.isfinite(py):
                obstacles.append((px - 1.5, py - 1.5, px + 1.5, py + 1.5))
    if ax.get_legend() is not None:
        markers.append(tuple(ax.get_legend().get_window_extent(renderer).extents))
    from matplotlib.text import Text
    for t in ax.texts:  # texts already on the axes (a map's region numbers, labels placed before)
        if t.get_text().strip():
            markers.append(tuple(Text.get_window_extent(t, renderer).extents))
    bounds = tuple(ax.get_window_extent(renderer).extents)
    placed, texts = [], []
    for (text, x, y, short), anchor, size in zip(labels, anchors, sizes):
        # One at a time, the labels placed before it as hard obstacles.
        hard = markers + [box for box, _ in placed]

        def collides(box):
            return not is_inside(box, bounds) or any(overlap(box, h) for h in hard)

        # The nearest free place; else the short form; else further out (with a leader line).
        (box, ring), = place_labels([anchor], [size], obstacles, bounds, hard=hard)
        if collides(box) and short:
            text, size = short, size_of(short)
            (box, ring), = place_labels([anchor], [size], obstacles, bounds, hard=hard)
        if collides(box):
            (box, ring), = place_labels([anchor], [size], obstacles, bounds, hard=hard, rings=30)
        if not is_inside(box, bounds):
            box, ring = clamp(box, bounds), max(ring, 1)
        placed.append((box, ring))
        texts.append(text)
    for (_, x, y, _), text, anchor, (box, ring) in zip(labels, texts, anchors, placed):
        # In points, so that the offset scales with the figure when saved at another dpi.
        offset = ((box[0] + 1 - anchor[0]) * 72.0 / figure.dpi, (box[1] + 1 - anchor[1]) * 72.0 / figure.dpi)
        ax.annotate(text, (x, y), xytext=offset, textcoords="offset points",
                    ha="left", va="bottom", fontsize=fontsize, zorder=6, gid="stickslip-label",
                    arrowprops=dict(arrowstyle="-", color="0.4", lw=0.5, shrinkA=0, shrinkB=3) if ring > 0 else None)
    return placed


# ---------------------------------------------------------------- drawing pieces

def runs_of(rows, key):
    """Consecutive pieces of rows with the same key (a column name or a function of the row), the
    boundary row repeated in both pieces."""
    value = key if callable(key) else (lambda row: row[key])
    pieces, current = [], []
    for row in rows:
        if current and value(row) != value(current[-1]):
            current.append(row)
            pieces.append(current)
            current = [row]
        else:
            current.append(row)
    if current:
        pieces.append(current)
    return pieces


def stable_off_the_curve(condition):
    """On a curve of folds, period doublings or torus points the critical multipliers sit on the
    unit circle, where the stored flag flickers with rounding: the orbit is stable on the curve if
    the others lie inside (LP: all but the one nearest +1; PD: nearest -1; TR: the pair nearest
    the circle)."""
    def stable(row):
        try:
            mu = [complex(float(row[f"floquet:mu{k}_re"]), float(row[f"floquet:mu{k}_im"])) for k in range(1, 5)]
        except KeyError:
            return row["stable"] == "1"
        if condition == "LP":
            mu.remove(min(mu, key=lambda m: abs(m - 1)))
        elif condition == "PD":
            mu.remove(min(mu, key=lambda m: abs(m + 1)))
        elif condition == "TR":
            mu = sorted(mu, key=lambda m: abs(abs(m) - 1) if m.imag != 0 else math.inf)[2:]
        else:
            return row["stable"] == "1"
        return all(abs(m) < 1 for m in mu)
    return stable


class Canvas:
    """What the pieces of one set of axes share: the axes, the colour of each orbit type, the
    legend's entries by group, the labels to place, the marks already drawn."""

    def __init__(self, ax):
        self.ax = ax
        self.colours = {}
        self.styles = {}   # (stable, admissible) -> longest span drawn
        self.markers = {}  # legend name -> handle
        self.extra = []    # other legend handles (sweeps, natural frequencies)
        self.labels = []
        self.drawn = set()
        self.widths = []

    def colour(self, signature):
        return self.colours.setdefault(signature, COLOURS[len(self.colours) % len(COLOURS)])

    def mark(self, kind, x, y, marker, face, size, name):
        """One mark per point (a point met twice, by two branches, is marked once)."""
        from matplotlib.lines import Line2D
        if not (math.isfinite(x) and math.isfinite(y)):
            return
        key = (kind, f"{x:.6g}", f"{y:.5g}")
        if key in self.drawn:
            return
        self.drawn.add(key)
        self.ax.plot(x, y, marker, color=face, ms=size, mec="black", mew=0.6,
                     zorder=6 if marker == SWITCH_MARKER[0] else 5)
        self.markers.setdefault(name, Line2D([], [], ls="", marker=marker, color=face, ms=min(size, 9), mec="black",
                                             mew=0.6, label=name))
        if kind:
            self.labels.append((kind, x, y))

    def handles(self):
        from matplotlib.lines import Line2D
        width = max(self.widths) if self.widths else 0.0
        shown = {key for key, span in self.styles.items() if span > 1e-6 * width}
        handles = [Line2D([], [], color=c, lw=1.8, label=s) for s, c in self.colours.items()]
        handles += [Line2D([], [], ls=ls, color="black", lw=1.5, label=name) for ls, name, key in
                    (("-", "stable", (True, True)), ("--", "unstable", (False, True))) if key in shown]
        if any(not a for _, a in shown):
            handles.append(Line2D([], [], ls="-", **INADMISSIBLE, label="no motion (a margin < 0)"))
        return handles + list(self.markers.values()) + self.extra


def draw_branch(canvas, branch, x, y, *, label_by="label", stable=None, skip=(), colour=None, label_changes=True):
    """A branch's curve on canvas.ax: y over x, stable solid, unstable dashed, stretches that are
    no motion (admissible 0) thin grey; its special points marked by kind and queued for
    labelling (by their label, "LP4", or with label_by="type" their code)."""
    ax = canvas.ax
    if stable is None and getattr(branch, "condition", ""):
        stable = stable_off_the_curve(branch.condition)
    stable = stable or (lambda r: r["stable"] == "1")
    rows = branch.rows
    if x not in rows[0] or y not in rows[0]:
        return
    colour = colour or canvas.colour(branch.signature)
    xs_all = [_number(r[x]) for r in rows]
    canvas.widths.append(max(xs_all) - min(xs_all))
    for piece in runs_of(rows, lambda r: (stable(r), r["admissible"] == "1")):
        key = (stable(piece[0]), piece[0]["admissible"] == "1")
        xs = [_number(r[x]) for r in piece]
        canvas.styles[key] = max(canvas.styles.get(key, 0.0), max(xs) - min(xs) if len(piece) > 1 else 0.0)
        ax.plot(xs, [_number(r[y]) for r in piece], "-" if key[0] else "--",
                **(dict(color=colour, lw=1.8) if key[1] else INADMISSIBLE))
    for row in branch.special:
        if row["test_function"] in SKIPPED_TESTS + (branch.summary["termination"],) or row in skip:
            continue
        if x not in row or y not in row:
            continue
        kind, px, py = row["type"], _number(row[x]), _number(row[y])
        text = row["label"] if label_by == "label" else kind
        if kind == "EP":
            continue
        if not label_changes and kind not in MARKERS:
            text = ""  # marked, not labelled: an atlas's many changes of type would bury its bifurcations
        canvas.mark(text, px, py, *MARKERS.get(kind, TYPE_CHANGE_MARKER), 6, legend_entry(kind))


def draw_trace(canvas, trace, x, y, label_changes=True):
    """Every branch of the trace and every branch followed at a bifurcation: each orbit type in its
    own colour, the trace's start (a white circle), every switch to the adjacent type (a star),
    every change of type that did not switch and every smooth bifurcation marked and labelled by
    its code."""
    switched_at = {}
    for direction in trace.trace["directions"]:
        for k, following in zip(direction["branches"], direction["branches"][1:]):
            entry = trace.branches[following - 1][0]
            if entry["start"] == "switch":
                switched_at[trace.branches[k - 1][0]["name"]] = "margin:" + entry["margin"]
    for entry, branch in trace.branches:
        if x not in branch.rows[0] or y not in branch.rows[0]:
            continue
        switch = [r for r in branch.special if r["test_function"] == switched_at.get(entry["name"])][-1:]
        draw_branch(canvas, branch, x, y, label_by="type", skip=switch, label_changes=label_changes)
        for row in switch:
            canvas.mark(row["type"], _number(row[x]), _number(row[y]), *SWITCH_MARKER, 12,
                        "switch to the adjacent type")
        if entry["start"] == "trace-start":
            canvas.mark("", _number(branch.rows[0][x]), _number(branch.rows[0][y]), "o", "white", 7,
                        "the trace's start")
    for entry, bifurcation, branch in trace.followed:
        if x in branch.rows[0] and y in branch.rows[0]:
            draw_branch(canvas, branch, x, y, label_by="type", label_changes=label_changes)


def draw_sweep(canvas, sweep, x, y):
    """The brute force's points by the period found on the section: the section's states (x1, x2,
    v1, v2) at every recorded period, any other quantity once per settled motion (k = 0)."""
    from matplotlib.lines import Line2D
    every = y in SECTION_COLUMNS or x in SECTION_COLUMNS
    points = {}
    for r in sweep.rows:
        if every or r["k"] == "0":
            period = min(int(r["period"]), 3)
            points.setdefault(period, []).append((_number(r[x]), _number(r[y])))
    for period, (marker, colour, size, name) in SWEEP_STYLES.items():
        if period in points:
            xs, ys = zip(*points[period])
            canvas.ax.plot(xs, ys, marker, color=colour, ms=size, mew=0.6, zorder=2, alpha=0.8)
            label = f"brute force, {name}"
            if label not in [h.get_label() for h in canvas.extra]:
                canvas.extra.append(Line2D([], [], ls="", marker=marker, color=colour, ms=4, label=label))


def mark_natural_frequencies(canvas, pairs, axis="x"):
    """omega1, omega2 of each (chi, eta) in `pairs` (eq. 56)."""
    named = []
    for chi, eta in sorted(pairs):
        for k, natural in enumerate(natural_frequencies(chi, eta), 1):
            named.append((rf"$\omega_{k}$" + (f" ($\\chi$ = {chi:g}, $\\eta$ = {eta:g})" if len(pairs) > 1 else ""), natural))
    mark_frequencies(canvas, named, axis, "natural frequency (eq. 56)")


def mark_model_frequencies(canvas, frequencies, axis="x"):
    """A [model]'s slip natural frequencies (trace.json's natural_frequencies, rad/s)."""
    named = [(rf"$\omega_{k}$", f) for k, f in enumerate(frequencies, 1)]
    mark_frequencies(canvas, named, axis, "natural frequency of the slip (undamped)")


def mark_frequencies(canvas, named, axis, legend):
    """Each (name, frequency) of `named`: inside the axes a dotted line, labelled (placed with the
    other labels); outside, a line of the legend giving their values."""
    from matplotlib.lines import Line2D
    ax = canvas.ax
    low, high = sorted(ax.get_xlim() if axis == "x" else ax.get_ylim())
    outside = []
    for name, natural in named:
        if low < natural < high:
            line = ax.axvline if axis == "x" else ax.axhline
            line(natural, ls=":", color="0.25", lw=1.0, zorder=1)
            if axis == "x":
                y0, y1 = ax.get_ylim()
                top = ax.transData.inverted().transform(ax.transAxes.transform((0, 0.97)))[1]
                canvas.labels.append((name, natural, top if y0 < top < y1 else y1))
            else:
                right = ax.transData.inverted().transform(ax.transAxes.transform((0.97, 0)))[0]
                canvas.labels.append((name, right, natural))
        else:
            outside.append(f"{name} = {natural:.4g}")
    if any(low < n < high for _, n in named):
        canvas.extra.append(Line2D([], [], ls=":", color="0.25", lw=1.0, label=legend))
    if outside:
        canvas.extra.append(Line2D([], [], ls="", label="natural frequencies " + ", ".join(outside)))


# ---------------------------------------------------------------- options

def _pair(option, text, valid, check):
    parts = text.split(",") if isinstance(text, str) else list(text)
    try:
        values = tuple(float(p) for p in parts)
    except (TypeError, ValueError):
        values = ()
    if len(values) != 2 or not all(math.isfinite(v) for v in values) or not check(values):
        shown = text if isinstance(text, str) else ",".join(str(p) for p in parts)
        raise BadInput(option, f"'{shown}'", valid)
    return values


class Options:
    """The figure's options, checked: BadInput names the first that is invalid (as the command
    line spells it, `option_prefix` "--"; in Python, the keyword)."""

    def __init__(self, x=None, y=None, xscale="linear", yscale="linear", xlim=None, ylim=None, size=None,
                 dpi=DEFAULT_DPI, title=None, legend="right", natural_frequencies=True, output=None, prefix=""):
        def name(n):
            return prefix + n if prefix else n
        self.x, self.y, self.title, self.natural_frequencies = x, y, title, natural_frequencies
        for option, value in (("xscale", xscale), ("yscale", yscale)):
            if value not in ("linear", "log"):
                raise BadInput(name(option), f"'{value}'", "linear or log (default linear)")
        self.xscale, self.yscale = xscale, yscale
        if legend not in ("right", "inside", "none"):
            raise BadInput(name("legend"), f"'{legend}'", "right, inside or none (default right)")
        self.legend = legend
        self.xlim = self.ylim = None
        for option, value, scale in (("xlim", xlim, xscale), ("ylim", ylim, yscale)):
            if value is not None:
                # Limits matplotlib draws as asked: a narrower range it would widen silently, a
                # wider one overflows its ticks.
                if scale == "log":
                    rule = (f"LOW,HIGH: two finite numbers, low < high and low > 0 on a log axis, each from "
                            f"{LIMIT_RANGE[0]:g} to {LIMIT_RANGE[1]:g}, high/low from 1 + {LIMIT_RESOLUTION:g} to "
                            f"{LIMIT_RANGE[1]:g}")
                    check = (lambda v: LIMIT_RANGE[0] <= v[0] < v[1] <= LIMIT_RANGE[1]
                             and 1.0 + LIMIT_RESOLUTION <= v[1] / v[0] <= LIMIT_RANGE[1])
                else:
                    rule = (f"LOW,HIGH: two finite numbers, low < high, each from -{LIMIT_RANGE[1]:g} to "
                            f"{LIMIT_RANGE[1]:g}, high - low > {LIMIT_RESOLUTION:g} of the larger magnitude")
                    check = (lambda v: -LIMIT_RANGE[1] <= v[0] < v[1] <= LIMIT_RANGE[1]
                             and v[1] - v[0] > LIMIT_RESOLUTION * max(abs(v[0]), abs(v[1])))
                setattr(self, option, _pair(name(option), value, rule, check))
        self.size = None
        if size is not None:
            self.size = _pair(name("size"), size, f"WIDTH,HEIGHT in inches, each {SIZE_RANGE[0]:g} to {SIZE_RANGE[1]:g}",
                              lambda v: all(SIZE_RANGE[0] <= s <= SIZE_RANGE[1] for s in v))
        try:
            self.dpi = float(dpi)
        except (TypeError, ValueError):
            self.dpi = math.nan
        if not (DPI_RANGE[0] <= self.dpi <= DPI_RANGE[1]):
            raise BadInput(name("dpi"), f"'{dpi}'", f"{DPI_RANGE[0]} to {DPI_RANGE[1]} dots per inch (default {DEFAULT_DPI})")
        if self.size:
            _check_pixels(name("dpi"), dpi, self.dpi, self.size)
        if title:
            _check_mathtext(name("title"), title)
        self.output = output
        if output is not None:
            extension = os.path.splitext(output)[1].lower()
            if extension not in FORMATS:
                raise BadInput(name("output"), f"'{output}'", "a file name ending in .png, .pdf or .svg")
        self.prefix = prefix

    def name(self, option):
        return self.prefix + option if self.prefix else option


def _check_pixels(option, shown, dpi, size):
    """A PNG of `size` inches at `dpi`: at most MAX_PIXELS a side and MAX_AREA pixels in all."""
    largest = min(MAX_PIXELS / max(size), math.sqrt(MAX_AREA / (size[0] * size[1])))
    if max(size) * dpi > MAX_PIXELS or size[0] * size[1] * dpi * dpi > MAX_AREA:
        raise BadInput(option, f"'{shown}'", f"at most {MAX_PIXELS} pixels a side and {MAX_AREA / 1e6:g} million "
                       f"pixels: dpi <= {math.floor(largest)} at size {size[0]:g},{size[1]:g}")


def _check_mathtext(option, text):
    """A text matplotlib can draw: its $...$ parts valid mathtext (a '$' alone is written \\$)."""
    from matplotlib import cbook
    from matplotlib.mathtext import MathTextParser
    for line in str(text).split("\n"):
        if cbook.is_math_text(line):
            try:
                MathTextParser("path").parse(line)
            except ValueError:
                raise BadInput(option, f"'{text}'", "a text whose $...$ parts are valid mathtext "
                               "(write \\$ for a dollar sign)") from None


def _escaped(name):
    """A result's name as text in a figure: a '$' in it is a dollar sign, not mathtext."""
    return str(name).replace("$", r"\$")


def _numeric_columns(result):
    if result.kind == "sweep":
        return [c for c in result.columns() if c not in TEXT_COLUMNS and c not in ("chain", "step", "k")]
    return [c for c in result.columns() if c not in TEXT_COLUMNS]


# ---------------------------------------------------------------- figures

_FONT_SCALE = [1.0]


def pt(points):
    """A font size in points, scaled for the figure being drawn (font_scale)."""
    return points * _FONT_SCALE[0]


def font_scale(size):
    """Smaller type on a smaller figure: 1 at 8 x 4.5 inches and above, down to 0.7 (a 3.5-inch
    column figure gets 7-point tick labels)."""
    return max(0.7, min(1.0, size[0] / 8.0, size[1] / 4.5))


def _typeset(fig):
    """Tick and axis labels at the figure's scale (tick labels are made when drawn, after the
    figure's rc context has ended)."""
    for ax in fig.axes:
        ax.tick_params(labelsize=pt(10))
        ax.xaxis.label.set_fontsize(pt(10))
        ax.yaxis.label.set_fontsize(pt(10))


def _layout(results):
    kinds = [r.kind for r in results]
    if "atlas" in kinds:
        if len(results) > 1:
            raise BadInput("inputs", ", ".join(f"'{r.name}' ({r.kind})" for r in results), "an atlas alone")
        return "atlas"
    maps = [r for r in results if r.kind in ("orbit-type-map", "map-sweep")]
    if not maps:
        return "response"
    others = [r for r in results if r.kind not in ("orbit-type-map", "map-sweep", "curve")]
    names = ", ".join(f"'{r.name}' ({r.kind})" for r in others)
    if others:
        raise BadInput("inputs", names, "with a map only two-parameter curves and at most one map of each kind "
                       "(an orbit-type map, a brute-force map)")
    if kinds.count("orbit-type-map") > 1 or kinds.count("map-sweep") > 1:
        raise BadInput("inputs", ", ".join(f"'{r.name}'" for r in maps), "at most one orbit-type map and one brute-force map")
    planes = {(m.first, m.second) for m in maps}
    if len(planes) > 1:
        raise BadInput("inputs", ", ".join(f"'{m.name}' ({m.first}, {m.second})" for m in maps), "maps over the same two parameters")
    return "plane"


def figure(results, options=None, **keywords):
    """The figure of `results` (a Result or a list of them, or paths: load() reads them) as a
    matplotlib Figure. Keywords: the options (module docstring). Raises BadInput for options or
    inputs that cannot be drawn."""
    import matplotlib.pyplot as plt
    options = options or Options(**keywords)
    if isinstance(results, (Result, str, os.PathLike)):
        results = [results]
    results = [r if isinstance(r, Result) else load(r) for r in results]
    if not results:
        raise BadInput("inputs", "''", "at least one result")
    layout = _layout(results)
    stated = {", ".join(u[k] for k in ("length", "time", "force")) if u else "scaled"
              for u in (r.units() for r in results if r.kind not in ("sweep", "map-sweep"))}
    if len(stated) > 1:  # the axes can name none: say why
        print(f"note: the inputs are in different units ({'; '.join(sorted(stated))}): the axes name none", file=sys.stderr)
    _FONT_SCALE[0] = font_scale(options.size or DEFAULT_SIZES["response"]) if options.size else 1.0
    try:
        with plt.rc_context({"font.size": pt(10)}):
            if layout == "plane":
                return _plane_figure(results, options, plt)
            if layout == "atlas":
                return _atlas_figure(results[0], options, plt)
            return _response_figure(results, options, plt)
    finally:
        _FONT_SCALE[0] = 1.0


def _check_quantity(options, which, value, results):
    common = None
    for r in results:
        columns = _numeric_columns(r)
        common = [c for c in (common if common is not None else columns) if c in columns]
    if value not in common:
        raise BadInput(options.name(which), f"'{value}'", "a numeric column of every input: " + ", ".join(common))


def _check_drawable(options, x, y, results):
    """At least one point (x, y) of the inputs is finite, and positive on a log axis: else the
    figure would be empty axes, written without a word (BadInput naming the option that empties it)."""
    rows = [row for r in results for b in _branches(r) for row in b.rows]
    rows += [row for r in results if r.kind == "sweep" for row in r.rows]
    points = [(_number(row.get(x)), _number(row.get(y))) for row in rows]
    points = [(a, b) for a, b in points if math.isfinite(a) and math.isfinite(b)]
    if not points:
        raise BadInput(options.name("y"), f"'{y}'", f"a quantity with at least one finite value (against {x}) to draw")
    for which, scale, k, quantity in (("xscale", options.xscale, 0, x), ("yscale", options.yscale, 1, y)):
        if scale == "log" and not any(p[k] > 0 for p in points):
            raise BadInput(options.name(which), "'log'", f"linear, or log where some value of {quantity} is > 0 (none is)")


def _contact_amplitude(result):
    """The default y: max |x2| for the paper's model; for a [model] its contact coordinate's
    amplitude (the coordinate its peak-to-peak column names, or a sweep's amplitude column)."""
    if result.kind == "sweep":
        columns = result.header
    else:
        columns = next((list(b.rows[0]) for b in _branches(result) if b.rows), [])
    if "amplitude:x2" in columns or not columns:
        return "amplitude:x2"
    contact = next((c.split(":", 1)[1] for c in columns if c.startswith("peak-to-peak:")), None)
    if contact:
        return f"amplitude:{contact}"
    return next((c for c in columns if c.startswith("amplitude:")), "amplitude:x2")


def _response_figure(results, options, plt):
    x = options.x or results[0].parameter
    if options.y:
        y = options.y
    elif all(r.kind == "curve" for r in results):
        y = results[0].second
    else:
        y = _contact_amplitude(results[0])
    _check_quantity(options, "x", x, results)
    _check_quantity(options, "y", y, results)
    _check_drawable(options, x, y, results)
    size = options.size or DEFAULT_SIZES["response"]
    fig, ax = plt.subplots(figsize=size, dpi=100)
    canvas = Canvas(ax)
    for r in results:
        if r.kind == "sweep":
            draw_sweep(canvas, r, x, y)
    for r in results:
        if r.kind == "trace":
            draw_trace(canvas, r, x, y)
        elif r.kind in ("branch", "curve"):
            draw_branch(canvas, r, x, y, label_by="label" if len(results) == 1 else "type")
    ax.set_xscale(options.xscale)
    ax.set_yscale(options.yscale)
    if options.xlim:
        ax.set_xlim(options.xlim)
    if options.ylim:
        ax.set_ylim(options.ylim)
    ax.set_xlabel(quantity_label(x, common_units(results)))
    ax.set_ylabel(quantity_label(y, common_units(results)))
    ax.grid(alpha=0.3, which="major")
    pairs = set()
    for r in results:
        for b in _branches(r):
            pairs |= {(float(row["chi"]), float(row["eta"])) for row in b.rows if "chi" in row}
    if options.natural_frequencies and pairs and len(pairs) <= 2 and "omega" in (x, y):
        mark_natural_frequencies(canvas, pairs, "x" if x == "omega" else "y")
    models = {tuple(r.trace.get("natural_frequencies", ())) for r in results if r.kind == "trace"} - {()}
    if options.natural_frequencies and len(models) == 1 and not pairs and "omega" in (x, y):
        mark_model_frequencies(canvas, next(iter(models)), "x" if x == "omega" else "y")
    _finish(fig, [(ax, canvas)], options, _title(results, x, y))
    return fig


def draw_atlas_attractors(canvas, atlas, x, y):
    """The exact orbits found from the brute force's attractors (atlas.json records their
    amplitudes), where x is the atlas's parameter and y an amplitude: black crosses."""
    from matplotlib.lines import Line2D
    # The paper's atlas names them amplitude_x1, amplitude_x2; a [model]'s by its columns' names.
    key = {"amplitude:x1": "amplitude_x1", "amplitude:x2": "amplitude_x2"}.get(y, y)
    if x != atlas.parameter or not y.startswith("amplitude:"):
        return
    points = [(g["value"], a.get(y, a.get(key))) for g in atlas.atlas["grid"] for a in g["attractors"]
              if a["fate"] == "on-branch" and a.get(y, a.get(key)) is not None]
    if points:
        xs, ys = zip(*points)
        canvas.ax.plot(xs, ys, "x", color="black", ms=4.5, mew=0.9, zorder=4)
        canvas.extra.append(Line2D([], [], ls="", marker="x", color="black", ms=4.5, mew=0.9,
                                   label="brute force (its attractors' exact orbits)"))


def draw_coexistence(strip, atlas, colour):
    """Below the response: at each grid value, the orbit types of the stable motions the brute
    force found there (the attractors that lie on a branch), one row per type, in its colour."""
    signature_of = {}
    for t in atlas.traces:
        for entry, _ in t.branches:
            signature_of[f"{t.name}/{entry['name']}"] = entry["signature"]
    rows = {}
    for g in atlas.atlas["grid"]:
        for place in g["stable_on"]:
            rows.setdefault(signature_of.get(place, "?"), set()).add(g["value"])
    for k, (signature, values) in enumerate(rows.items()):
        strip.plot(sorted(values), [k] * len(values), "s", color=colour(signature), ms=4, mec="none")
    # Below them, where the brute force found a motion no periodic orbit up to the limit describes.
    others = [g["value"] for g in atlas.atlas["grid"]
              if any(a["fate"] in ("not-settled", "above-period-limit") for a in g["attractors"])]
    if others:
        strip.plot(others, [-1] * len(others), "|", color="0.45", ms=6)
        strip.text(1.01, -1, "not periodic\nwithin the limit", transform=strip.get_yaxis_transform(), fontsize=pt(7),
                   va="center", color="0.35")
    strip.set_ylim(-1.8 if others else -0.8, max(len(rows), 1) - 0.2)
    strip.set_yticks([])
    strip.set_ylabel("stable\nmotions", fontsize=pt(8))
    strip.grid(alpha=0.3, axis="x")


def _atlas_title(atlas):
    c = atlas.atlas["counts"]
    others = c["attractors"] - c["on_branches"]
    plural = lambda n, word: f"{n} {word}" + ("" if n == 1 else "s")
    return (f"Atlas over {symbol(atlas.parameter)}{_named(atlas)}: {plural(c['on_branches'], 'attractor')} on "
            f"{plural(c['branches'], 'branch').replace('branchs', 'branches')} of {plural(len(c['orbit_types']), 'orbit type')}, "
            f"traced from {plural(c['traces'], 'start')}\n"
            f"{plural(others, 'other attractor')} listed in atlas.json with the reason (no orbit type, not settled, a "
            f"longer period, not solved)")


def _atlas_figure(atlas, options, plt):
    if not atlas.traces:
        raise BadInput("input", f"'{atlas.name}'", "an atlas with at least one traced branch (this one traced none: "
                       "its atlas.json lists every attractor with the reason)")
    x = options.x or atlas.parameter
    y = options.y or _contact_amplitude(atlas)
    _check_quantity(options, "x", x, [atlas])
    _check_quantity(options, "y", y, [atlas])
    _check_drawable(options, x, y, [atlas])
    fig, (ax, strip) = plt.subplots(2, 1, figsize=options.size or DEFAULT_SIZES["atlas"], dpi=100, sharex=True,
                                    gridspec_kw={"height_ratios": [4.2, 1.0]})
    canvas = Canvas(ax)
    for trace in atlas.traces:
        draw_trace(canvas, trace, x, y, label_changes=False)
    draw_atlas_attractors(canvas, atlas, x, y)
    if x == atlas.parameter:
        draw_coexistence(strip, atlas, canvas.colour)
    ax.set_xscale(options.xscale)
    ax.set_yscale(options.yscale)
    if options.xlim:
        ax.set_xlim(options.xlim)
    elif x == atlas.parameter and options.xscale == "linear":  # the range asked for, where nothing was found too
        low, high = atlas.atlas["range"]
        ax.set_xlim(low - 0.02 * (high - low), high + 0.02 * (high - low))
    if options.ylim:
        ax.set_ylim(options.ylim)
    strip.set_xlabel(quantity_label(x, atlas.units()))
    ax.set_ylabel(quantity_label(y, atlas.units()))
    ax.grid(alpha=0.3, which="major")
    pairs = {(float(row["chi"]), float(row["eta"])) for b in _branches(atlas) for row in b.rows if "chi" in row}
    if options.natural_frequencies and pairs and len(pairs) <= 2 and "omega" in (x, y):
        mark_natural_frequencies(canvas, pairs, "x" if x == "omega" else "y")
    models = {tuple(t.trace.get("natural_frequencies", ())) for t in atlas.traces} - {()}
    if options.natural_frequencies and len(models) == 1 and not pairs and "omega" in (x, y):
        mark_model_frequencies(canvas, next(iter(models)), "x" if x == "omega" else "y")
    _finish(fig, [(strip, Canvas(strip)), (ax, canvas)], options, _atlas_title(atlas))
    return fig


def _branches(result):
    if result.kind in ("branch", "curve"):
        return [result]
    if result.kind == "atlas":
        return [b for t in result.traces for b in _branches(t)]
    if result.kind == "trace":
        return [b for _, b in result.branches] + [b for _, _, b in result.followed]
    return []


def _legend(ax, handles, options, fig, below=False):
    if not handles or options.legend == "none":
        return
    if below and options.legend == "right":  # beside the axes stands a colour bar
        ax.legend(handles=handles, fontsize=pt(8), loc="upper center", bbox_to_anchor=(0.5, -0.14), borderaxespad=0.0,
                  ncol=min(3, len(handles)))
    elif options.legend == "inside":
        ax.legend(handles=handles, fontsize=pt(7), loc="best", framealpha=0.9)
    else:
        ax.legend(handles=handles, fontsize=pt(8), loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0)


def wrap(text, width_inches, fontsize):
    """The text's lines wrapped to fit `width_inches` at `fontsize` points (an average glyph is
    about 0.55 of the font size wide; mathtext such as $\\omega$ counts as one glyph)."""
    import re
    import textwrap
    columns = max(20, int(width_inches * 72 / (0.55 * fontsize)) - 2)
    lines = []
    for line in text.split("\n"):
        visible = len(re.sub(r"\$[^$]*\$", "w", line))
        if visible <= columns:
            lines.append(line)
            continue
        # Wrap by words, counting each $...$ group as one glyph.
        current, length = [], 0
        for word in line.split(" "):
            size = len(re.sub(r"\$[^$]*\$", "w", word))
            if current and length + 1 + size > columns:
                lines.append(" ".join(current))
                current, length = [], 0
            current.append(word)
            length += size + (1 if length else 0)
        if current:
            lines.append(" ".join(current))
    return "\n".join(lines)


def _finish(fig, panels, options, title, below=False):
    """Legend, title, layout, then the labels (placed once the layout is final)."""
    for k, (ax, canvas) in enumerate(panels):
        if k == len(panels) - 1:
            handles = []
            for _, c in panels:
                for h in c.handles():
                    if h.get_label() not in [g.get_label() for g in handles]:
                        handles.append(h)
            _legend(ax, handles, options, fig, below)
    _typeset(fig)
    text = title if options.title is None else options.title
    if text:
        fig.suptitle(wrap(text, fig.get_figwidth(), pt(10)), fontsize=pt(10))
    fig.tight_layout()
    # The panels' titles wrapped to their axes' widths, once the layout has given them.
    for ax, _ in panels:
        title = ax.get_title()
        if title:
            ax.set_title(wrap(title.replace("\n", " "), ax.get_position().width * fig.get_figwidth(), pt(9)), fontsize=pt(9))
    fig.tight_layout()
    for ax, canvas in panels:
        label_points(fig, ax, canvas.labels)


def _ends_in_words(result):
    p = symbol(result.parameter)
    if result.kind == "trace":
        words = []
        for d in result.trace["directions"]:
            last = result.branches[d["branches"][-1] - 1][1].rows[-1] if d["branches"] else None
            value = _value(last[result.parameter]) if last else "?"
            end = TRACE_ENDS.get(d["end"], d["end"].replace("-", " ") + " at {p} = {v}").format(p=p, v=value)
            towards = "lower" if d["direction"] == "down" else "higher"
            words.append(f"towards {towards} {p}: {end}")
        return "; ".join(words)
    if result.kind in ("branch", "curve"):
        value = _value(result.rows[-1][result.parameter])
        end = result.summary["termination"]
        message = result.summary.get("message", "")
        if end == "stopped" and message.startswith("resonance"):
            return f"ends at a resonance near {p} = {value}"
        if end == "terminal-event":
            import re
            code = re.search(r"\((\w+)\)", message)
            return f"ends where the orbit type changes{f' ({code.group(1)})' if code else ''} at {p} = {value}"
        return "ends: " + BRANCH_ENDS.get(end, end.replace("-", " ") + " at {p} = {v}").format(p=p, v=value)
    return ""


def _named(result):
    return f" ({_escaped(result.name)})" if result.name else ""


def _title(results, x, y):
    main = [r for r in results if r.kind != "sweep"]
    sweeps = [r for r in results if r.kind == "sweep"]
    if len(main) == 1 and sweeps and main[0].parameter == x:
        names = ", ".join(dict.fromkeys(_escaped(r.name) for r in sweeps))
        return _title(main, x, y) + f"\nwith the brute force (sweeps {names})"
    if len(results) == 1:
        r = results[0]
        if r.kind == "trace":
            return (f"Orbits traced over {symbol(r.parameter)} from '{r.signature}' ({_escaped(r.name) + ', ' if r.name else ''}"
                    f"{len(r.branches) + len(r.followed)} branches)\n{_ends_in_words(r)}")
        if r.kind == "curve":
            return (f"Curve in ({symbol(r.parameter)}, {symbol(r.second)}) of '{r.signature}' orbits{_named(r)}\n"
                    f"{_ends_in_words(r)}")
        if r.kind == "branch":
            return f"Branch of '{r.signature}' orbits over {symbol(r.parameter)}{_named(r)}\n{_ends_in_words(r)}"
        if r.kind == "sweep":
            recorded = max(int(row["k"]) for row in r.rows) + 1
            return f"Brute force over {symbol(r.parameter)}: the settled motions, {recorded} periods recorded each{_named(r)}"
    names = ", ".join(_escaped(r.name) for r in results[:-1]) + " and " + _escaped(results[-1].name)
    return f"{quantity_label(y)} against {symbol(x)}: {names}"


def read_trace(directory):
    """trace.json and, per branch in file order, (entry, summary, rows, special): the tuples
    tools/trace_intervals.py and tools/plot_figures.py read."""
    trace = load(directory)
    return trace.trace, [(entry, b.summary, b.rows, b.special) for entry, b in trace.branches]


def holds_data(branches):
    """Whether the model's data (chi, eta, u_s, u_r) are the same at every point of a trace's
    branches (read_trace's tuples), so that a sweep at those data is a brute force of the same
    system (not where u_s = u_r is solved)."""
    return len({(r["chi"], r["eta"], r["u_s"], r["u_r"]) for _, _, rows, _ in branches for r in rows}) == 1


def diagram(result, y="x20", stable=None, size=DEFAULT_SIZES["diagram"]):
    """The bifurcation diagram of one branch (a Branch or its directory): `y` (x20, the orbit's
    origin; a curve's second parameter) over the parameter on top, the segment durations below,
    special points marked on top. Returns (figure, top, bottom, canvas): label the points with
    finish_diagram once everything else is drawn."""
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    branch = result if isinstance(result, Result) else load(result)
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=size, dpi=100)
    canvas = Canvas(top)
    draw_branch(canvas, branch, branch.parameter, y, stable=stable)
    durations = [c for c in branch.rows[0] if c.startswith("d") and c[1:].isdigit()]
    stable_of = stable or (lambda r: r["stable"] == "1")
    for piece in runs_of(branch.rows, lambda r: (stable_of(r), r["admissible"])):
        xs = [_number(r[branch.parameter]) for r in piece]
        for k, d in enumerate(durations):
            # The durations keep their colours where the orbit is no motion, faded and thin.
            bottom.plot(xs, [_number(r[d]) for r in piece], "-" if stable_of(piece[0]) else "--", color=f"C{k + 1}",
                        **(dict(lw=1.5) if piece[0]["admissible"] == "1" else dict(lw=0.9, alpha=0.4)))
    if durations:
        bottom.legend(handles=[Line2D([], [], color=f"C{k + 1}", lw=1.5, label=f"segment {d[1:]}")
                               for k, d in enumerate(durations)], fontsize=pt(7), loc="best", ncol=min(len(durations), 4))
    units = branch.units()
    top.set_ylabel(quantity_label(y, units))
    bottom.set_ylabel(f"segment durations ({units['time']})" if units else "segment durations")
    bottom.set_xlabel(quantity_label(branch.parameter, units))
    top.grid(alpha=0.3)
    bottom.grid(alpha=0.3)
    return fig, top, bottom, canvas


def finish_diagram(fig, top, canvas, title, options=None):
    """The diagram's legend beside the top axes, its title, layout and labels."""
    options = options or Options()
    _finish(fig, [(top, canvas)], options, title)


# ---------------------------------------------------------------- maps

def canonical(signature):
    """The orbit type up to a cyclic shift of its segments (as analysis/map_comparison.hpp)."""
    head, sep, tail = signature.partition(" /")
    tokens = head.split()
    rotations = [tokens[k:] + tokens[:k] for k in range(len(tokens))] or [tokens]
    return " ".join(min(rotations)) + (sep + tail if sep else "")


def _kind_name(kind):
    return kind[len("margin:"):] if kind.startswith("margin:") else kind


def _brute_cells(ms):
    cells = {}
    for r in ms.rows:
        if r["k"] != "0":
            continue
        cell = cells.setdefault((int(r["i"]), int(r["j"])), dict(x=float(r[ms.first]), y=float(r[ms.second]),
                                                                attractors=[], types=set(), other=False))
        cell["attractors"].append(dict(status=r["status"], period=int(r["period"]),
                                       stops=float(r["stops_per_period"]), sticks=float(r["sticks_per_period"])))
        if r["status"] == "periodic" and r["period"] == "1" and r.get("signature"):
            cell["types"].add(canonical(r["signature"]))
        else:
            cell["other"] = True
    return cells


def _extent_of(cells):
    xs = sorted({c["x"] for c in cells.values()})
    ys = sorted({c["y"] for c in cells.values()})
    dx = (xs[-1] - xs[0]) / max(1, len(xs) - 1) if len(xs) > 1 else 1.0
    dy = (ys[-1] - ys[0]) / max(1, len(ys) - 1) if len(ys) > 1 else 1.0
    return xs, ys, dx, dy, (xs[0] - dx / 2, xs[-1] + dx / 2, ys[0] - dy / 2, ys[-1] + dy / 2)


def _draw_map_curves(canvas, otm, colours):
    """The orbit-type map's curves coloured by kind, solid where the orbit on the curve is
    admissible apart from the curve's own condition, dashed where not."""
    import numpy as np
    from matplotlib.lines import Line2D
    for cid, c in sorted(otm.curves.items()):
        colour = colours[c["kind"]]
        x, y, adm = np.array(c["x"]), np.array(c["y"]), np.array(c["adm"])
        for solid in (True, False):
            mask = adm if solid else ~adm
            keep = mask.copy()
            keep[1:] |= mask[:-1]
            xs, ys = np.where(keep, x, np.nan), np.where(keep, y, np.nan)
            canvas.ax.plot(xs, ys, color=colour, lw=1.6 if solid else 1.0, ls="-" if solid else "--")
    for kind, colour in colours.items():
        name = f"boundary {_kind_name(kind)}"
        if name not in canvas.markers:
            canvas.markers[name] = Line2D([], [], color=colour, lw=1.6, label=name)


def _map_special_points(otm):
    """The curves' codimension-two points (not their ends, EP, nor BP), one label per place: the
    types met there and the curves' kinds ("SK (LP, PD)"), points within 1/60 of the axes' ranges
    taken as one place."""
    rect = otm.regions["rectangle"]
    width, height = rect["first_max"] - rect["first_min"], rect["second_max"] - rect["second_min"]
    places = {}
    for c in otm.regions["curves"]:
        for p in c["special_points"]:
            if p["type"] in ("EP", "BP"):
                continue
            key = (round(p[otm.first] / width * 60), round(p[otm.second] / height * 60))
            place = places.setdefault(key, dict(x=p[otm.first], y=p[otm.second], types=set(), kinds=set()))
            place["types"].add(p["type"])
            place["kinds"].add(_kind_name(c["kind"]))
    return [(q["x"], q["y"], f'{"/".join(sorted(q["types"]))} ({", ".join(sorted(q["kinds"]))})')
            for q in places.values()]


def _trace_directory(otm):
    """The map's trace as the map recorded it (relative to the directory it was made in: the
    current one, or one of the map directory's ancestors), or None where it is not found."""
    trace = otm.regions.get("trace") or ""
    if not trace:
        return None
    candidates = [trace] + [os.path.join(os.path.dirname(otm.path) + "/.." * k, trace) for k in range(4)]
    return next((c for c in candidates if os.path.isdir(c)), None)


def _trace_start(otm):
    """Where the map's trace starts: its first point, or None where the trace is not found."""
    trace = _trace_directory(otm)
    try:
        with open(os.path.join(trace, "branch-1", "branch.csv"), newline="") as f:
            row = next(csv.DictReader(f))
        return float(row[otm.first]), float(row[otm.second])
    except (OSError, StopIteration, KeyError, TypeError):
        return None


def _trace_frequencies(otm):
    """A [model]'s slip natural frequencies as its map's trace lists them (trace.json), or () where
    the trace is not found or lists none (the paper's: its (chi, eta) give them)."""
    trace = _trace_directory(otm)
    try:
        with open(os.path.join(trace, "trace.json")) as f:
            return tuple(float(value) for value in json.load(f).get("natural_frequencies", ()))
    except (OSError, TypeError, ValueError, AttributeError):
        return ()


# How a region that is not uniform is drawn: a grey diagonal hatch over its cells (its fill, from
# the types at its interior point, as any region's), and the legend's word for it.
NOT_UNIFORM_HATCH = dict(hatch="//", edgecolor="0.55", facecolor="none", lw=0)
NOT_UNIFORM_LEGEND = "not uniform: a boundary is missing"


def _not_uniform_regions(otm):
    """The map's regions that are not uniform: a point of the trace inside differs from the orbits
    found at the region's interior point ("differing" > 0; a map written before the key existed
    has none; anything but a number counts as none)."""
    return [r for r in otm.regions["regions"] if isinstance(r.get("differing"), (int, float)) and r["differing"] > 0]


def _hatch_regions(ax, otm, extent):
    """Hatches the cells of each region of the map that is not uniform (one patch per region, the
    runs of its cells row by row); the legend's handle, or None where every region is uniform."""
    from matplotlib.patches import Patch, PathPatch
    from matplotlib.path import Path
    hatched = {r["id"] for r in _not_uniform_regions(otm)}
    if not hatched:
        return None
    n = otm.regions["raster"]
    dx, dy = (extent[1] - extent[0]) / n, (extent[3] - extent[2]) / n
    runs = {rid: [] for rid in hatched}
    for j, row in enumerate(otm.regions["cells"]):
        ids = [int(v) for v in row.split()] + [0]
        start = None
        for i, rid in enumerate(ids):
            if start is not None and rid != ids[start]:
                runs[ids[start]].append((start, i, j))
                start = None
            if start is None and rid in hatched:
                start = i
    for rid in sorted(runs):
        if not runs[rid]:
            continue
        vertices, codes = [], []
        for i0, i1, j in runs[rid]:
            x0, x1 = extent[0] + i0 * dx, extent[0] + i1 * dx
            y0, y1 = extent[2] + j * dy, extent[2] + (j + 1) * dy
            vertices += [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)]
            codes += [Path.MOVETO, Path.LINETO, Path.LINETO, Path.LINETO, Path.CLOSEPOLY]
        ax.add_patch(PathPatch(Path(vertices, codes), zorder=1, gid=f"not-uniform-region-{rid}", **NOT_UNIFORM_HATCH))
    return Patch(hatch=NOT_UNIFORM_HATCH["hatch"], edgecolor=NOT_UNIFORM_HATCH["edgecolor"], facecolor="white",
                 lw=0.6, label=NOT_UNIFORM_LEGEND)


def _plane_figure(results, options, plt):
    import numpy as np
    from matplotlib.lines import Line2D
    otm = next((r for r in results if r.kind == "orbit-type-map"), None)
    ms = next((r for r in results if r.kind == "map-sweep"), None)
    curves = [r for r in results if r.kind == "curve"]
    first, second = (otm or ms).first, (otm or ms).second
    for option, value, expected in (("x", options.x, first), ("y", options.y, second)):
        if value is not None and value != expected:
            raise BadInput(options.name(option), f"'{value}'", f"{expected} (a map's axes are its two parameters, "
                           f"x {first} and y {second})")
    for c in curves:
        if first not in c.rows[0] or second not in c.rows[0]:
            raise BadInput("inputs", f"'{c.name}'", f"curves with the map's parameters {first} and {second}")
    cells = _brute_cells(ms) if ms else {}
    if otm:
        key = "orbit-type-map+map-sweep" if ms else "orbit-type-map"
        panels = 2 if ms else 1
    else:
        key, panels = "map-sweep", 2
    size = options.size or DEFAULT_SIZES[key]
    fig, axes = plt.subplots(1, panels, figsize=size, dpi=100, squeeze=False)
    axes = list(axes[0])
    canvases = [Canvas(ax) for ax in axes]
    if otm:
        rect = otm.regions["rectangle"]
        extent = (rect["first_min"], rect["first_max"], rect["second_min"], rect["second_max"])
        types = sorted({" + ".join(canonical(t) for t in r["stable_types"]) or "none" for r in otm.regions["regions"]}
                       | {" + ".join(sorted(c["types"])) or "none" for c in cells.values()})
        types = [t for t in types if t != "none"]
        palette = plt.get_cmap("Pastel1").colors + plt.get_cmap("Pastel2").colors
        shade = {t: palette[k % len(palette)] for k, t in enumerate(types)}
        shade["none"] = (1.0, 1.0, 1.0)
        by_id = {r["id"]: r for r in otm.regions["regions"]}
        n = otm.regions["raster"]
        image = np.ones((n, n, 3))
        for j, row in enumerate(otm.regions["cells"]):
            for i, v in enumerate(row.split()):
                rid = int(v)
                if rid > 0:
                    image[j, i] = shade[" + ".join(canonical(t) for t in by_id[rid]["stable_types"]) or "none"]
                elif rid == -2:
                    image[j, i] = (0.85, 0.85, 0.85)
        ax, canvas = axes[0], canvases[0]
        ax.imshow(image, origin="lower", extent=extent, aspect="auto", interpolation="nearest")
        not_uniform = _hatch_regions(ax, otm, extent)
        kinds = sorted({c["kind"] for c in otm.curves.values()})
        strong = plt.get_cmap("tab10").colors
        colours = {k: strong[m % len(strong)] for m, k in enumerate(kinds)}
        for c in canvases:
            _draw_map_curves(c, otm, colours)
        for x, y, text in _map_special_points(otm):
            count = len(canvas.labels)
            canvas.mark(text, x, y, "o", "white", 5, "codimension-two point")
            if len(canvas.labels) > count:  # the short form: the types met there only
                canvas.labels[-1] = canvas.labels[-1] + (text.split(" (")[0],)
        hatched = {r["id"] for r in _not_uniform_regions(otm)}
        for r in otm.regions["regions"]:
            # A hatched region's number on white, where the hatch would cross it.
            behind = dict(bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none")) if r["id"] in hatched else {}
            ax.annotate(str(r["id"]), (r[first], r[second]), fontsize=pt(7), ha="center", va="center", color="0.3", **behind)
        start = _trace_start(otm)
        # The paper's maps are traced from its example; a [model]'s from the user's own start.
        started = "the trace's start" + (" (the paper's example)" if otm.chi_eta else "")
        for c in canvases:
            if start:
                c.mark("", *start, "*", "gold", 12, started)
        canvas.extra += [Line2D([], [], ls="", marker="s", ms=9, color=shade[t], label=f"stable: {t}") for t in types]
        if not_uniform:
            canvas.extra.append(not_uniform)
        ax.set_title(f"{'(a) ' if ms else ''}stable orbit types, from the orbit-type map {_escaped(otm.name)}", fontsize=pt(9))
        if ms:
            ax = axes[1]
            xs, ys, dx, dy, _ = _extent_of(cells)
            marks = len(xs) <= 40 and len(ys) <= 40
            for cell in cells.values():
                t = " + ".join(sorted(cell["types"])) or "none"
                colour = shade[t] if t != "none" else ((0.7, 0.7, 0.7) if cell["other"] else (1, 1, 1))
                ax.add_patch(plt.Rectangle((cell["x"] - dx / 2, cell["y"] - dy / 2), dx, dy, color=colour, lw=0))
                if cell["other"] and marks:
                    ax.plot(cell["x"], cell["y"], "x", color="0.35", ms=3, zorder=3)
            other = "x: other motions too" if marks else "grey: other motions only"
            ax.set_title(f"(b) brute force {_escaped(ms.name)} ({len(xs)} x {len(ys)} cells): stable period-1 types ({other})",
                         fontsize=pt(9))
        for ax in axes:
            ax.set_xlim(extent[0], extent[1])
            ax.set_ylim(extent[2], extent[3])
        title = f"Orbit types over ({symbol(first)}, {symbol(second)})"
    elif ms:
        xs, ys, dx, dy, extent = _extent_of(cells)
        ni, nj = len(xs), len(ys)
        index_x = {v: k for k, v in enumerate(xs)}
        index_y = {v: k for k, v in enumerate(ys)}
        count, period = np.full((nj, ni), np.nan), np.full((nj, ni), np.nan)
        sticking, unsettled = [], []
        for cell in cells.values():
            i, j = index_x[cell["x"]], index_y[cell["y"]]
            count[j, i] = len(cell["attractors"])
            moving = [a for a in cell["attractors"] if a["status"] == "periodic" and a["stops"] > 0]
            period[j, i] = max((a["period"] for a in moving), default=0)
            if any(a["sticks"] > 0 for a in moving):
                sticking.append((cell["x"], cell["y"]))
            if any(a["status"] != "periodic" for a in cell["attractors"]):
                unsettled.append((cell["x"], cell["y"]))
        for ax, values, text in ((axes[0], count, "(a) coexisting attractors"),
                                 (axes[1], period, "(b) largest period of a moving attractor (0: none)")):
            top = int(np.nanmax(values))
            image = ax.imshow(values, origin="lower", aspect="auto", extent=extent, interpolation="nearest",
                              cmap=plt.get_cmap("tab20", top + 1), vmin=-0.5, vmax=top + 0.5)
            fig.colorbar(image, ax=ax, ticks=range(0, top + 1, max(1, (top + 1) // 10)))
            ax.set_title(text, fontsize=pt(9))
        if sticking:
            axes[1].plot(*zip(*sticking), ".", color="white", ms=3, mec="black", mew=0.3)
            canvases[1].extra.append(Line2D([], [], ls="", marker=".", color="white", mec="black", mew=0.3,
                                            label="a moving attractor sticks"))
        if unsettled:
            axes[0].plot(*zip(*unsettled), "x", color="red", ms=4)
            canvases[0].extra.append(Line2D([], [], ls="", marker="x", color="red", label="a run did not settle"))
        title = f"Brute-force map over ({symbol(first)}, {symbol(second)}): {_escaped(ms.name)}"
    for ax, canvas in zip(axes, canvases):
        for c in curves:
            draw_branch(canvas, c, first, second, label_by="type")
        if options.xlim:
            ax.set_xlim(options.xlim)
        if options.ylim:
            ax.set_ylim(options.ylim)
        ax.set_xscale(options.xscale)
        ax.set_yscale(options.yscale)
        ax.set_xlabel(quantity_label(first, common_units(results)))
        ax.set_ylabel(quantity_label(second, common_units(results)))
    pairs = set(otm.chi_eta) if otm else set()
    for c in curves:
        pairs |= {(float(r["chi"]), float(r["eta"])) for r in c.rows if "chi" in r}
    if options.natural_frequencies and pairs and len(pairs) <= 2 and "omega" in (first, second):
        for canvas in canvases:
            mark_natural_frequencies(canvas, pairs, "x" if first == "omega" else "y")
    # A [model]'s, as its trace's figure marks them: its trace lists them.
    frequencies = _trace_frequencies(otm) if otm and not pairs and "omega" in (first, second) else ()
    if options.natural_frequencies and frequencies:
        for canvas in canvases:
            mark_model_frequencies(canvas, frequencies, "x" if first == "omega" else "y")
    if curves:
        title += " with " + ", ".join(_escaped(c.name) for c in curves)
    # Per-panel legends would repeat; one legend beside the last panel.
    for canvas in canvases[:-1]:
        canvases[-1].extra += [h for h in canvas.handles() if h.get_label() not in
                               [g.get_label() for g in canvases[-1].handles()]]
        canvas.markers, canvas.extra, canvas.colours, canvas.styles = {}, [], {}, {}
    _finish(fig, list(zip(axes, canvases)), options, title, below=bool(ms) and not otm)
    return fig


# ---------------------------------------------------------------- writing

# What a figure written by save() carries in its metadata (no date, no version): the mark of a file
# that `stickslip plot` may replace (check_replaceable).
MARKER = "stickslip plot"
MARKER_BYTES = {".png": b"tEXtSoftware\x00" + MARKER.encode(), ".pdf": b"/Creator (" + MARKER.encode() + b")",
                ".svg": b"<dc:title>" + MARKER.encode() + b"</dc:title>"}


def written_by_stickslip(path):
    """Whether the file at `path` is a figure save() wrote: its extension's marker in its first or
    last 64 KiB (a PNG's text chunk and an SVG's metadata lead, a PDF's Info dictionary trails)."""
    marker = MARKER_BYTES.get(os.path.splitext(path)[1].lower())
    if marker is None:
        return False
    try:
        with open(path, "rb") as f:
            head = f.read(65536)
            f.seek(0, os.SEEK_END)
            f.seek(max(0, f.tell() - 65536))
            tail = f.read(65536)
    except OSError:
        return False
    return marker in head or marker in tail


def check_replaceable(path, option="output", force=False):
    """BadInput unless `path` is new, a figure stickslip plot wrote (written_by_stickslip), or
    `force`: a figure never replaces a file of the user's (a thesis.pdf, a photo)."""
    path = os.fspath(path)
    directory = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(directory):
        raise BadInput(option, f"'{path}'", f"a file in an existing directory ('{directory}' is not one)")
    if force or not os.path.lexists(path):
        return
    if os.path.isdir(path):
        raise BadInput(option, f"'{path}'", "a file name, not a directory")
    if not written_by_stickslip(path):
        raise BadInput(option, f"'{path}'", "a new file or a figure stickslip plot wrote (its metadata names it); "
                       "this one it did not write: remove it or choose another name")


def save(fig, path, dpi=DEFAULT_DPI, option="dpi"):
    """Writes the figure to `path` (PNG, PDF or SVG by its extension), whole or not at all (a
    temporary file beside it, then renamed), without volatile metadata (dates, versions). A PNG
    of more pixels than MAX_PIXELS a side or MAX_AREA in all is BadInput (`option` names dpi)."""
    import matplotlib.pyplot as plt
    extension = os.path.splitext(path)[1].lower()
    if extension not in FORMATS:
        raise BadInput("output", f"'{path}'", "a file name ending in .png, .pdf or .svg")
    if extension == ".png":
        try:
            _check_pixels(option, f"{float(dpi):g}", float(dpi), tuple(fig.get_size_inches()))
        except BadInput:
            plt.close(fig)
            raise
    metadata = {".png": {"Software": MARKER}, ".pdf": {"Creator": MARKER, "Producer": None, "CreationDate": None},
                ".svg": {"Creator": MARKER, "Date": None}}[extension]
    directory, name = os.path.split(os.path.abspath(path))
    temporary = os.path.join(directory, f".{name}.tmp.{os.getpid()}{extension}")
    try:
        fig.savefig(temporary, dpi=dpi, metadata=metadata, format=extension[1:])
        os.replace(temporary, path)
    except OSError as e:  # named by the user's path: the temporary one is never seen
        raise CannotWrite(path, e) from None
    finally:
        plt.close(fig)
        if os.path.exists(temporary):
            os.remove(temporary)


def label_boxes(fig):
    """The display boxes of the labels placed on the figure's points, after a draw (for checks)."""
    from matplotlib.text import Text
    renderer = fig.canvas.get_renderer()
    # The text's own box (an annotation's extent would include its leader line).
    return [tuple(Text.get_window_extent(t, renderer).extents) for ax in fig.axes for t in ax.texts
            if t.get_gid() == "stickslip-label"]


def text_boxes(fig):
    """Every text of the figure that is drawn (labels, titles, axis labels, tick labels, legend
    entries) as (what, box), after a draw."""
    from matplotlib.text import Text
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    boxes = []
    # Tick labels: only of the ticks drawn (those outside the view keep stale positions).
    ticks, drawn = set(), []
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            for tick in axis.get_major_ticks() + axis.get_minor_ticks():
                ticks |= {id(tick.label1), id(tick.label2)}
            for tick in axis._update_ticks():
                drawn += [label for label in (tick.label1, tick.label2) if label.get_visible()]
    for t in [t for t in fig.findobj(lambda a: isinstance(a, Text)) if id(t) not in ticks] + drawn:
        if t.get_visible() and t.get_text().strip() and t.figure is fig:
            try:
                boxes.append((t.get_text(), tuple(Text.get_window_extent(t, renderer).extents)))
            except (RuntimeError, ValueError):
                pass
    return boxes


# ---------------------------------------------------------------- command line

OPTIONS_WITH_VALUES = ("--output", "--x", "--y", "--xscale", "--yscale", "--xlim", "--ylim", "--size", "--dpi",
                       "--title", "--legend")


def main(argv):
    values, inputs, naturals, force = {}, [], True, False
    k = 1
    try:
        while k < len(argv):
            arg = argv[k]
            if arg in OPTIONS_WITH_VALUES:
                if k + 1 >= len(argv):
                    raise BadInput(arg, "''", "a value after the option")
                values[arg[2:]] = argv[k + 1]
                k += 2
            elif arg == "--":  # every argument after it is an input (a file whose name begins with -)
                inputs += argv[k + 1:]
                break
            elif arg == "--no-natural-frequencies":
                naturals = False
                k += 1
            elif arg == "--force":
                force = True
                k += 1
            elif arg.startswith("--"):
                raise BadInput("option", f"'{arg}'",
                               "one of " + ", ".join(OPTIONS_WITH_VALUES) + ", --no-natural-frequencies, --force")
            else:
                inputs.append(arg)
                k += 1
        if "output" not in values or not inputs:
            print(__doc__, file=sys.stderr)
            return 2
        try:
            import matplotlib
        except ImportError:
            return 3  # stickslip plot says what to install
        matplotlib.use("Agg")
        options = Options(prefix="--", natural_frequencies=naturals, **values)
        check_replaceable(options.output, "--output", force)
        results = [load(path) for path in inputs]
        fig = figure(results, options)
        save(fig, options.output, options.dpi, "--dpi")
    except (BadInput, CannotWrite) as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    except Exception as e:  # noqa: BLE001 - one line, never a traceback; save() removed its temporary file
        why = " ".join(str(e).split()) or type(e).__name__
        print(f"error: the figure could not be drawn or written ({type(e).__name__}: {why}); nothing was written",
              file=sys.stderr)
        return 1
    print("wrote", options.output)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
