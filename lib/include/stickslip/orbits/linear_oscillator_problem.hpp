// The orbit problem of the linear oscillator whose size comes with its data
// (DynamicLinearOscillator), compiled once in the library (linear_oscillator_problem.cpp) instead
// of in every file that solves, continues, traces or finds its orbits: those include this header.
#pragma once

#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/orbits/model_orbit_problem.hpp"

namespace stickslip {

extern template class BasicPeriodicityEquations<DynamicLinearOscillator>;
extern template class BasicOrbitSystem<DynamicLinearOscillator>;
extern template class ModelOrbitProblem<DynamicLinearOscillator>;

}  // namespace stickslip
