#include "stickslip/orbits/linear_oscillator_problem.hpp"

namespace stickslip {

template class BasicPeriodicityEquations<DynamicLinearOscillator>;
template class BasicOrbitSystem<DynamicLinearOscillator>;
template class ModelOrbitProblem<DynamicLinearOscillator>;

}  // namespace stickslip
