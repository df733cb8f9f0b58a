#include "stickslip/branches/boundary_curve.hpp"

#include <algorithm>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "stickslip/branches/margin_condition.hpp"
#include "stickslip/invalid_input.hpp"

namespace stickslip {

namespace {

namespace ov = orbit_variables;

// The branch's unknowns with `second` released: a parameter, not the continued one, not released.
UnknownChoice WithSecondReleased(const CurveStart& start, std::string_view second) {
  const int n = start.orbit.signature.size();
  const std::optional<int> index = ov::IndexOf(n, second);
  if (!index || *index < ov::Parameter(n, ParameterId::kChi) || second == start.parameter) {
    throw InvalidInput("second", std::string(second),
                       fmt::format("a parameter other than the continued {}: chi, eta, omega, u_s, u_r", start.parameter));
  }
  UnknownChoice unknowns = start.unknowns;
  if (std::find(unknowns.release.begin(), unknowns.release.end(), second) != unknowns.release.end()) {
    throw InvalidInput("second", std::string(second), "a parameter not released already");
  }
  unknowns.release.emplace_back(second);
  return unknowns;
}

}  // namespace

OrbitContinuationSetup BoundaryCurve(const CurveStart& start, const OrbitContinuationSetup& branch_setup,
                                     std::string_view second) {
  const std::string_view prefix = orbit_columns::kMarginPrefix;
  if (!start.condition.starts_with(prefix)) {
    throw InvalidInput("condition", start.condition, "a margin's column (margin:reversal:1, ...)");
  }
  auto condition = std::make_shared<MarginCondition>(start.orbit, start.condition.substr(prefix.size()));
  OrbitContinuationSetup setup = branch_setup;
  setup.unknowns = WithSecondReleased(start, second);
  setup.start = start.orbit;
  setup.parameter = start.parameter;
  // The curve ends where a second margin reaches zero: a codimension-two point.
  setup.options.continue_past_terminal = false;
  setup.condition = std::move(condition);
  return setup;
}

}  // namespace stickslip
