"""stickslip: periodic orbits of the two-degree-of-freedom dry-friction oscillator of
M. Pascal, Nonlinear Dyn. 77 (2014) 267-276, from Python.

The same computations as the command line, with the same keys and the same checks:

    import stickslip
    p = stickslip.Parameters.preset("paper-5.1")          # or Parameters(chi=..., eta=..., ...)
    sim = stickslip.simulate(p, state=(1, 0, 0, 0), phi=0, periods=2)
    orbit = stickslip.solve(preset="paper-5.1")            # -> Orbit: unknowns, margins, multipliers
    branch = stickslip.continue_orbit("omega", (0.3, 0.9), preset="paper-5.1", ds=0.005)
    branch["omega"], branch.special_points, branch.save("results/my-run")
    cont = stickslip.Continuation("omega", (0.3, 0.9), preset="paper-5.1")
    for point in cont: ...                                 # one point at a time
    sweep = stickslip.sweep(preset="paper-5.1", range=(0.55, 0.6), steps=50)
    trace = stickslip.trace("omega", (0.3, 0.69), preset="paper-4.1")  # -> Trace: Branches, ends
    trace = stickslip.trace("omega", (0.5, 0.6), start=stickslip.find(preset="paper-4.1").orbit)
    other = branch.switch("PD2", side=1)                   # the branch leaving a PD, SB or BP label
    m = stickslip.map_sweep(preset="paper-6", first_range=(0.55, 0.6), second_range=(1.2, 1.5))
    fig = branch.plot(y="peak-to-peak:x2", yscale="log")  # matplotlib Figures, as `stickslip plot`
    fig = trace.plot(); fig = sweep.plot(); fig = m.plot()
    stickslip.plot(branch, trace, sweep, output="overlay.pdf")   # several results; paths too
    trace.to_pandas()                                      # every point, measure columns included
    stickslip.describe("belt.toml")                        # an oscillator of your own: a run file's [model]
    stickslip.find(model="belt.toml", set={"v_b": 0.4})    # -> ModelFound: the orbit it settles on

Time is the paper's scaled time t; every quantity is dimensionless (eq. 3). Bad input raises
ValueError with the command line's one-line message ("<field> = <value> is invalid: <valid
range>"); a keyword of the wrong type (ds=True, tolerance="1e-6") InvalidArgument, a ValueError and
a TypeError with a message of that form; a Newton method that does not converge raises ConvergenceError, whose `summary`
attribute holds the Newton summary. Long computations release the GIL; a sweep runs its chains
on every core.
"""

import inspect as _inspect
import json as _json
from dataclasses import dataclass as _dataclass

import numpy as _np

from . import _stickslip as _core
from ._stickslip import ConvergenceError, MapSweepResult, ModelMapSweepResult, Orbit, Parameters, Signature, SweepResult
# The project's VERSION (CMakeLists.txt), as `stickslip --version` and the result files give it.
from ._stickslip import __version__
from ._branch import Branch, Continuation
from ._trace import Trace
from ._atlas import Atlas
from ._inputs import InvalidArgument, _checked, _one_off_run, _optional_text, _pair, _start, _steps
from . import plotting

__all__ = [
    "Atlas", "atlas", "Branch", "Continuation", "ConvergenceError", "InvalidArgument", "MapSweepResult", "ModelMapSweepResult", "Orbit", "Parameters", "Preset", "Signature",
    "Found", "ModelFound", "Simulation", "SweepResult", "Trace", "continue_orbit", "describe", "find", "map_sweep", "natural_frequencies",
    "plot", "plotting", "presets", "run", "simulate", "solve", "sweep", "trace", "two_parameter",
]


@_dataclass(frozen=True)
class Preset:
    """One of the paper's five examples: its data, printed initial state and phase, orbit type
    and printed durations (a starting guess; the printed numbers are rounded, see ERRATA)."""

    name: str
    equation: str
    title: str
    parameters: Parameters
    state: _np.ndarray
    phi: float
    signature: Signature
    durations: _np.ndarray


#: The paper presets by name: "paper-4.1", "paper-4.2", "paper-5.1", "paper-5.2", "paper-6".
presets = {name: Preset(**_core._preset(name)) for name in _core._preset_names()}


def _parameters_of_preset(name):
    """The data of the paper preset `name` ("paper-5.1", ...); an unknown name raises
    ValueError listing the valid ones."""
    return _core._preset(name)["parameters"]


Parameters.preset = staticmethod(_parameters_of_preset)


def _plotting_result(result, name):
    if isinstance(result, (Branch, Trace)):
        return result._plotting_result()
    if isinstance(result, (SweepResult, MapSweepResult, ModelMapSweepResult)):
        return plotting.csv_result(name, result.csv())
    return result  # a path, or a plotting result already


