#include "support/general_models.hpp"

namespace stickslip {

template class BasicPeriodicityEquations<LinearOscillator<1>>;
template class BasicPeriodicityEquations<LinearOscillator<2>>;
template class BasicOrbitSystem<LinearOscillator<1>>;
template class BasicOrbitSystem<LinearOscillator<2>>;
template class ModelOrbitProblem<LinearOscillator<1>>;
template class ModelOrbitProblem<LinearOscillator<2>>;

}  // namespace stickslip
