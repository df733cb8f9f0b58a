#include "stickslip/branches/type_switch.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "stickslip/branches/model_type_switch.hpp"
#include "stickslip/invalid_input.hpp"

namespace stickslip {

namespace type_switch_detail {

UnknownChoice Renamed(const UnknownChoice& unknowns, const SignatureEdit& edit) {
  UnknownChoice renamed = unknowns;
  for (std::string& name : renamed.release) name = edit.Renamed(name);
  for (std::string& name : renamed.fix) name = edit.Renamed(name);
  return renamed;
}

int ParameterIndexOf(const ModelDescription& description, const std::string& name) {
  if (const std::optional<int> index = description.ParameterIndex(name)) return *index;
  std::vector<std::string> names;
  for (const ParameterDescription& p : description.parameters) names.push_back(p.name);
  throw InvalidInput("parameter", name, fmt::format("{}", fmt::join(names, ", ")));
}

bool FromInadmissibleSide(const Branch& branch, const SpecialPoint& special, double boundary_tolerance) {
  const auto& functions = branch.test_functions;
  const auto function = std::find_if(functions.begin(), functions.end(),
                                     [&](const TestFunctionInfo& f) { return f.name == special.test_function; });
  for (int k = special.point - 1; k >= 0 && function != functions.end(); --k) {
    const BranchPoint& point = branch.points[k];
    const double value = point.tests(function - functions.begin());
    if (!point.label.empty() || !(std::abs(value) > boundary_tolerance)) continue;
    return value < 0.0;
  }
  return false;
}

}  // namespace type_switch_detail

const char* ToString(TypeSwitchStatus status) {
  switch (status) {
    case TypeSwitchStatus::kConfirmed: return "confirmed";
    case TypeSwitchStatus::kNotConfirmed: return "not-confirmed";
    case TypeSwitchStatus::kNoAdjacentType: return "no-adjacent-type";
  }
  return "?";
}

void TypeSwitchOptions::Validate() const {
  if (!(nudge > 0.0 && nudge <= 0.1)) throw InvalidInput("nudge", nudge, "0 < nudge <= 0.1");
  if (!(max_new_duration > 0.0 && max_new_duration <= 1.0)) {
    throw InvalidInput("max_new_duration", max_new_duration, "0 < max_new_duration <= 1");
  }
  for (const double d : new_durations) {
    if (!(d > 0.0 && d <= max_new_duration)) {
      throw InvalidInput("new_durations", d, fmt::format("0 < each <= max_new_duration = {}", max_new_duration));
    }
  }
  if (!(simulation_tolerance > 0.0 && simulation_tolerance <= 1e-3)) {
    throw InvalidInput("simulation_tolerance", simulation_tolerance, "0 < simulation_tolerance <= 1e-3");
  }
  if (!(same_orbit > 0.0 && same_orbit <= 1e-3)) throw InvalidInput("same_orbit", same_orbit, "0 < same_orbit <= 1e-3");
  if (!(start_margin_tolerance >= 0.0 && start_margin_tolerance <= 1e-3)) {
    throw InvalidInput("start_margin_tolerance", start_margin_tolerance, "0 <= start_margin_tolerance <= 1e-3");
  }
}

template LocatedTypeChange TypeChangeAt(const OrbitBranch& branch, const SpecialPoint& special,
                                        const OrbitContinuationSetup& setup);
template TypeSwitch SwitchAt(const LocatedTypeChange& located, const TypeSwitchOptions& options);

}  // namespace stickslip
