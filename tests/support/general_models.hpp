// The general linear oscillator's orbit problem (the periodicity equations in chosen unknowns, and
// at them the margins, stability, measures and slip resonance), for the fixed sizes the tests use
// (the library compiles the dynamic size: orbits/linear_oscillator_problem.hpp),
// compiled once (general_models.cpp) instead of in every test file that solves, continues or
// traces such a model: those files include this header.
#pragma once

#include "stickslip/orbits/linear_oscillator_problem.hpp"

namespace stickslip {

extern template class BasicPeriodicityEquations<LinearOscillator<1>>;
extern template class BasicPeriodicityEquations<LinearOscillator<2>>;
extern template class BasicOrbitSystem<LinearOscillator<1>>;
extern template class BasicOrbitSystem<LinearOscillator<2>>;
extern template class ModelOrbitProblem<LinearOscillator<1>>;
extern template class ModelOrbitProblem<LinearOscillator<2>>;

}  // namespace stickslip