def plot(*results, output=None, dpi=plotting.DEFAULT_DPI, force=False, **options):
    """Several results on one figure, as `stickslip plot A B ...` overlays them: Branch, Trace,
    SweepResult, MapSweepResult, or paths of stored results (a run's, trace's or orbit-type map's
    directory, a sweep's or map-sweep's CSV). Keywords: Branch.plot's options; with output=
    "figure.png" (or .pdf, .svg) the figure is also written, at `dpi` for a PNG. Returns the
    matplotlib Figure; bad options raise ValueError naming the option, its value and the valid
    range. An existing output is replaced only if stickslip wrote it (a figure of stickslip plot),
    or with force=True; any other raises ValueError before anything is drawn."""
    named = [_plotting_result(r, f"sweep {k + 1}" if isinstance(r, SweepResult) else f"map {k + 1}")
             for k, r in enumerate(results)]
    opts = plotting.Options(dpi=dpi, output=None if output is None else str(output), **options)
    if output is not None:
        plotting.check_replaceable(str(output), "output", force)
    fig = plotting.figure(named, opts)
    if output is not None:
        plotting.save(fig, str(output), dpi)  # whole or not at all, the format of the extension
    return fig


def _result_plot(self, **options):
    """The result as a matplotlib Figure, as `stickslip plot` draws its file (a sweep: its settled
    motions' amplitude:x2 by period, or any column as y=; a map: the coexisting attractors and the
    largest period). Keywords: Branch.plot's."""
    return plotting.figure([_plotting_result(self, "sweep" if isinstance(self, SweepResult) else "map")], **options)


SweepResult.plot = _result_plot
MapSweepResult.plot = _result_plot
ModelMapSweepResult.plot = _result_plot


def natural_frequencies(parameters):
    """(omega1, omega2): the natural frequencies of the slip for `parameters` (eq. 56). The forced
    amplitude is singular there, so omega must stay away from them."""
    return parameters.natural_frequencies


class Simulation:
    """A simulated motion: `events` (t, kind, mode_before, mode_after, state (n, 4): a [model]'s
    (n, its size), named by `state_names`), `samples` (t, state, mode), `segments`, and how it ended
    (`end`, `message`, `completed`)."""

    def __init__(self, d):
        self.parameters = d["parameters"]
        self.initial_state = d["initial_state"]
        self.phi = d["phi"]
        self.events = {k: (v if isinstance(v, _np.ndarray) else _np.array(v, dtype=str)) for k, v in d["events"].items()}
        self.samples = {k: (v if isinstance(v, _np.ndarray) else _np.array(v, dtype=str)) for k, v in d["samples"].items()}
        self.segments = d["segments"]
        self.end = d["end"]
        self.message = d["message"]
        self.completed = d["completed"]
        self.state_names = d.get("state_names", ["x1", "x2", "x1'", "x2'"])

    def __repr__(self):
        return (f"<stickslip.Simulation {len(self.events['t'])} events, {len(self.samples['t'])} samples, "
                f"end {self.end}>")


_SIMULATE_DEFAULTS = _core._simulate_defaults()


def simulate(parameters=None, state=None, phi=None, *, periods=_SIMULATE_DEFAULTS["periods"],
             method=_SIMULATE_DEFAULTS["method"], samples_per_period=_SIMULATE_DEFAULTS["samples_per_period"],
             preset=None, point=None, results="results", set=None, model=None):
    """Simulate the oscillator under Coulomb's law, as `stickslip simulate`.

    parameters  Parameters (or give preset=, point= or set=)
    state       (x10, x20, v10, v20) at t = 0 (|value| <= 1e6)
    phi         forcing phase at t = 0, rad (|phi| <= 1e6)
    periods     simulated time in forcing periods 2 pi/omega (0 < periods <= 1e6)
    method      "exact" (closed-form flows, events to 1e-13 in time) or "odeint" (Boost.Odeint
                dopri5 at 1e-12, independent of the closed form)
    samples_per_period  time-series density (1 to 1e5 samples per forcing period)
    preset, point ("RUN:LABEL" under `results`), set ({key: value}): as --preset, --point, --set;
                later values win over the preset's, a key given twice is an error.
    Returns a Simulation: events and the sampled time series as NumPy arrays. A simulation that
    stops early (chattering) is returned with completed False and the reason in `message`.

    model=path: the oscillator in that run file's [model], as `stickslip simulate --model`, from its
    start (set= a dict over its parameters, start state by name and phi); its states (n, its size)
    named by `state_names`, its parameters a dict; without forcing periods count 2 pi/omega_1.
    """
    numbers = [_checked(periods, "periods", "number"), _checked(method, "method", "text"),
               _checked(samples_per_period, "samples_per_period", "number")]
    if model is not None:
        _refuse_paper_start(parameters, state, phi, preset, point, results)
        return Simulation(_core._simulate_model(_checked(model, "model", "path"), _model_set(set), *numbers))
    start = _start(parameters, state, phi, preset=preset, point=point, results=results, set=set)
    return Simulation(_core._simulate(start, *numbers))


