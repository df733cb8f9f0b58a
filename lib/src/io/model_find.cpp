#include "stickslip/io/model_find.hpp"

#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/model_table.hpp"

namespace stickslip {

namespace {

// The time `periods` take: forcing periods, or those of the slowest free oscillation of the slip.
double SettlingTime(const DynamicLinearOscillator& model, const DynamicLinearOscillator::Parameters& p,
                    const LinearOscillatorModes& modes, int periods) {
  if (!model.Autonomous()) return periods * 2.0 * std::numbers::pi / p.omega;
  double slowest = std::numeric_limits<double>::infinity();
  for (const std::complex<double>& lambda : modes.slip.eigenvalues) slowest = std::min(slowest, std::abs(lambda));
  return periods * 2.0 * std::numbers::pi / slowest;
}

}  // namespace

ModelFindRun FindModelFileOrbit(const std::filesystem::path& run_file, const NamedValues& set, int transients,
                                ProgressCallback progress) {
  if (transients < kMinModelTransients || transients > kMaxModelTransients) {
    throw InvalidInput("transients", transients,
                       fmt::format("whole numbers {} <= transients <= {}", kMinModelTransients, kMaxModelTransients));
  }
  const ModelTable table = ReadModelTable(run_file);
  const LinearOscillatorData data = ModelDataOf(table);
  DynamicLinearOscillator model(data);
  const DynamicLinearOscillator::Parameters p = ParametersOf(model, table, set);
  ModelFindOptions options;
  options.duration = SettlingTime(model, p, ModesOf(data), transients);
  // Read from the last ten forcing periods; without forcing, from the last half, which must hold two
  // stick-slip cycles (a slow belt's are long: its messages ask for more transients).
  options.record = model.Autonomous() ? options.duration / 2 : std::min(options.duration, 20.0 * std::numbers::pi / p.omega);
  options.progress = std::move(progress);
  ModelFindResult<DynamicLinearOscillator> found = FindModelOrbit(model, p, FilledState(model, 0.0), options);
  return {std::move(model), p, std::move(found)};
}

}  // namespace stickslip
