#include "stickslip/branches/boundary_curve.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "stickslip/branches/floquet_condition.hpp"
#include "stickslip/branches/type_boundary.hpp"
#include "stickslip/invalid_input.hpp"

namespace stickslip {

namespace ov = orbit_variables;

OrbitContinuationSetup BoundaryCurve(const CurveStart& start, const OrbitContinuationSetup& branch_setup,
                                     std::string_view second) {
  const std::string_view prefix = orbit_columns::kMarginPrefix;
  if (start.condition.starts_with(prefix)) {
    const LocatedTypeChange located{.orbit = start.orbit,
                                    .margin = start.condition.substr(prefix.size()),
                                    .parameter = start.parameter,
                                    .past = 1,
                                    .unknowns = start.unknowns};
    return TypeBoundary(located, branch_setup, second).setup;
  }
  const int n = start.orbit.signature.size();
  const std::optional<int> second_index = ov::IndexOf(n, second);
  const std::vector<std::string>& released = start.unknowns.release;
  if (!second_index || *second_index < ov::Parameter(n, ParameterId::kChi) || second == start.parameter ||
      std::find(released.begin(), released.end(), second) != released.end() ||
      (second == "u_r" && start.unknowns.tie_static_friction)) {
    throw InvalidInput("second", std::string(second),
                       fmt::format("a parameter other than the continued {}, not released already: chi, eta, omega, u_s, u_r",
                                   start.parameter));
  }
  OrbitContinuationSetup setup = branch_setup;
  setup.condition = FloquetCondition(start.condition, start.orbit);
  setup.start = start.orbit;
  setup.unknowns = start.unknowns;
  setup.unknowns.release.emplace_back(second);
  setup.unknowns.condition_equations = setup.condition->EquationCount() - setup.condition->ExtraUnknownCount();
  setup.parameter = start.parameter;
  setup.options.continue_past_terminal = false;
  return setup;
}

}  // namespace stickslip
