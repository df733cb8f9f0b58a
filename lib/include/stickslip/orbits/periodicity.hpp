// The periodicity equations of an orbit signature (Pascal 2014, eqs. 12-54 generalised to any
// signature) and the orbit as a square system for Newton.
//
// Equations, for n listed segments:
//  - the end condition of each segment i: x2' = 0 at a stop (eq. 14, 16, 30), and also
//    x2'' = 0 at an abnormal stop (eq. 18, 23); s - eta u_r = 0 at an exit into slip-, or
//    s + eta u_r = 0 at an exit into slip+ (eq. 32, 37, 48, 50): n + (abnormal stops) equations;
//  - periodicity of x1, x2, x1' at the end of the listed segments (eq. 19-21, 34, 38, 53), or
//    antiperiodicity X(Theta/2) = -X(0) (eq. 22, 47): 3 equations. x2' needs none: the end
//    condition of the last segment already gives x2' = 0 = x2'0;
//  - the durations sum to the covered time k 2 pi/omega (half of it when antisymmetric): 1.
// So m = n + 4 (+1 per abnormal stop) equations. The unknowns are x10, x20, x1'0, phi and the n
// durations: n + 4, square. (The paper counts n + 3 because it eliminates the last duration with
// the sum.) Releasing a parameter must be paid for by fixing an unknown, and an abnormal stop
// needs a released parameter (u_s = u_r in section 4.2).
//
// Multiple shooting adds the start state of each segment after the first as 4 unknowns, with 4
// continuity equations each; the Jacobian is then block sparse.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "stickslip/numerics/newton.hpp"
#include "stickslip/model/pascal_2014.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/orbit_system.hpp"
#include "stickslip/orbits/periodicity_equations.hpp"

namespace stickslip {

// The paper's model's flows, as the benchmark may swap them.
using FlowEvaluator = BasicFlowEvaluator<Pascal2014>;

// The equations of the paper's model (periodicity_equations.hpp), in the variables of an Orbit
// (orbit.hpp: the same layout).
class PeriodicityEquations : public BasicPeriodicityEquations<Pascal2014> {
 public:
  PeriodicityEquations(Signature signature, Shooting shooting, FlowEvaluator flow = {})
      : BasicPeriodicityEquations(Pascal2014{}, std::move(signature), shooting, flow) {}
  // The variables of an orbit: its full vector and, for multiple shooting, the segment start
  // states obtained by flowing.
  Eigen::VectorXd Variables(const Orbit& orbit) const;
};
Eigen::VectorXd VariablesOf(const BasicPeriodicityEquations<Pascal2014>& equations, const Orbit& orbit);

// The paper's model's orbit as a system in chosen unknowns (orbit_system.hpp), built from an
// Orbit: `free` holds indices of the full variable vector (orbit.hpp).
class OrbitSystem final : public BasicOrbitSystem<Pascal2014> {
 public:
  // Throws InvalidInput naming "free" for an index that is no variable, or u_r freed while tied.
  OrbitSystem(const Orbit& reference, std::vector<int> free, bool tie_static_friction, Shooting shooting,
              FlowEvaluator flow = {});

  using BasicOrbitSystem::Unknowns;
  Eigen::VectorXd Unknowns(const Orbit& orbit) const;
  Orbit ToOrbit(const Eigen::VectorXd& u) const;

 private:
  OrbitSystem(const PeriodicityEquations& equations, const Orbit& reference, std::vector<int> free,
              bool tie_static_friction);
};

}  // namespace stickslip
