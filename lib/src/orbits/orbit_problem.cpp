#include "stickslip/orbits/orbit_problem.hpp"

#include <stdexcept>

#include "stickslip/model/pascal_2014.hpp"

namespace stickslip {

Orbit ToOrbit(const OrbitProblem& problem, const Eigen::VectorXd& u) {
  if (&problem.description() != &Pascal2014{}.Description()) {
    throw std::logic_error("ToOrbit: the problem is not of the paper's model");
  }
  return orbit_variables::Unpack(problem.signature(),
                                 problem.Variables(u.head(problem.UnknownCount())).head(problem.FullCount()));
}

}  // namespace stickslip
