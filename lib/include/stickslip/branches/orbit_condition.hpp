// A condition on a periodic orbit that, added to the periodicity equations with a second parameter
// released, defines a curve of codimension-one points in the plane of two parameters: a margin
// through zero (a type boundary, branches/boundary_curve.hpp), a Floquet multiplier at +1 or -1
// (a fold, a period doubling), ... The condition may bring unknowns of its own (the time of an
// interior extremum) and then one equation more than it has unknowns.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "stickslip/branches/orbit_monitor.hpp"
#include "stickslip/orbits/orbit_problem.hpp"

namespace stickslip {

class OrbitCondition {
 public:
  virtual ~OrbitCondition() = default;
  // What the curve is, for files and messages: "LP", "PD", "margin:G:2".
  virtual std::string Name() const = 0;
  // Its own unknowns (0 by default); it has one equation more.
  virtual int ExtraUnknownCount() const { return 0; }
  int EquationCount() const { return ExtraUnknownCount() + 1; }
  // An orbit is asked through its problem (orbits/orbit_problem.hpp) at the problem's unknowns u,
  // of any model: the condition knows the model only through that. A condition is made at one
  // problem's start and evaluated with another's (the curve's, one parameter more released) of
  // the same model and signature: what it keeps depends on those only.
  // Its own unknowns' values at an orbit on the curve (or near it: the start of the curve's
  // continuation).
  virtual Eigen::VectorXd ExtraUnknowns(const OrbitProblem& problem, const Eigen::VectorXd& u) const {
    (void)problem, (void)u;
    return Eigen::VectorXd();
  }
  // The residuals at the orbit with its own unknowns `extra`, and their exact derivatives with
  // respect to the orbit's full variables (problem.FullCount() columns) and to `extra`, where the
  // pointers are not null.
  virtual void Evaluate(const OrbitProblem& problem, const Eigen::VectorXd& u, const Eigen::VectorXd& extra,
                        Eigen::VectorXd* residual, Eigen::MatrixXd* d_variables, Eigen::MatrixXd* d_extra) const = 0;
  // The monitor's test functions (column names: "margin:G:2", "floquet:det(M+I)") that sit on zero
  // along the curve by its definition, or mean nothing there: recorded, not watched.
  virtual std::vector<std::string> Defining() const { return {}; }
  // Columns watched along the curve with a type of their own: the other Floquet tests, whose sign
  // changes are codimension-two points (a fold-flip LPPD on a PD curve, ...).
  virtual std::vector<WatchedColumn> CodimensionTwoTests() const { return {}; }
};

}  // namespace stickslip
