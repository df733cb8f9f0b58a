#include "stickslip/branches/boundary_curve.hpp"
#include "stickslip/branches/model_boundary_curve.hpp"

#include <algorithm>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "stickslip/branches/floquet_condition.hpp"
#include "stickslip/branches/margin_condition.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/linear_oscillator_problem.hpp"

namespace stickslip {

std::string CurveCondition(const std::string& type, const std::string& test_function) {
  return test_function.starts_with(orbit_columns::kMarginPrefix) ? test_function : type;
}

std::shared_ptr<const OrbitCondition> MakeCurveCondition(std::string_view condition, const OrbitProblem& problem,
                                                         const Eigen::VectorXd& u) {
  // A type boundary is its margin's zero (margin_condition.hpp); LP, PD, SB, TR a multiplier's
  // condition (floquet_condition.hpp).
  const std::string_view prefix = orbit_columns::kMarginPrefix;
  if (condition.starts_with(prefix)) return std::make_shared<MarginCondition>(problem, u, condition.substr(prefix.size()));
  return FloquetCondition(condition, problem, u);
}

void CheckSecondParameter(const OrbitLayout& layout, int static_level, int unvaried, const UnknownChoice& unknowns,
                          std::string_view parameter, std::string_view second) {
  const std::vector<std::string>& released = unknowns.release;
  std::vector<std::string> names;  // the valid ones
  for (int k = layout.Parameter(0); k < layout.Count(); ++k) {
    const std::string name = layout.Name(k);
    const bool taken = name == parameter || std::find(released.begin(), released.end(), name) != released.end() ||
                       (k == static_level && unknowns.tie_static_friction);
    if (k != unvaried && !taken) names.push_back(name);
  }
  if (std::find(names.begin(), names.end(), second) == names.end()) {
    throw InvalidInput("second", std::string(second),
                       fmt::format("a parameter the model varies, not the continued {} nor one released already: {}",
                                   parameter, fmt::join(names, ", ")));
  }
}

template OrbitContinuationSetup BoundaryCurve(const CurveStart&, const OrbitContinuationSetup&, std::string_view);
template BasicOrbitContinuationSetup<DynamicLinearOscillator> BoundaryCurve(
    const BasicCurveStart<DynamicLinearOscillator>&, const BasicOrbitContinuationSetup<DynamicLinearOscillator>&,
    std::string_view);

}  // namespace stickslip