def solve(parameters=None, signature=None, *, preset=None, point=None, results="results", set=None, guess=None,
          free=None, fix=None, tie_u_r=False, paper_choice=False, shooting="auto", linear_solver=None):
    """Solve the periodicity equations of an orbit type for one periodic orbit, as `stickslip solve`.

    parameters  Parameters of the model (or preset=, point=, set=)
    signature   an orbit type: Signature or its text ("slip- slip+ stick slip+", "... / antisymmetric")
    guess       {name: value} starting values of any orbit variable: x10 x20 v10 phi d1..dn (durations,
                scaled time, >= 0) chi eta omega u_s u_r
    free        variables released as unknowns (usually a parameter), a name or a list
    fix         variables held: a list of names (held at their guess) or {name: value}
    tie_u_r     hold u_r = u_s (abnormal stops need it, eq. 25)
    paper_choice  with preset: the paper's own choice of unknowns (see ERRATA)
    shooting    "auto", "single" or "multiple"; linear_solver "klu" (default), "umfpack" or "dense"
                where multiple shooting is used (refused with shooting="single", where it is not)
    Returns an Orbit. Raises ConvergenceError if Newton does not converge. A converged orbit that is
    not a motion (a margin <= 0, orbit.admissible False) or fails its verification is returned: the
    command line exits 4 for it. point="RUN:LABEL" under results= may be a [model]'s label (no other
    start keyword then): its orbit solved again at the label's parameters, as a ModelFound (as
    find(model=) returns it; `stickslip solve --point` prints the same).
    """
    if point is not None and _core._holds_model_point(str(_checked(results, "results", "path")),
                                                      _optional_text(point, "point", "a str, a stored point 'RUN:LABEL'")):
        given = [name for name, value in (("parameters", parameters), ("signature", signature), ("preset", preset),
                                          ("set", set), ("guess", guess), ("free", free), ("fix", fix),
                                          ("tie_u_r", tie_u_r or None), ("paper_choice", paper_choice or None))
                 if value is not None]
        if given:
            raise ValueError(f"{given[0]} is invalid with a [model]'s point: valid left out (the label gives the "
                             "model, its parameters and the orbit)")
        return ModelFound(**_json.loads(_core._solve_model_label(str(results), point, _checked(shooting, "shooting", "text"),
                                                                 _optional_text(linear_solver, "linear_solver"))))
    start = _start(parameters, preset=preset, point=point, results=results, set=set, signature=signature,
                   guess=guess, free=free, fix=fix, tie_u_r=tie_u_r, paper_choice=paper_choice)
    return _core._solve(start, _checked(shooting, "shooting", "text"), _optional_text(linear_solver, "linear_solver"))


@_dataclass(frozen=True)
class Found:
    """What stickslip.find found: `status` ("found", "not-periodic", "no-orbit-type",
    "simulation-incomplete", "solve-failed", "not-a-motion") and `message`; the period multiple k
    (0 when none repeats), the section mismatch, whether the motion is antisymmetric, the transient
    periods simulated; the orbit type read off the motion (`signature`), and the solved `orbit`
    (an Orbit, as solve returns it) when Newton converged."""
    status: str
    message: str
    transient_periods: int
    period_multiple: int
    mismatch: float
    closest_multiple: int
    antisymmetric: bool
    signature: object
    orbit: object

    @property
    def found(self):
        return self.status == "found"


@_dataclass(frozen=True)
class ModelFound:
    """What stickslip.find(model=...) found for an oscillator of your own: `status` and `message` as
    Found's, the orbit type read off the motion (`signature`, a str, or None), and the solved `orbit`
    when Newton converged: a dict with the keys of `stickslip find --model --json` (signature, units,
    parameters, period, phi, start by the model's names (x1_0, v1_0 for x1; m1_0, v_m1_0 for m1), durations, margins,
    admissible, multipliers, stable, measures per coordinate, verification)."""
    status: str
    message: str
    signature: object
    orbit: object

    @property
    def found(self):
        return self.status == "found"


def describe(path):
    """The oscillator of a run file's [model] table, as `stickslip describe --json`: a dict with its
    model, kind, coordinates, contact, forcing, friction_slope, units (length, time, force),
    parameters (name, meaning, unit, minimum, maximum, range, value), autonomous, free_oscillations
    (slip, stick) and start_state."""
    return _json.loads(_core._describe_model(_checked(path, "path", "path")))


