#include "stickslip/orbits/margins.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace stickslip {

const char* ToString(MarginKind kind) {
  switch (kind) {
    case MarginKind::kDuration: return "duration";
    case MarginKind::kSlipVelocity: return "slip-velocity";
    case MarginKind::kStopSlope: return "stop-slope";
    case MarginKind::kStopForce: return "stop-force";
    case MarginKind::kStickConstraint: return "stick-constraint";
    case MarginKind::kExitSlope: return "exit-slope";
    case MarginKind::kFrictionLevel: break;
  }
  return "friction-level";
}

namespace {

template <typename F>
Extremum InteriorMinimumOf(const F& f, double d) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const double guard = 1e-9 * std::max(1.0, d);
  Extremum best{0.0, kInfinity};
  const F df = f.Derivative();
  const F d2f = df.Derivative();
  if (std::isnan(d)) return {0.0, std::numeric_limits<double>::quiet_NaN()};
  if (!(d > 2 * guard)) return best;
  const ZeroSearch critical = Zeros(df, guard, d - guard, std::numeric_limits<int>::max());
  if (!critical.Complete()) return {0.0, std::numeric_limits<double>::quiet_NaN()};
  for (const Zero& z : critical.zeros) {
    if (d2f(z.t) < 0.0) continue;  // a maximum
    const double value = f(z.t);
    if (value < best.value) best = {z.t, value};
  }
  return best;
}

}  // namespace

Extremum InteriorMinimum(const SinusoidSum& f, double d) { return InteriorMinimumOf(f, d); }
Extremum InteriorMinimum(const ExponentialSum& f, double d) { return InteriorMinimumOf(f, d); }

std::string Margin::Name() const {
  return segment < 0 ? std::string(base) : fmt::format("{}:{}", base, segment + 1);
}

std::vector<Margin> AdmissibilityMargins(const Orbit& orbit) {
  return AdmissibilityMargins(Pascal2014{}, orbit.OnModel());
}

Margin SmallestMargin(const std::vector<Margin>& margins) {
  const auto undefined = std::find_if(margins.begin(), margins.end(), [](const Margin& m) { return std::isnan(m.value); });
  if (undefined != margins.end()) return *undefined;
  return *std::min_element(margins.begin(), margins.end(),
                           [](const Margin& a, const Margin& b) { return a.value < b.value; });
}

}  // namespace stickslip
