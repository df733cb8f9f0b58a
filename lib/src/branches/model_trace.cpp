// The trace for a model whose size comes with its data, compiled once for every front end.
#include "stickslip/branches/model_trace.hpp"

#include "stickslip/model/linear_oscillator.hpp"

namespace stickslip {

template BasicTraceResult<DynamicLinearOscillator> TraceOrbits(
    const BasicOrbitContinuationSetup<DynamicLinearOscillator>& start, const TraceOptions& options);
template BasicOrbitContinuationSetup<DynamicLinearOscillator> AtLeastPeriod(
    BasicOrbitContinuationSetup<DynamicLinearOscillator> setup);

}  // namespace stickslip