def _find_model(model, set, transients, max_multiple):
    found = _json.loads(_core._find_model(_checked(model, "model", "path"), _model_set(set),
                                          _checked(transients, "transients", "number"),
                                          _checked(max_multiple, "max_multiple", "number")))
    return ModelFound(**found)


def _model_set(set):
    given = {} if set is None else set
    if not isinstance(given, dict):
        raise InvalidArgument(f"set = {set!r} is invalid: valid range a dict of name: number")
    return [(_checked(name, "set", "text"), _checked(value, name, "number")) for name, value in given.items()]

def _refuse_paper_start(parameters, state, phi, preset, point, results, others=()):
    """With model=: the paper's start arguments (and `others`, names of arguments given that the
    model's path does not take) raise ValueError naming the first one."""
    given = [name for name, value in (("parameters", parameters), ("state", state), ("phi", phi), ("preset", preset),
                                      ("point", point)) if value is not None]
    given += ["results"] if results != "results" else []
    given += list(others)
    if given:
        raise ValueError(f"{given[0]} is invalid with model=: valid left out (the model's run file gives the "
                         "oscillator and its start; set= its parameters, start state by name and phi)")



def _trace_model(parameter, range, options, *, model, set=None, transients=1000, ds=None, ds_min=None, ds_max=None,
                 max_points=None, **others):
    if others:
        raise TypeError(f"trace() got an unexpected keyword argument '{next(iter(others))}' with model= (it takes "
                        "set=, transients=, ds=, ds_min=, ds_max= and max_points=)")
    low, high = _pair(range, "range")
    steps = _steps(ds, ds_min, ds_max, max_points)
    text, stored = _core._trace_model(_checked(model, "model", "path"), _model_set(set),
                                      _checked(transients, "transients", "number"),
                                      _checked(parameter, "parameter", "text"), low, high, options, steps)
    return ModelTrace(_json.loads(text), stored)


class ModelTrace(dict):
    """trace(model=...)'s result: the JSON of `stickslip find --model --trace --json` as a dict:
    "parameter", "start" (the orbit found, as find(model=) gives it), "completed" (True when both
    directions ran to their ends, whatever those were; False when a branch failed or none started),
    "down" and "up" (each its "end", "message" and "branches", every point's columns by name).
    .trace is the same trace as a Trace (plot(), to_pandas(), files()); None where no branch started."""

    def __init__(self, printed, stored):
        super().__init__(printed)
        self._stored = stored

    def __reduce__(self):
        # A copy or a pickle is the dict: the stored trace it would save is a C++ object.
        return (dict, (dict(self),))

    @property
    def trace(self):
        """The trace as a Trace, as Trace.load reads it back after save(); None where no branch started."""
        return None if self._stored is None else Trace(self._stored)

    def plot(self, **options):
        """The trace's response as Trace.plot draws it (its keywords); ValueError where no branch started."""
        if self._stored is None:
            raise ValueError("the trace has no branch to plot (no branch started)")
        return Trace(self._stored).plot(**options)

    def save(self, directory):
        """Writes the trace's files into `directory` as `stickslip find --model --trace --output`
        writes them (branch-<k>/, trace.csv, trace.json; the directory's name becomes the output
        name); other files in it are kept and their names returned. A directory that holds neither a
        stickslip trace nor a run raises ValueError, and nothing is touched; a trace whose every
        branch failed to start raises ValueError."""
        if self._stored is None:
            raise ValueError("the trace has no branch to write (no branch started)")
        return self._stored.save(_checked(directory, "directory", "path"))


_FIND_DEFAULTS = _core._find_defaults()


