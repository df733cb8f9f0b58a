#include "stickslip/model/pascal_2014/events.hpp"

#include <cmath>

namespace stickslip {

Mode ModeFromRest(const State& x, double phase, const Parameters& p) {
  const double s = StickForce(x, phase, p);
  const double threshold = p.eta * p.u_r;
  if (s > threshold) return Mode::kSlipNegative;
  if (s < -threshold) return Mode::kSlipPositive;
  // On the threshold (to rounding) the sign of ds/dt during a stick decides, as the continuous
  // extension of the strict inequality.
  const double level = 1e-12 * (std::abs(s) + threshold + 1.0);
  if (threshold - std::abs(s) <= level) {
    const double ds_dt = StickForceRate(AtRest(x), phase, p);
    if (s > 0.0 && ds_dt > 0.0) return Mode::kSlipNegative;
    if (s < 0.0 && ds_dt < 0.0) return Mode::kSlipPositive;
  }
  return Mode::kStick;
}

SinusoidSum CoordinateAlong(const ModeMotion<double>& motion, int i) {
  const int position = i % 2;
  const bool velocity = i >= 2;
  std::vector<Sinusoid> terms;
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
  std::vector<Sinusoid> terms;
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
