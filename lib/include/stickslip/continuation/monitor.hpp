// Problem-specific quantities along a branch, apart as BifurcationKit keeps events apart from
// record_from_solution: test functions, whose sign changes are special points (events), and
// recorded values, stored with each point the branch keeps and never watched. The engine adds
// its own test functions (LP, BP, UZ) and knows nothing of what these mean.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

namespace stickslip {

struct TestFunctionInfo {
  std::string name;       // e.g. "G:3"
  std::string type;       // special-point code reported at a sign change, e.g. "GR"
  bool terminal = false;  // the branch ends where it leaves its positive side, unless told to
                          // continue past such points
  // The edge of the problem's domain (a physical parameter's range): the branch ends where it
  // leaves the positive side, even when told to continue past terminal functions.
  bool domain_boundary = false;
  // A sign change may be a pole rather than a zero (a saltation matrix blows up where an event
  // becomes tangent): with this set, one whose value next to the change (located, or at the ends
  // of the narrowest bracket reached where the corrector fails there) is larger than at one end of
  // the step is no special point.
  bool may_have_poles = false;
  std::string positive_side = "positive";  // what the positive side means, for the end message
};

class Monitor {
 public:
  virtual ~Monitor() = default;
  virtual std::vector<TestFunctionInfo> TestFunctions() const = 0;
  // The names of the recorded values; none by default.
  virtual std::vector<std::string> RecordedNames() const { return {}; }
  // At a branch point u (all unknowns, the continuation parameter included): the test
  // functions, in TestFunctions' order, and the recorded values where `recorded` is not null
  // (the engine asks for them at the points it keeps, not at the trial points of locating an
  // event). A NaN test value means "not defined here" and is never taken for a sign change; an
  // infinite one is far on its side ("none yet": a margin's interior minimum that does not exist),
  // and a step from +inf to a negative value is a sign change, located where the value is finite.
  virtual void Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* tests, Eigen::VectorXd* recorded) const = 0;
};

}  // namespace stickslip
