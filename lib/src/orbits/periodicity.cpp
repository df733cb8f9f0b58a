#include "stickslip/orbits/periodicity.hpp"

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {

namespace ov = orbit_variables;

const char* ToString(Shooting s) { return s == Shooting::kSingle ? "single" : "multiple"; }

Eigen::VectorXd VariablesOf(const BasicPeriodicityEquations<Pascal2014>& equations, const Orbit& orbit) {
  Eigen::VectorXd v(equations.VariableCount());
  const int full = ov::Count(equations.signature().size());
  v.head(full) = ov::Pack(orbit);
  if (equations.shooting() == Shooting::kMultiple) {
    const std::vector<State> states = orbit.SegmentStates();
    for (int i = 1; i < equations.signature().size(); ++i) v.segment<4>(full + 4 * (i - 1)) = states[i];
  }
  return v;
}

Eigen::VectorXd PeriodicityEquations::Variables(const Orbit& orbit) const { return VariablesOf(*this, orbit); }

OrbitSystem::OrbitSystem(const Orbit& reference, std::vector<int> free, bool tie_static_friction, Shooting shooting,
                         FlowEvaluator flow)
    : OrbitSystem(PeriodicityEquations(reference.signature, shooting, flow), reference, std::move(free),
                  tie_static_friction) {}

OrbitSystem::OrbitSystem(const PeriodicityEquations& equations, const Orbit& reference, std::vector<int> free,
                         bool tie_static_friction)
    : BasicOrbitSystem(equations, equations.Variables(reference), std::move(free), tie_static_friction) {}

Eigen::VectorXd OrbitSystem::Unknowns(const Orbit& orbit) const { return Unknowns(VariablesOf(equations(), orbit)); }

Orbit OrbitSystem::ToOrbit(const Eigen::VectorXd& u) const {
  return ov::Unpack(equations().signature(), Variables(u).head(equations().FullCount()));
}

}  // namespace stickslip