def find(parameters=None, state=None, phi=None, *, transients=_FIND_DEFAULTS["transients"],
         max_multiple=_FIND_DEFAULTS["max_multiple"], tolerance=_FIND_DEFAULTS["tolerance"],
         confirmations=_FIND_DEFAULTS["confirmations"], preset=None, point=None, results="results", set=None, model=None):
    """From a simulated motion to its exact periodic orbit, as `stickslip find`.

    model: a run file with a [model] table (an oscillator of your own, as `stickslip find --model`):
    its motion from rest simulated for `transients` periods (2 to 1e5: forcing periods; without
    forcing, periods of its slowest free oscillation), its last period (the least of 1 to
    max_multiple forcing periods, 1 to 20, that is one) read from a stop, solved and verified; `set`
    a dict of its parameters over the file's, its start state by name (x1_0, v1_0, ...) and the
    forcing phase phi at t = 0; returns a ModelFound. With `model`, tolerance and confirmations
    must stay at their defaults.

    Simulates `transients` forcing periods (0 to 1e6; more while the motion has not settled), finds
    the smallest k <= max_multiple (1 to 999) after which the stroboscopic section repeats to
    `tolerance` (relative, 1e-12 to 1e-2) over `confirmations` (1 to 100) more periods of k T, reads
    the orbit type, durations, phase and state off one period, solves the periodicity equations and
    verifies the orbit by both simulators. parameters, state, phi, preset, point, set: as simulate.
    Returns a Found; every numerical outcome is its status (the command line's exit codes 0, 1, 3,
    4, 5). Bad input raises ValueError.
    """
    if model is not None:
        _refuse_paper_start(parameters, state, phi, preset, point, results,
                            [name for name, value, default in (("tolerance", tolerance, 1e-6),
                                                               ("confirmations", confirmations, 3)) if value != default])
        return _find_model(model, set, transients, max_multiple)
    start = _start(parameters, state, phi, preset=preset, point=point, results=results, set=set)
    numbers = [_checked(value, name, "number") for name, value in (("transients", transients), ("max_multiple", max_multiple),
                                                                  ("tolerance", tolerance), ("confirmations", confirmations))]
    return Found(**_core._find(start, *numbers))


def continue_orbit(parameter, range, **keywords):
    """Continue a periodic orbit in `parameter` over `range` = (min, max), as `stickslip continue`
    (the keys of a run file's [continuation] table as keywords; left out, the engine's defaults).

    parameter   the continued variable: omega, u_r, u_s, chi, eta (or any held orbit variable)
    direction   "up" or "down"
    output      the run's name, recorded in summary.json (save() records its directory's name)
    ds, ds_min, ds_max  initial, smallest and largest arclength step (0 < ds_min <= ds <= ds_max)
    max_points  accepted points (1 to 1e6)
    shooting, linear_solver, detect_folds, detect_branch_points, continue_past_type_changes: as in
                run files
    max_amplitude   a resonance ends the branch at its first point where max |x1|, |x2| over the
                orbit (scaled displacement) passes this (finite, > 0; default 1e3)
    resonance_approach  and a branch of orbits that never stick at its first point within this
                (relative, 0 to 1; default 0.01; 0: never) of a natural frequency of the undamped
                slip that it approaches
    user_values     values of the parameter at which to record a UZ point
    user_values_of  {variable: [values]}: UZ points of other unknowns
    switch_branch   with point="RUN:LABEL" at a PD or an SB: the branch that leaves the point (the
                run file's restart = { ..., switch_branch = true }), on the side `direction` names
                ("up" +1, "down" -1); single shooting. Branch.switch does the same from a branch in
                memory, also at a BP.
    boundary    with point="RUN:LABEL" at a change of type: the type boundary there (its margin
                = 0), continued in `parameter` and this second parameter (the run file's
                restart = { ..., boundary = "u_r" }); two_parameter() says it in its own words.
    start       an Orbit (solve()'s, or find().orbit): the start, with the orbit's own unknowns;
                or the start keywords of solve() instead. point="RUN:LABEL" under results= may be
                a [model]'s label too (its model from the run file its summary names; no other start
                keyword then), as `stickslip continue --point` takes it.
    Returns a Branch; raises ConvergenceError if the start does not converge, ValueError for bad
    input (the command line's message).
    """
    return Branch(_core._continue(_one_off_run(parameter, range, **keywords)))


continue_orbit.__signature__ = _inspect.signature(_one_off_run)


def two_parameter(parameter, second, range, *, point, **keywords):
    """The type boundary at a stored change of type, continued in two parameters: from
    point="RUN:LABEL" at a located type change (SK, T0, GR, NS: its margin, e.g. reversal:1,
    G:3, velocity:2), the orbit of the located type with that margin held at zero (for an
    interior extremum, velocity or G/G1 inside the stick, also its time), `second` (a parameter
    of the model: chi, eta, u_s, u_r, omega for the paper's, omega, F_k, F_s, v_b for a [model];
    not `parameter`) released, continued in `parameter` over `range` =
    (min, max). The other keywords are continue_orbit's. Returns a Branch whose points lie on the
    boundary (the curve in the plane of the two is branch[parameter], branch[second]); it ends
    where a second margin reaches zero (a codimension-two point), at the range, or where `second`
    leaves its valid range (a static level at the held kinetic one). Refused: a slip's duration
    and sliding-friction (no regular curve).
    """
    if not isinstance(second, str) or not second:
        raise ValueError(f"second = {second!r} is invalid: valid the name of a parameter of the model, not `parameter`")
    return continue_orbit(parameter, range, point=point, boundary=second, **keywords)

