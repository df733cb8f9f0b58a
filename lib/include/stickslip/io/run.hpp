// Executing a run file: the continuation setup it describes (presets, restart from a labelled
// point of earlier results, choice of unknowns). The files a run produces are result_files.hpp's.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "stickslip/branches/boundary_curve.hpp"
#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/run_file.hpp"

namespace stickslip {

// `options` stepping as `steps` says (the engine's step controls and max_points).
ContinuationOptions WithSteps(ContinuationOptions options, const BranchSteps& steps);

// The run file's [continuation] keys as the engine's options: direction, range, steps, max_points,
// the detections and continue_past_type_changes (user values are MakeSetup's: they address the
// unknowns).
ContinuationOptions WithContinuationKeys(ContinuationOptions options, const RunFile& run);

// Throws KeyError at continuation.range where the run's range does not hold the start's `value` of
// the continued parameter.
void CheckRangeHoldsStart(const RunFile& run, double value);

// The same for the branch's first point, after the continuation: a switched branch's lies ds
// along it from the label, which CheckRangeHoldsStart saw. Also where the first point lies inside
// the run's range but past a bound of the physics (BranchEnd::kStartOutsideRange: a friction level
// past the other, held one; a parameter's valid range): KeyError at start.restart.switch_branch for
// a switched branch, else at continuation.range, with the engine's message.
void CheckRangeHoldsFirstPoint(const RunFile& run, const Branch& branch);

// The run's user values as the engine takes them: each variable by its position among `order` (the
// free variables in their order, then the continued parameter), found by name with `index_of`.
// Throws KeyError at continuation.user_values_of for a name that is no unknown of the run.
std::vector<UserValue> UserValuesOf(const RunFile& run, const std::vector<int>& order,
                                    const std::function<std::optional<int>(const std::string&)>& index_of);

// The curve in two parameters the restart asks for (start.restart.boundary) through its label, a
// special point of `type` whose test function is `test_function`, from `setup` (the branch's at
// the label): the run's parameter continued, the boundary released (BoundaryCurve). Throws
// KeyError at start.restart.boundary where BoundaryCurve refuses it, with its reason.
template <OscillatorModel Model>
BasicOrbitContinuationSetup<Model> CurveOfRestart(const RunFile& run, const std::string& type,
                                                  const std::string& test_function,
                                                  const BasicOrbitContinuationSetup<Model>& setup) {
  const std::string condition = CurveCondition(type, test_function);
  try {
    return BoundaryCurve(BasicCurveStart<Model>{setup.start, condition, run.parameter, setup.unknowns}, setup,
                         run.restart_boundary);
  } catch (const InvalidInput& e) {
    // The curve's own fields are the run's: its second parameter is the boundary given, its
    // condition the label's type; what is wrong is said in the valid range.
    const bool own = e.field() == "second" || e.value() == condition;  // the value shown already
    const std::string why = e.valid_range().empty() ? std::string(e.what())
                            : own                    ? "valid " + e.valid_range()
                                                     : fmt::format("{} is invalid: valid {}", e.value(), e.valid_range());
    throw KeyError(run, "start.restart.boundary",
                   fmt::format("= '{}' is invalid at '{}' ({}): {}", run.restart_boundary, run.restart_label, condition, why));
  }
}

// The setup a run file describes. Throws RunFileError naming the file, line and key.
OrbitContinuationSetup MakeSetup(const RunFile& run, const std::filesystem::path& results_root);

}  // namespace stickslip
