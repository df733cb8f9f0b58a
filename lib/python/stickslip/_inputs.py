"""The inputs of every computation, as the command line's options: the start (--preset, --point,
--set, --signature, --guess, --free, --fix, --tie-u_r) as the dict the compiled core takes, and a
continuation run given by keywords (`stickslip continue`'s, and a run file's [continuation] keys)."""

import numbers as _numbers

import numpy as _np

from . import _stickslip as _core
from ._stickslip import Orbit, Parameters

_DEFAULTS = _core._continuation_defaults()
_INITIAL_STATE = tuple(_core._initial_state())  # the model's state at t = 0 by name


def _number(value, field):
    """`value` as a float; TypeError naming `field` for anything not a real number (a bool is not
    one, though float(True) is 1.0; a str is not one, though float("0.5") is 0.5)."""
    if isinstance(value, bool) or not isinstance(value, _numbers.Real):
        raise TypeError(f"{field} must be a number, got {type(value).__name__} {value!r}")
    return float(value)


def _flag(value, field):
    """`value` as a bool; TypeError naming `field` for anything else (bool('no') is True, so a str
    would silently switch the option on)."""
    if not isinstance(value, bool):
        raise TypeError(f"{field} must be True or False, got {type(value).__name__} {value!r}")
    return value


def _text(value, field, valid):
    """`value` as the str the core takes, None as ""; TypeError naming `field` for any other type
    (the core's own conversion would raise pybind11's RuntimeError, naming no keyword)."""
    if value is None:
        return ""
    if not isinstance(value, str):
        raise TypeError(f"{field} must be a str ({valid}), got {type(value).__name__} {value!r}")
    return value


def _named_values(values, field):
    if values is None:
        return []
    if not isinstance(values, dict):
        raise TypeError(f"{field} must be a dict of name: value, got {type(values).__name__}")
    return [(str(name), _number(value, f"{field}[{name!r}]")) for name, value in values.items()]


def _start(parameters=None, state=None, phi=None, *, preset=None, point=None, results="results", set=None,
           signature=None, guess=None, free=None, fix=None, tie_u_r=False, paper_choice=False):
    pairs = []
    if parameters is not None:
        if not isinstance(parameters, Parameters):
            raise TypeError(f"parameters must be a stickslip.Parameters, got {type(parameters).__name__}")
        pairs += list(parameters.as_dict().items())
    if state is not None:
        values = [float(x) for x in _np.asarray(state, dtype=float).ravel()]
        if len(values) != len(_INITIAL_STATE):
            raise TypeError(f"state must hold ({', '.join(_INITIAL_STATE)}), got {len(values)} values")
        pairs += list(zip(_INITIAL_STATE, values))
    if phi is not None:
        pairs.append(("phi", float(phi)))
    pairs += _named_values(set, "set")
    if isinstance(free, str):
        free = [free]
    fixes = []
    if isinstance(fix, str):
        fix = [fix]
    if isinstance(fix, dict):
        fixes = [(str(k), None if v is None else float(v)) for k, v in fix.items()]
    elif fix is not None:
        fixes = [(str(k), None) for k in fix]
    return {
        "preset": _text(preset, "preset", "a paper preset's name: " + ", ".join(_core._preset_names())),
        "point": _text(point, "point", "a stored point 'RUN:LABEL'"), "results": str(results),
        "signature": "" if signature is None else str(signature),
        "set": pairs, "guess": _named_values(guess, "guess"), "free": [str(f) for f in (free or [])],
        "fix": fixes, "tie_u_r": _flag(tie_u_r, "tie_u_r"),
        "paper_choice": _flag(paper_choice, "paper_choice"),
    }


def _orbit_start(orbit, results, others):
    """The start that gives `orbit` (an Orbit of solve() or find()) back: its type, its parameters as
    set, its state, phase and durations as guess, and its own unknowns (free, fix, tie_u_r)."""
    if not isinstance(orbit, Orbit):
        raise TypeError(f"start must be a stickslip.Orbit (solve()'s, or find().orbit), got {type(orbit).__name__}")
    given = [name for name, value in others.items() if value not in (None, False)]
    if given:
        raise TypeError(f"start= is the whole start: {given[0]}= cannot be given with it")
    # The start state, phi and the durations are unknowns unless fixed, the parameters only if
    # released (the start builder's rule, FreeIndices).
    always = _core._orbit_start_variables(len(orbit.durations))
    unknowns = orbit.unknowns
    return _start(orbit.parameters, results=results, signature=orbit.signature,
                  guess={name: orbit.variables[name] for name in always},
                  free=[name for name in unknowns if name not in always],
                  fix=[name for name in always if name not in unknowns], tie_u_r=orbit.tie_u_r)


def _one_off_run(parameter, range, *, direction="up", output="python", start=None, parameters=None, signature=None,
                 preset=None, point=None, switch_branch=False, boundary=None, results="results", set=None, guess=None,
                 free=None, fix=None, tie_u_r=False, ds=None,
                 ds_min=None, ds_max=None, max_points=None, shooting=None, linear_solver=None, detect_folds=None,
                 detect_branch_points=None, continue_past_type_changes=None, max_amplitude=None, user_values=(),
                 user_values_of=None):
    """The run `stickslip continue` makes of its options (checked by the library, as there)."""
    if range is None or len(range) != 2:
        raise TypeError("range must be (min, max)")
    given = {"ds": ds, "ds_min": ds_min, "ds_max": ds_max, "max_points": max_points, "shooting": shooting,
             "linear_solver": linear_solver, "detect_folds": detect_folds,
             "detect_branch_points": detect_branch_points, "continue_past_type_changes": continue_past_type_changes,
             "max_amplitude": max_amplitude}
    options = {key: (_DEFAULTS[key] if value is None else value) for key, value in given.items()}
    options.update({
        "parameter": str(parameter), "range": (float(range[0]), float(range[1])), "direction": str(direction),
        "output": str(output), "results": str(results), "linear_solver_given": linear_solver is not None,
        "switch_branch": switch_branch, "boundary": "" if boundary is None else str(boundary),
        "user_values": [float(v) for v in user_values],
        "user_values_of": {str(k): [float(v) for v in vs] for k, vs in (user_values_of or {}).items()},
    })
    if start is not None:
        others = dict(parameters=parameters, signature=signature, preset=preset, point=point, set=set, guess=guess,
                      free=free, fix=fix, tie_u_r=tie_u_r)
        return _core._one_off_run(_orbit_start(start, results, others), options)
    begin = _start(parameters, preset=preset, point=point, results=results, set=set, signature=signature,
                   guess=guess, free=free, fix=fix, tie_u_r=tie_u_r)
    return _core._one_off_run(begin, options)
