"""The inputs of every computation, as the command line's options: the start (--preset, --point,
--set, --signature, --guess, --free, --fix, --tie-u_r) as the dict the compiled core takes, and a
continuation run given by keywords (`stickslip continue`'s, and a run file's [continuation] keys)."""

import numbers as _numbers
import os as _os

import numpy as _np

from . import _stickslip as _core
from ._stickslip import Orbit, Parameters, Signature

_DEFAULTS = _core._continuation_defaults()
_INITIAL_STATE = tuple(_core._initial_state())  # the model's state at t = 0 by name


class InvalidArgument(TypeError, ValueError):
    """A keyword argument of the wrong type (ds=True, tolerance="1e-6", output=5): a TypeError, as
    Python has it, and a ValueError, the module's error for every bad input, so that `except
    ValueError` catches them all. The message is the library's: "<field> = <value> is invalid:
    valid range <what it must be>"."""


# What each kind of keyword argument must be, as the messages say it.
_KINDS = {
    "number": "a number (int or float, not bool) of magnitude below 1.8e308",
    "count": "a whole number (int, or a float without a fraction; not bool)",
    "index": "an int (not bool) of magnitude below 2**31",
    "flag": "True or False",
    "text": "a str",
    "path": "a str or an os.PathLike path",
}


def _checked(value, field, kind, valid=None):
    """The one check of a keyword argument's type, for every function of the module: `value` as the
    compiled core takes it (a float for "number"; for "count" the value itself, whose range the
    library states; an int for "index"; a bool for "flag"; a str for "text" and "path"), or
    InvalidArgument naming
    `field`, the value and `valid` (by default what the kind must be). A bool is no number though
    float(True) is 1.0, a str none though float("1e-6") is 1e-06, and bool("no") is True: each
    would pass a wrong value on silently; an int beyond a double raised OverflowError."""
    if kind == "flag" and isinstance(value, bool):
        return value
    if kind == "text" and isinstance(value, str):
        return value
    if kind == "index" and isinstance(value, _numbers.Integral) and not isinstance(value, bool) and abs(value) < 2**31:
        return int(value)
    if kind == "path" and isinstance(value, (str, _os.PathLike)) and isinstance(_os.fspath(value), str):
        return _os.fspath(value)
    if kind in ("number", "count") and isinstance(value, _numbers.Real) and not isinstance(value, bool):
        if kind == "count":
            return value
        try:
            return float(value)
        except OverflowError:
            pass
    raise InvalidArgument(f"{field} = {value!r} is invalid: valid range {valid or _KINDS[kind]}")


def _optional_text(value, field, valid=None):
    """A str keyword that may be left out: None as ""."""
    return "" if value is None else _checked(value, field, "text", valid)


def _boundary(value):
    """A curve's second parameter: a name, or None for no curve. An empty name is refused (as
    --boundary ''), not taken as no curve."""
    name = _optional_text(value, "boundary")
    if value is not None and not name:
        raise ValueError("boundary = '' is invalid: valid the name of a second parameter to release, or None")
    return name


def _numbers_of(values, field, valid="a sequence of numbers (int or float, not bool) of magnitude below 1.8e308"):
    """A sequence of numbers (not a str), named whole in a message."""
    try:
        if isinstance(values, (str, bytes)) or not hasattr(values, "__iter__"):
            raise InvalidArgument()
        return [_checked(v, field, "number") for v in values]
    except InvalidArgument:
        raise InvalidArgument(f"{field} = {values!r} is invalid: valid range {valid}") from None


def _pair(values, field):
    """(low, high): two numbers."""
    numbers = _numbers_of(values, field, "(min, max), two numbers")
    if len(numbers) != 2:
        raise InvalidArgument(f"{field} = {values!r} is invalid: valid range (min, max), two numbers")
    return numbers[0], numbers[1]


def _names(values, field):
    """A name or a sequence of names."""
    if values is None:
        return []
    if isinstance(values, str):
        return [values]
    if not hasattr(values, "__iter__"):
        raise InvalidArgument(f"{field} = {values!r} is invalid: valid range a str or a sequence of str")
    return [_checked(v, field, "text", "a str or a sequence of str") for v in values]


def _dict(values, field, valid):
    """A dict that may be left out (None: empty)."""
    if values is None:
        return {}
    if not isinstance(values, dict):
        raise InvalidArgument(f"{field} = {values!r} is invalid: valid range {valid}")
    return values


def _named_values(values, field):
    return [(_checked(name, field, "text", "a dict of name: number"), _checked(value, f"{field}[{name!r}]", "number"))
            for name, value in _dict(values, field, "a dict of name: number").items()]


