#include "stickslip/io/model_find.hpp"

#include "stickslip/model/free_oscillations.hpp"

#include <algorithm>
#include <string>
#include <vector>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/model_restart.hpp"
#include "stickslip/io/model_table.hpp"

namespace stickslip {

ModelFindRun FindModelOrbitOf(const ModelFileStart& start, int transients, int max_multiple, ProgressCallback progress) {
  if (transients < kMinModelTransients || transients > kMaxModelTransients) {
    throw InvalidInput("transients", transients,
                       fmt::format("whole numbers {} <= transients <= {}", kMinModelTransients, kMaxModelTransients));
  }
  if (max_multiple < 1 || max_multiple > ModelFindOptions::kMaxMultiple) {
    throw InvalidInput("max-multiple", max_multiple,
                       fmt::format("whole numbers 1 <= max-multiple <= {}", ModelFindOptions::kMaxMultiple));
  }
  const DynamicLinearOscillator& model = start.model;
  const DynamicLinearOscillator::Parameters& p = start.parameters;
  ModelFindOptions options;
  options.duration = transients * 2.0 * std::numbers::pi / (model.Autonomous() ? start.slowest_frequency : p.omega);
  // Read from the last 2 max_multiple + 2 forcing periods (at least ten); without forcing, from the last
  // half, which must hold two stick-slip cycles (a slow belt's are long: its messages ask for more
  // transients).
  const int recorded = std::max(10, 2 * max_multiple + 2);
  options.record = model.Autonomous() ? options.duration / 2
                                      : std::min(options.duration, recorded * 2.0 * std::numbers::pi / p.omega);
  options.max_multiple = max_multiple;
  options.phi0 = start.phi;
  options.progress = std::move(progress);
  return {model, p, FindModelOrbit(model, p, start.state, options), start.slip_frequencies};
}

ModelFindRun SolveAtModelLabel(const std::filesystem::path& results_root, const std::string& point,
                               const OrbitSolverOptions& solver) {
  ModelLabel at = [&] {
    try {
      const auto [run, label] = RunAndLabel(point);
      return ReadModelLabel(results_root, run, label);
    } catch (const InvalidInput& e) {
      throw e.Renamed("point");
    }
  }();
  const DynamicLinearOscillator& model = at.file.model;
  ModelFindResult<DynamicLinearOscillator> found;
  found.guess = at.orbit;
  found = SolvedAtFixedParameters(model, ModelFindOptions{.solver = solver}, std::move(found));
  if (!found.solution) {  // an abnormal stop: solved only with a friction level released
    throw InvalidInput::WithMessage(
        "point", fmt::format("point = '{}' cannot be solved at its parameters: its orbit '{}' has an abnormal stop (a stop "
                             "without reversal or stick), solved only with a friction level released: valid another "
                             "label (continue --point and trace --point take this one)",
                             point, at.orbit.signature.ToString()));
  }
  if (found.solution->summary.Converged()) found = CheckedModelOrbit(model, std::move(found));
  return {model, at.file.parameters, std::move(found), at.file.slip_frequencies};
}

}  // namespace stickslip
