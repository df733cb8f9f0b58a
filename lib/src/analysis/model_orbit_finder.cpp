// The finder for a model whose size comes with its data, compiled once for every front end.
#include "stickslip/analysis/model_orbit_finder.hpp"

#include "stickslip/model/linear_oscillator.hpp"

namespace stickslip {

template Verification VerifyByBothSimulators(const DynamicLinearOscillator& model,
                                             const BasicOrbit<DynamicLinearOscillator>& orbit);
template ModelFindResult<DynamicLinearOscillator> FindModelOrbit(const DynamicLinearOscillator& model,
                                                                 const DynamicLinearOscillator::Parameters& p,
                                                                 const DynamicLinearOscillator::State& x0,
                                                                 const ModelFindOptions& options);

}  // namespace stickslip
