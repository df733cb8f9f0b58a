// Problem-specific test functions watched along a branch: named scalar functions of the branch
// point, each with the special-point type its sign change means. The continuation engine adds
// its own (LP, BP, UZ) and knows nothing of what these mean.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

namespace stickslip {

struct TestFunctionInfo {
  std::string name;       // e.g. "G:3"
  std::string type;       // special-point code reported at a sign change, e.g. "GR"
  bool terminal = false;  // the branch ends there unless told to continue past such points
  bool detect = true;     // false: a value recorded at every point, never an event
};

class Monitor {
 public:
  virtual ~Monitor() = default;
  virtual std::vector<TestFunctionInfo> TestFunctions() const = 0;
  // Values at a branch point u (all unknowns, the continuation parameter included). Non-finite
  // values mean "not defined here" and are never taken for a sign change.
  virtual Eigen::VectorXd Evaluate(const Eigen::VectorXd& u) const = 0;
};

}  // namespace stickslip
