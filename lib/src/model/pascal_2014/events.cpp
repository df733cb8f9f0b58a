#include "stickslip/model/pascal_2014/events.hpp"

#include <cmath>

#include "stickslip/model/coulomb_at_rest.hpp"

namespace stickslip {

Mode ModeFromRest(const State& x, double phase, const Parameters& p) {
  return CoulombModeAtRest(StickForce(x, phase, p), p.eta * p.u_r,
                           [&] { return StickForceRate(AtRest(x), phase, p); });
}

SinusoidSum CoordinateAlong(const ModeMotion<double>& motion, int i) {
  const int position = i % 2;
  const bool velocity = i >= 2;
  SinusoidTerms terms;
  for (int k = 0; k < motion.component_count; ++k) {
    const auto& c = motion.components[k];
    const double a = c.cos_coefficient(position);
    const double b = c.sin_coefficient(position);
    if (velocity) {
      terms.push_back({c.frequency, c.frequency * b, -c.frequency * a});
    } else {
      terms.push_back({c.frequency, a, b});
    }
  }
  const double drift = motion.drift(position);
  return velocity ? SinusoidSum(drift, 0.0, std::move(terms))
                  : SinusoidSum(motion.offset(position), drift, std::move(terms));
}

SinusoidSum StickForceAlong(const ModeMotion<double>& motion, double phase, const Parameters& p) {
  const double k = p.chi * p.eta;
  SinusoidTerms terms;
  for (int c = 0; c < motion.component_count; ++c) {
    const auto& m = motion.components[c];
    terms.push_back({m.frequency, k * (m.cos_coefficient(1) - m.cos_coefficient(0)),
                     k * (m.sin_coefficient(1) - m.sin_coefficient(0))});
  }
  // -cos(omega s + psi) = -cos(psi) cos(omega s) + sin(psi) sin(omega s)
  terms.push_back({p.omega, -std::cos(phase), std::sin(phase)});
  return SinusoidSum(k * (motion.offset(1) - motion.offset(0)),
                     k * (motion.drift(1) - motion.drift(0)), std::move(terms));
}

}  // namespace stickslip
