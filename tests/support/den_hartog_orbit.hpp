// Den Hartog's closed-form non-sticking orbit of the one-mass oscillator with Coulomb friction
// (Trans. ASME APM 53 (1931) 107; ../shared/FRICTION-LITERATURE.md), the reference for the tests
// of tests/support/den_hartog_oscillator.hpp.
#pragma once

#include <cmath>
#include <numbers>

#include <Eigen/Core>

#include "stickslip/orbits/periodicity_equations.hpp"
#include "support/den_hartog_oscillator.hpp"

namespace stickslip {

// Den Hartog's symmetric orbit with two stops per period, in the time tau = r t: V = 1/(1 - r^2),
// U = tan(pi/(2r))/r, amplitude X = sqrt(V^2 - beta^2 U^2), forcing phase at the upper stop with
// sin phi = -beta U/V, cos phi = X/V, and on the half period tau in [0, pi]
//   x(tau) = X cos tau + beta U sin tau + beta (1 - cos(tau/r) - U r sin(tau/r)).
struct DenHartogOrbit {
  double r, beta, v, u, amplitude, phi;
  DenHartogOrbit(double r_, double beta_) : r(r_), beta(beta_) {
    v = 1.0 / (1.0 - r * r);
    u = std::tan(std::numbers::pi / (2.0 * r)) / r;
    amplitude = std::sqrt(v * v - beta * beta * u * u);
    phi = std::atan2(-beta * u / v, amplitude / v);
  }
  double X(double t) const {  // t in [0, pi/r]
    const double tau = r * t;
    return amplitude * std::cos(tau) + beta * u * std::sin(tau) +
           beta * (1.0 - std::cos(tau / r) - u * r * std::sin(tau / r));
  }
};

// Den Hartog's orbit as the variables of a signature: antisymmetric "slip-" (one listed half
// period), or "slip- slip+" over the whole period with, for multiple shooting, the lower turning
// point as the second segment's start.
inline Eigen::VectorXd DenHartogVariables(const DenHartogOrbit& orbit,
                                          const BasicPeriodicityEquations<DenHartogOscillator>& equations) {
  using Equations = BasicPeriodicityEquations<DenHartogOscillator>;
  const double half = std::numbers::pi / orbit.r;
  Eigen::VectorXd v(equations.VariableCount());
  v(0) = orbit.amplitude;
  v(Equations::kPhi) = orbit.phi;
  for (int i = 0; i < equations.signature().size(); ++i) v(Equations::Duration(i)) = half;
  v.segment<3>(equations.Parameter(0)) << orbit.r, orbit.beta, orbit.beta;
  if (equations.VariableCount() > equations.FullCount()) v.tail<2>() << -orbit.amplitude, 0.0;
  return v;
}

}  // namespace stickslip
