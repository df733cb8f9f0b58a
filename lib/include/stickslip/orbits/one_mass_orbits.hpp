// The orbit layer compiled once, in the library, for the linear oscillator of one coordinate
// (model/linear_oscillator.hpp with N = 1: Den Hartog's oscillator, a mass on a belt).
//
// The orbit layer is templates on the model; every translation unit that uses them for
// LinearOscillator<1> would otherwise compile the exponential-sum flows, their forward-mode
// derivatives and the root finder again. These explicit instantiation declarations (defined in
// one_mass_orbits.cpp) let them link to one copy instead.
#pragma once

#include <vector>

#include "stickslip/model/exact_simulator.hpp"
#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/model/odeint_simulation.hpp"
#include "stickslip/orbits/floquet_gradients.hpp"
#include "stickslip/orbits/margin_gradients.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/orbit_measures.hpp"
#include "stickslip/orbits/orbit_system.hpp"
#include "stickslip/orbits/periodicity_equations.hpp"
#include "stickslip/orbits/stability.hpp"

namespace stickslip {

using OneMass = LinearOscillator<1>;

extern template class BasicPeriodicityEquations<OneMass>;
extern template BasicSimulationResult<OneMass> SimulateExact(const OneMass&, const OneMass::Parameters&,
                                                             const OneMass::State&, double,
                                                             const BasicSimulationOptions<OneMass::State>&);
extern template BasicSimulationResult<OneMass> SimulateOdeint(const OneMass&, const OneMass::Parameters&,
                                                              const OneMass::State&, double,
                                                              const BasicSimulationOptions<OneMass::State>&,
                                                              const OdeintOptions&);
extern template std::vector<Margin> AdmissibilityMargins(const OneMass&, const BasicOrbit<OneMass>&);
extern template std::vector<MarginGradient> MarginGradients(const OneMass&, const BasicOrbit<OneMass>&);
extern template MarginGradient MarginGradientAt(const OneMass&, const BasicOrbit<OneMass>&, const Margin&, double);
extern template BasicStability<OneMass::kStateSize> StabilityOf(const OneMass&, const BasicOrbit<OneMass>&);
extern template BasicMonodromyGradient<OneMass::kStateSize> MonodromyGradients(const OneMass&,
                                                                             const BasicOrbit<OneMass>&);
extern template BasicOrbitMeasures Measure(const OneMass&, const BasicOrbit<OneMass>&);

}  // namespace stickslip