def _start(parameters=None, state=None, phi=None, *, preset=None, point=None, results="results", set=None,
           signature=None, guess=None, free=None, fix=None, tie_u_r=False, paper_choice=False):
    pairs = []
    if parameters is not None:
        if not isinstance(parameters, Parameters):
            raise InvalidArgument(f"parameters = {parameters!r} is invalid: valid range a stickslip.Parameters")
        pairs += list(parameters.as_dict().items())
    if state is not None:
        values = _numbers_of(_np.asarray(state).ravel().tolist() if isinstance(state, _np.ndarray) else state, "state")
        if len(values) != len(_INITIAL_STATE):
            raise InvalidArgument(f"state = {state!r} is invalid: valid range ({', '.join(_INITIAL_STATE)}), "
                                  f"{len(_INITIAL_STATE)} numbers")
        pairs += list(zip(_INITIAL_STATE, values))
    if phi is not None:
        pairs.append(("phi", _checked(phi, "phi", "number")))
    pairs += _named_values(set, "set")
    if isinstance(fix, dict):
        fixes = [(_checked(k, "fix", "text", "names, or a dict of name: number or None"),
                  None if v is None else _checked(v, f"fix[{k!r}]", "number")) for k, v in fix.items()]
    else:
        fixes = [(k, None) for k in _names(fix, "fix")]
    if isinstance(signature, Signature):
        signature = str(signature)
    return {
        "preset": _optional_text(preset, "preset", "a str, a paper preset's name: " + ", ".join(_core._preset_names())),
        "point": _optional_text(point, "point", "a str, a stored point 'RUN:LABEL'"),
        "results": _checked(results, "results", "path"),
        "signature": _optional_text(signature, "signature", "a stickslip.Signature or its text"),
        "set": pairs, "guess": _named_values(guess, "guess"), "free": _names(free, "free"),
        "fix": fixes, "tie_u_r": _checked(tie_u_r, "tie_u_r", "flag"),
        "paper_choice": _checked(paper_choice, "paper_choice", "flag"),
    }


def _orbit_start(orbit, results, others):
    """The start that gives `orbit` (an Orbit of solve() or find()) back: its type, its parameters as
    set, its state, phase and durations as guess, and its own unknowns (free, fix, tie_u_r)."""
    if not isinstance(orbit, Orbit):
        raise InvalidArgument(f"start = {orbit!r} is invalid: valid range a stickslip.Orbit (solve()'s, or find().orbit)")
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


# A branch's steps, the keywords of every function that runs branches, by kind (_checked).
_STEP_KINDS = {"ds": "number", "ds_min": "number", "ds_max": "number", "max_points": "count"}


def _steps(ds=None, ds_min=None, ds_max=None, max_points=None):
    """The steps given (None: the library's default), each checked for its kind."""
    given = {"ds": ds, "ds_min": ds_min, "ds_max": ds_max, "max_points": max_points}
    return {key: None if value is None else _checked(value, key, _STEP_KINDS[key]) for key, value in given.items()}


def _one_off_run(parameter, range, *, direction="up", output="python", start=None, parameters=None, signature=None,
                 preset=None, point=None, switch_branch=False, boundary=None, results="results", set=None, guess=None,
                 free=None, fix=None, tie_u_r=False, ds=None,
                 ds_min=None, ds_max=None, max_points=None, shooting=None, linear_solver=None, detect_folds=None,
                 detect_branch_points=None, continue_past_type_changes=None, max_amplitude=None,
                 resonance_approach=None, user_values=(), user_values_of=None):
    """The run `stickslip continue` makes of its options (checked by the library, as there)."""
    given = {"ds": ds, "ds_min": ds_min, "ds_max": ds_max, "max_points": max_points, "shooting": shooting,
             "linear_solver": linear_solver, "detect_folds": detect_folds,
             "detect_branch_points": detect_branch_points, "continue_past_type_changes": continue_past_type_changes,
             "max_amplitude": max_amplitude, "resonance_approach": resonance_approach}
    kinds = {**_STEP_KINDS, "shooting": "text", "linear_solver": "text", "detect_folds": "flag",
             "detect_branch_points": "flag", "continue_past_type_changes": "flag", "max_amplitude": "number",
             "resonance_approach": "number"}
    options = {key: (_DEFAULTS[key] if value is None else _checked(value, key, kinds[key]))
               for key, value in given.items()}
    options.update({
        "parameter": _checked(parameter, "parameter", "text"), "range": _pair(range, "range"),
        "direction": _checked(direction, "direction", "text"), "output": _checked(output, "output", "text"),
        "results": _checked(results, "results", "path"), "linear_solver_given": linear_solver is not None,
        "switch_branch": _checked(switch_branch, "switch_branch", "flag"),
        "boundary": _boundary(boundary),
        "user_values": _numbers_of(user_values, "user_values"),
        "user_values_of": {_checked(k, "user_values_of", "text", "a dict of name: numbers"): _numbers_of(vs, "user_values_of")
                           for k, vs in _dict(user_values_of, "user_values_of", "a dict of name: numbers").items()},
    })
    if start is not None:
        others = dict(parameters=parameters, signature=signature, preset=preset, point=point, set=set, guess=guess,
                      free=free, fix=fix, tie_u_r=tie_u_r)
        return _core._one_off_run(_orbit_start(start, results, others), options)
    begin = _start(parameters, preset=preset, point=point, results=results, set=set, signature=signature,
                   guess=guess, free=free, fix=fix, tie_u_r=tie_u_r)
    return _core._one_off_run(begin, options)
