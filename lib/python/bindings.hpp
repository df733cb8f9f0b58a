// What the two translation units of the Python module share: the start of a computation as the
// Python layer hands it over, and the module's errors. The Pythonic signatures, keyword
// defaults and docstrings live in stickslip/__init__.py; the functions bound here take the start
// as one dict and compute with the GIL released.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "stickslip/io/run_file.hpp"
#include "stickslip/numerics/newton.hpp"
#include "stickslip/orbits/start_problem.hpp"

namespace stickslip::python {

namespace py = pybind11;

// The start dict of stickslip/__init__.py (_start): preset, point, results, signature, set, guess
// (lists of (name, value)), free (names), fix (list of (name, value or None)), tie_u_r,
// paper_choice. The restart point is read here from results/RUN. Throws InvalidInput.
StartInput ToStartInput(const py::dict& start);

// The run a continuation or a trace computes: from a run file, or from keywords as `stickslip
// continue` and `stickslip trace` make one (summary.json and trace.json record "(command line)" as
// the run file, as the commands' do), with the results root its restart point is read from.
struct RunInput {
  RunFile run;
  std::string results = "results";
};

// A directory given to save(): (the results root, the run's name, its last component). Throws
// InvalidInput naming "directory" when the name is not a run name.
std::pair<std::filesystem::path, std::string> SplitRunDirectory(const std::string& directory);

// A keyword's value as a run takes it, refused in the command line's words (InvalidInput, a
// ValueError) rather than by pybind11's bare cast error: a whole number (2.5 or 10**30 would not
// fit an int; `valid` is the range the message states), True or False.
int KeywordWholeNumber(const py::handle& value, const std::string& field, std::string_view valid);
bool KeywordTrueOrFalse(const py::handle& value, const std::string& field);

// `steps` with those given in `o` (its keys ds, ds_min, ds_max and max_points, where not None), not
// yet checked (CheckSteps, or CheckRunValues with the rest of a run).
BranchSteps StepsOf(const py::dict& o, BranchSteps steps);

// Raises stickslip.ConvergenceError(message) with its `summary` attribute set (a dict).
[[noreturn]] void RaiseConvergenceError(const std::string& message, py::dict summary);
py::dict SummaryDict(const NewtonSummary& summary);

// (t, x): `count` equally spaced times over one period of `orbit`, from 0 to the period, and the
// state at each, by the orbit's closed-form flows. Throws InvalidInput naming "n".
py::tuple SampleOrbit(const Orbit& orbit, int count);

// A list of 4-vectors as an (n, 4) array.
// States as an (n, size) array, any model's (every state of one size).
template <typename StateType>
py::array_t<double> StateArray(const std::vector<StateType>& states, py::ssize_t size) {
  py::array_t<double> a({static_cast<py::ssize_t>(states.size()), size});
  for (std::size_t i = 0; i < states.size(); ++i) {
    for (py::ssize_t j = 0; j < size; ++j) a.mutable_at(i, j) = states[i](j);
  }
  return a;
}
py::array_t<double> StateArray(const std::vector<State>& states);  // the paper's, (n, 4)

// The bindings of orbit_bindings.cpp (model, single orbits) and branch_bindings.cpp (branches,
// continuation stepping, sweeps, runs) and trace_bindings.cpp (traces, maps). A new capability (find, trace) adds a function to one of
// them and a wrapper to __init__.py.
void BindErrors(py::module_& m);  // ConvergenceError, and InvalidInput as ValueError
void BindOrbits(py::module_& m);
void BindBranches(py::module_& m);
void BindTraces(py::module_& m);  // trace_bindings.cpp: traces and brute-force maps
void BindAtlas(py::module_& m);   // atlas_bindings.cpp

}  // namespace stickslip::python