_TRACE_DEFAULTS = _core._trace_defaults()
# The keywords of continue_orbit that a trace does not take: it goes both ways and decides at every
# change of type.
_NOT_TRACE_KEYWORDS = ("direction", "continue_past_type_changes", "switch_branch", "boundary")


def trace(parameter, range, *, max_branches=_TRACE_DEFAULTS["max_branches"],
          max_amplitude=_TRACE_DEFAULTS["max_amplitude"], loop_tolerance=_TRACE_DEFAULTS["loop_tolerance"],
          follow_past_unswitched=_TRACE_DEFAULTS["follow_past_unswitched"],
          follow_bifurcations=_TRACE_DEFAULTS["follow_bifurcations"],
          allow_inadmissible=_TRACE_DEFAULTS["allow_inadmissible"], **keywords):
    """Follow the chain of orbit branches through every change of orbit type, both ways from the
    start within `range`, as `stickslip trace`: at each change the adjacent types are tried and the
    one confirmed by simulation is continued.

    max_branches    branches per direction (1 to 1e4)
    max_amplitude   a resonance ends a direction where max |x1|, |x2| over the orbit (scaled
                    displacement, exact) passes this (> 0)
    loop_tolerance  the chain has come back to a point it visited when the signature agrees and
                    the parameter (relative), start state, phase and period differ by at most this
                    (0 < loop_tolerance <= 1e-2)
    follow_past_unswitched  at a change of type that switches nowhere, follow the same type on past
                    it (not a motion there, admissible 0) instead of ending the direction
    follow_bifurcations  how many of the branches met at BP, PD and SB to follow, in the order met,
                    each as one branch (0 to 1e4; the others are recorded only)
    allow_inadmissible  trace from a start that is not a motion of the system (a margin < 0 there:
                    admissible 0) instead of refusing it (ValueError, as the command line exits 4)
    The other keywords are continue_orbit's but direction, continue_past_type_changes and
    switch_branch (the range bounds the whole trace; ds, max_points, ... apply to every branch):
    start=found.orbit traces from an orbit find() found, as `stickslip find --trace` does;
    point="RUN:LABEL" under results= from a label of any run, a [model]'s too (its model from the
    run file its summary names; no other start keyword then), as `stickslip trace --point` does.
    Returns a Trace whatever its directions' ends (see trace.ends); raises ConvergenceError when no
    branch started, ValueError for bad input (the command line's message) and for a start that is
    not a motion without allow_inadmissible.

    model=path (with set= a dict over the file's parameters and transients=, as find(model=...)):
    an oscillator of your own traced in one of its parameters (omega, F_k, F_s, v_b) from the orbit
    its motion from rest settles on, as `stickslip find --model path --trace LO,HI --trace-parameter
    NAME --json`; returns that JSON as a dict, a ModelTrace (start: the orbit found; completed; down,
    up: their end, message and branches, each with every point's columns by name), whose
    save(directory) writes the files --output writes (stickslip.Trace.load reads them back), whose
    plot() draws it and whose .trace is it as a Trace. Of continue_orbit's keywords only the steps
    of every branch are taken with it: ds, ds_min, ds_max and max_points.
    """
    options = {"max_branches": _checked(max_branches, "max_branches", "count"),
               "max_amplitude": _checked(max_amplitude, "max_amplitude", "number"),
               "loop_tolerance": _checked(loop_tolerance, "loop_tolerance", "number"),
               "follow_past_unswitched": _checked(follow_past_unswitched, "follow_past_unswitched", "flag"),
               "follow_bifurcations": _checked(follow_bifurcations, "follow_bifurcations", "count"),
               "allow_inadmissible": _checked(allow_inadmissible, "allow_inadmissible", "flag")}
    if "model" in keywords:
        return _trace_model(parameter, range, options, **keywords)
    for key in _NOT_TRACE_KEYWORDS:
        if key in keywords:
            raise TypeError(f"trace() got an unexpected keyword argument '{key}' (a trace goes both ways)")
    return Trace(_core._trace(_one_off_run(parameter, range, **keywords), options))


def run(path, results="results"):
    """Run a run file (TOML, continuation-scripts/), as `stickslip run`, without writing: returns the
    Branch, or the Trace of a run file with a [trace] table; result.save(f"{results}/{result.output}")
    writes the files `stickslip run` writes. Restart points are read from `results`."""
    run_input = _core._run_file(_checked(path, "path", "path"), _checked(results, "results", "path"))
    if run_input.is_trace:
        return Trace(_core._trace(run_input, None))
    return Branch(_core._continue(run_input))


_SWEEP_DEFAULTS = _core._sweep_defaults()


