#include "stickslip/branches/boundary_curve.hpp"

#include <algorithm>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "stickslip/branches/floquet_condition.hpp"
#include "stickslip/branches/margin_condition.hpp"
#include "stickslip/invalid_input.hpp"

namespace stickslip {

namespace ov = orbit_variables;

OrbitContinuationSetup BoundaryCurve(const CurveStart& start, const OrbitContinuationSetup& branch_setup,
                                     std::string_view second) {
  const int n = start.orbit.signature.size();
  const std::optional<int> second_index = ov::IndexOf(n, second);
  const std::vector<std::string>& released = start.unknowns.release;
  if (!second_index || *second_index < ov::FirstParameter(n) || second == start.parameter ||
      std::find(released.begin(), released.end(), second) != released.end() ||
      (second == "u_r" && start.unknowns.tie_static_friction)) {
    throw InvalidInput("second", std::string(second),
                       fmt::format("a parameter other than the continued {}, not released already: chi, eta, omega, u_s, u_r",
                                   start.parameter));
  }
  OrbitContinuationSetup setup = branch_setup;
  // A type boundary is its margin's zero (margin_condition.hpp); LP, PD, SB, TR a multiplier's
  // condition (floquet_condition.hpp).
  const std::string_view prefix = orbit_columns::kMarginPrefix;
  if (start.condition.starts_with(prefix)) {
    setup.condition = std::make_shared<MarginCondition>(start.orbit, start.condition.substr(prefix.size()));
  } else {
    setup.condition = FloquetCondition(start.condition, start.orbit);
  }
  setup.start = start.orbit;
  setup.unknowns = start.unknowns;
  setup.unknowns.release.emplace_back(second);
  setup.unknowns.condition_equations = setup.condition->EquationCount() - setup.condition->ExtraUnknownCount();
  setup.parameter = start.parameter;
  // The curve ends where a second margin reaches zero: a codimension-two point.
  setup.options.continue_past_terminal = false;
  return setup;
}

}  // namespace stickslip
