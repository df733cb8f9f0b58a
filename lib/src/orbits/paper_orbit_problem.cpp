#include "stickslip/model/pascal_2014.hpp"
#include "stickslip/orbits/model_orbit_problem.hpp"

namespace stickslip {

template class BasicPeriodicityEquations<Pascal2014>;
template class BasicOrbitSystem<Pascal2014>;
template class ModelOrbitProblem<Pascal2014>;

}  // namespace stickslip
