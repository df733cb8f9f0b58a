#include "stickslip/orbits/one_mass_orbits.hpp"

namespace stickslip {

template class BasicPeriodicityEquations<OneMass>;
template BasicSimulationResult<OneMass> SimulateExact(const OneMass&, const OneMass::Parameters&, const OneMass::State&,
                                                      double, const BasicSimulationOptions<OneMass::State>&);
template BasicSimulationResult<OneMass> SimulateOdeint(const OneMass&, const OneMass::Parameters&,
                                                       const OneMass::State&, double,
                                                       const BasicSimulationOptions<OneMass::State>&,
                                                       const OdeintOptions&);
template std::vector<Margin> AdmissibilityMargins(const OneMass&, const BasicOrbit<OneMass>&);
template std::vector<MarginGradient> MarginGradients(const OneMass&, const BasicOrbit<OneMass>&);
template MarginGradient MarginGradientAt(const OneMass&, const BasicOrbit<OneMass>&, const Margin&, double);
template BasicStability<OneMass::kStateSize> StabilityOf(const OneMass&, const BasicOrbit<OneMass>&);
template BasicMonodromyGradient<OneMass::kStateSize> MonodromyGradients(const OneMass&, const BasicOrbit<OneMass>&);
template BasicOrbitMeasures Measure(const OneMass&, const BasicOrbit<OneMass>&);

}  // namespace stickslip
