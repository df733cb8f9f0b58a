#include "stickslip/io/model_file_start.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/model_table.hpp"
#include "stickslip/model/free_oscillations.hpp"

namespace stickslip {

namespace {

// A name `set` gives that is neither a parameter nor the start's.
InvalidInput UnknownName(const ModelDescription& d, const std::string& name, double value) {
  std::vector<std::string> names;
  for (const ParameterDescription& p : d.parameters) names.push_back(p.name);
  return InvalidInput::WithMessage(
      name, fmt::format("{} = {} is invalid: {} is no parameter of the model: valid {}, or the start's {} and phi", name,
                        value, name, fmt::join(names, ", "), fmt::join(d.initial_state, ", ")));
}

}  // namespace

ModelFileStart ReadModelFileStart(const std::filesystem::path& run_file, const NamedValues& set) {
  const ModelTable table = ReadModelTable(run_file);
  const LinearOscillatorData data = ModelDataOf(table);
  DynamicLinearOscillator model(data);
  // The start's entries of `set` (StartOf); the rest are parameters.
  ModelStartState begin = StartOf(model, table, set);
  NamedValues parameters;
  for (const auto& [name, value] : set) {
    if (name == "omega" && model.Autonomous()) {  // no part in the motion, but its event search's scale
      throw InvalidInput::WithMessage(
          "omega", fmt::format("omega = {} is invalid: the model has no forcing, whose frequency it would be: valid "
                               "for a forced model only",
                               value));
    }
    if (name == "phi" && model.Autonomous()) {
      throw InvalidInput::WithMessage(
          "phi", fmt::format("phi = {} is invalid: the model has no forcing, whose phase it would be: valid for a "
                             "forced model only",
                             value));
    }
    if (IsStartName(model.Description(), name)) continue;
    if (!model.Description().ParameterIndex(name)) throw UnknownName(model.Description(), name, value);
    parameters.emplace_back(name, value);
  }
  RefuseRepeatedNames("set", set);
  const DynamicLinearOscillator::Parameters p = ParametersOf(model, table, parameters);
  const Eigen::VectorXcd slip = ModesOf(data).slip.eigenvalues;
  double slowest = std::numeric_limits<double>::infinity();
  for (const std::complex<double>& lambda : slip) slowest = std::min(slowest, std::abs(lambda));
  std::vector<double> frequencies;
  for (const FreeOscillation& mode : FreeOscillations(slip)) {
    if (mode.oscillates) frequencies.push_back(mode.frequency);
  }
  return {std::move(model), p, slowest, std::move(frequencies), std::move(begin.state), begin.phi, std::move(parameters)};
}

void ModelFileStart::RefuseSetOf(const std::string& parameter, std::string_view varies) const {
  for (const auto& [name, value] : set_parameters) {
    if (name != parameter) continue;
    throw InvalidInput::WithMessage("set", fmt::format("set {}={} is invalid: {} varies {} over its own values: valid "
                                                       "--set of the other parameters",
                                                       name, value, varies, name));
  }
}

}  // namespace stickslip