def sweep(parameters=None, state=None, phi=None, *, range, parameter=_SWEEP_DEFAULTS["parameter"],
          steps=_SWEEP_DEFAULTS["steps"], transients=_SWEEP_DEFAULTS["transients"],
          periods=_SWEEP_DEFAULTS["periods"], start=_SWEEP_DEFAULTS["start"], chains=_SWEEP_DEFAULTS["chains"],
          scatter=_SWEEP_DEFAULTS["scatter"], seed=_SWEEP_DEFAULTS["seed"], threads=_SWEEP_DEFAULTS["threads"],
          preset=None, point=None, results="results", set=None, model=None):
    """A brute-force bifurcation diagram by simulation, as `stickslip sweep`.

    range       (from, to) of `parameter` (chi, eta, omega, u_s or u_r), in its valid range
    steps       intervals between from and to (1 to 1e5)
    transients  forcing periods simulated and discarded at each point (0 to 1e6)
    periods     forcing periods recorded at each point (1 to 1e5)
    start       "chained" (up then down, each point from the last state) or "fixed" (every point
                from its chain's start, one pass)
    chains      starting states, the first the given one (1 to 1e4); scatter: half-width of the
                box the others are drawn from (0 to 1e6); seed (0 to 1e9)
    threads     0: every core (0 to 1024); the result does not depend on it
    The section is taken at the forcing phase phi. Returns a SweepResult with NumPy arrays;
    result.csv() is the file `stickslip sweep --output` writes.

    model: a run file with a [model] table (an oscillator of your own, as `stickslip sweep --model`):
    `parameter` one of its parameters (omega, F_k, F_s, v_b), `set` a dict of them over the file's;
    the chains start from rest (or set='s start state and phi) and from states scattered around it,
    the section at that forcing phase;
    section has the model's state size, the CSV its column names. A model without forcing (a belt) is
    read on its stick-entry section (per stick-slip cycle; a steady slide has period 1, no stop).
    """
    low, high = _pair(range, "range")
    numbers = {"steps": steps, "transients": transients, "periods": periods, "chains": chains, "scatter": scatter,
               "seed": seed, "threads": threads}
    options = {"parameter": _checked(parameter, "parameter", "text"), "from": low, "to": high,
               "start": _checked(start, "start", "text"),
               **{name: _checked(value, name, "number") for name, value in numbers.items()}}
    if model is not None:
        _refuse_paper_start(parameters, state, phi, preset, point, results)
        return _core._sweep_model(_checked(model, "model", "path"), _model_set(set), options)
    origin = _start(parameters, state, phi, preset=preset, point=point, results=results, set=set)
    return _core._sweep(origin, options)


_MAP_DEFAULTS = _core._map_sweep_defaults()


def map_sweep(parameters=None, state=None, phi=None, *, first_range, second_range, first=None, second=None,
              first_steps=_MAP_DEFAULTS["first_steps"], second_steps=_MAP_DEFAULTS["second_steps"],
              transients=_MAP_DEFAULTS["transients"], periods=_MAP_DEFAULTS["periods"], starts=_MAP_DEFAULTS["starts"],
              scatter=_MAP_DEFAULTS["scatter"], seed=_MAP_DEFAULTS["seed"], tolerance=_MAP_DEFAULTS["tolerance"],
              threads=_MAP_DEFAULTS["threads"], preset=None, point=None, results="results", set=None, model=None):
    """The brute-force map of motions over two parameters, as `stickslip map-sweep`.

    first, second   the parameters stepped along i and along j (chi, eta, omega, u_s, u_r; different;
                    unless given omega and u_r)
    first_range, second_range  (from, to) of each, in the parameter's valid range (every cell is
                    checked: u_r >= u_s, away from the natural frequencies)
    first_steps, second_steps  intervals along i and j (0 to 1e4): (steps + 1) cells each
    transients      forcing periods discarded per run (0 to 1e6)
    periods         forcing periods recorded per run (2 to 1e5): periods up to half of it are found
    starts          starts per cell besides rest and the neighbour cell's end (0 to 1000): the given
                    state (state=, the preset's; rest if none) and states scattered around it
    scatter         half-width of the box the scattered starts are drawn from (0 to 1e6); seed (0 to 1e9)
    tolerance       section points repeat, and two runs' orbits agree, within this (absolute, max
                    norm; 1e-14 to 1e-2)
    threads         0: every core (0 to 1024); the map does not depend on it
    The section is taken at the forcing phase phi (time 0 of every run). Returns a MapSweepResult:
    per cell and per attractor NumPy arrays; result.csv() / result.save(path) is the file
    `stickslip map-sweep --output` writes. The GIL is released while the map is computed.

    model: a run file with a [model] table (an oscillator of your own, as `stickslip map-sweep
    --model`): first and second name its parameters (unless given omega, v_b without forcing, and
    F_s), set= a dict over the file's parameters and start (x1_0=..., phi=...), scatter and
    tolerance in its units (tolerance relative to the section states' size). Returns a
    ModelMapSweepResult: its attractors carry 'amplitude:<contact>' where the paper's carry
    'signature', their sections the model's state size.
    """
    first_from, first_to = _pair(first_range, "first_range")
    second_from, second_to = _pair(second_range, "second_range")
    numbers = {"first_steps": first_steps, "second_steps": second_steps, "transients": transients, "periods": periods,
               "starts": starts, "scatter": scatter, "seed": seed, "tolerance": tolerance, "threads": threads}
    options = {"first": "" if first is None else _checked(first, "first", "text"),
               "second": "" if second is None else _checked(second, "second", "text"),
               "first_from": first_from, "first_to": first_to, "second_from": second_from, "second_to": second_to,
               **{name: _checked(value, name, "number") for name, value in numbers.items()}}
    if model is not None:
        _refuse_paper_start(parameters, state, phi, preset, point, results)
        return _core._map_sweep_model(_checked(model, "model", "path"), _model_set(set), options)
    options["first"] = _MAP_DEFAULTS["first"] if first is None else options["first"]
    options["second"] = _MAP_DEFAULTS["second"] if second is None else options["second"]
    origin = _start(parameters, state, phi, preset=preset, point=point, results=results, set=set)
    return _core._map_sweep(origin, options)


