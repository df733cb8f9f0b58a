#include "stickslip/branches/boundary_curve.hpp"

#include "stickslip/branches/type_boundary.hpp"
#include "stickslip/invalid_input.hpp"

namespace stickslip {

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
  throw InvalidInput("condition", start.condition, "a margin's column (margin:reversal:1, ...)");
}

}  // namespace stickslip
