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

// The orbit as a system in chosen unknowns: the full variables listed in `free` (in that order),
// then the multiple-shooting states; every other variable is held at the reference orbit's
// value. With tie_static_friction, u_r follows u_s (u_r = u_s, needed by abnormal stops).
class OrbitSystem final : public NonlinearSystem {
 public:
  // Throws InvalidInput naming "free" for an index that is no variable, or u_r freed while tied.
  OrbitSystem(const Orbit& reference, std::vector<int> free, bool tie_static_friction,
              Shooting shooting, FlowEvaluator flow = {});

  int EquationCount() const override { return equations_.EquationCount(); }
  int UnknownCount() const override;
  // Dense Jacobian for single shooting, sparse for multiple shooting.
  void Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* residual,
                JacobianMatrix* jacobian) const override;
  std::optional<std::string> DomainError(const Eigen::VectorXd& u) const override;

  Eigen::VectorXd Unknowns(const Orbit& orbit) const;
  Orbit ToOrbit(const Eigen::VectorXd& u) const;
  // Derivatives with respect to the full variables (orbit.hpp's order; then, for multiple
  // shooting, the segment states, or none of them: a function of the orbit alone) as derivatives
  // with respect to the unknowns (the chain rule of holding, freeing and tying).
  Eigen::MatrixXd ToUnknowns(const Eigen::MatrixXd& d_variables) const;
  const std::vector<int>& free() const { return free_; }
  const PeriodicityEquations& equations() const { return equations_; }

 private:
  Eigen::VectorXd Variables(const Eigen::VectorXd& u) const;

  PeriodicityEquations equations_;
  Eigen::VectorXd reference_;
  std::vector<int> free_;
  bool tie_static_friction_;
};

}  // namespace stickslip