_ATLAS_DEFAULTS = _core._atlas_defaults()


def atlas(parameter, range, parameters=None, state=None, phi=None, *, steps=_ATLAS_DEFAULTS["steps"],
          transients=_ATLAS_DEFAULTS["transients"], periods=_ATLAS_DEFAULTS["periods"], starts=_ATLAS_DEFAULTS["starts"],
          scatter=_ATLAS_DEFAULTS["scatter"], seed=_ATLAS_DEFAULTS["seed"], tolerance=_ATLAS_DEFAULTS["tolerance"],
          max_multiple=_ATLAS_DEFAULTS["max_multiple"], max_amplitude=_ATLAS_DEFAULTS["max_amplitude"],
          max_points=_ATLAS_DEFAULTS["max_points"], resonance_approach=_ATLAS_DEFAULTS["resonance_approach"],
          threads=_ATLAS_DEFAULTS["threads"], output="atlas", preset=None, point=None, results="results", set=None,
          model=None):
    """Every periodic motion over `range` = (min, max) of `parameter` (chi, eta, omega, u_s, u_r), as
    `stickslip atlas`: a brute force on steps + 1 grid values (rest, the neighbouring value's
    attractor and `starts` scattered states around the given state at each; transients, periods,
    scatter, seed, tolerance as map_sweep's), the exact orbit of every attractor of period up to
    max_multiple (1 to 100; find, whose transient doubles until the motion has settled), and a trace
    over the whole range from each exact orbit on no branch yet, from its mirror image, and from every
    confirmed adjacent type a trace did not take (max_amplitude ends a trace at a resonance, max_points
    (1 to 1e6) bounds each of its branches, resonance_approach (0 <= . < 1, 0: never) ends a branch of
    orbits that never stick that near a natural frequency of the undamped slip it approaches).
    parameters, state, phi, preset, point, set: as simulate; output: the name atlas.json records.
    Returns an Atlas whatever it found (every attractor on a branch or listed with the reason); bad
    input raises ValueError. The GIL is released while it runs; the result does not depend on threads.

    model=path: the atlas of the oscillator in that run file's [model] (set= a dict over its
    parameters), as `stickslip atlas --model`: parameter one of the model's (omega, F_k, F_s, v_b),
    scatter in its units around its start, tolerance relative; without forcing read on the
    stick-entry section; mirror images traced where the model has the symmetry (v_b = 0).
    """
    if model is None:
        origin = _start(parameters, state, phi, preset=preset, point=point, results=results, set=set)
    else:
        _refuse_paper_start(parameters, state, phi, preset, point, results)
    low, high = _pair(range, "range")
    numbers = {"steps": steps, "transients": transients, "periods": periods, "starts": starts, "scatter": scatter,
               "seed": seed, "tolerance": tolerance, "threads": threads, "max_multiple": max_multiple,
               "max_amplitude": max_amplitude, "max_points": max_points,
               "resonance_approach": resonance_approach}
    options = {"parameter": _checked(parameter, "parameter", "text"), "from": low, "to": high,
               **{name: _checked(value, name, "number") for name, value in numbers.items()}}
    output = _checked(output, "output", "text")
    if model is not None:
        return Atlas(_core._model_atlas(_checked(model, "model", "path"), _model_set(set), options, output))
    return Atlas(_core._atlas(origin, options, output))

