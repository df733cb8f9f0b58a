#include "stickslip/io/model_find.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/model_table.hpp"

namespace stickslip {

ModelFileStart ReadModelFileStart(const std::filesystem::path& run_file, const NamedValues& set) {
  const ModelTable table = ReadModelTable(run_file);
  const LinearOscillatorData data = ModelDataOf(table);
  DynamicLinearOscillator model(data);
  const DynamicLinearOscillator::Parameters p = ParametersOf(model, table, set);
  double slowest = std::numeric_limits<double>::infinity();
  for (const std::complex<double>& lambda : ModesOf(data).slip.eigenvalues) slowest = std::min(slowest, std::abs(lambda));
  return {std::move(model), p, slowest};
}

ModelFindRun FindModelOrbitOf(const ModelFileStart& start, int transients, ProgressCallback progress) {
  if (transients < kMinModelTransients || transients > kMaxModelTransients) {
    throw InvalidInput("transients", transients,
                       fmt::format("whole numbers {} <= transients <= {}", kMinModelTransients, kMaxModelTransients));
  }
  const DynamicLinearOscillator& model = start.model;
  const DynamicLinearOscillator::Parameters& p = start.parameters;
  ModelFindOptions options;
  options.duration = transients * 2.0 * std::numbers::pi / (model.Autonomous() ? start.slowest_frequency : p.omega);
  // Read from the last ten forcing periods; without forcing, from the last half, which must hold two
  // stick-slip cycles (a slow belt's are long: its messages ask for more transients).
  options.record = model.Autonomous() ? options.duration / 2 : std::min(options.duration, 20.0 * std::numbers::pi / p.omega);
  options.progress = std::move(progress);
  return {model, p, FindModelOrbit(model, p, FilledState(model, 0.0), options)};
}

}  // namespace stickslip
