// The trace for a model whose size comes with its data, and its one branch (ContinueOrbit),
// compiled once for every front end.
#include "stickslip/branches/model_trace.hpp"

#include "stickslip/model/linear_oscillator.hpp"

namespace stickslip {

template BasicTraceResult<DynamicLinearOscillator> TraceOrbits(
    const BasicOrbitContinuationSetup<DynamicLinearOscillator>& start, const TraceOptions& options);
template BasicOrbitContinuationSetup<DynamicLinearOscillator> AtLeastPeriod(
    BasicOrbitContinuationSetup<DynamicLinearOscillator> setup);
// ContinueOrbit's pieces (orbit_continuation.hpp) for a [model], for a front end's one branch.
template OrbitContinuationProblem MakeOrbitContinuation(const BasicOrbitContinuationSetup<DynamicLinearOscillator>&);
template BasicOrbitBranch<DynamicLinearOscillator> ToOrbitBranch<DynamicLinearOscillator>(
    const OrbitContinuationProblem&, Branch);
// The branch leaving a bifurcation, for the trace's and a restart's (io/switched_restart.hpp).
template BasicBifurcationBranchStart<DynamicLinearOscillator> BranchFromBifurcation(
    const SpecialPoint&, const BasicOrbitContinuationSetup<DynamicLinearOscillator>&, int);
template BasicBifurcationBranchStart<DynamicLinearOscillator> BranchFromBifurcation(
    const std::string&, const BasicOrbitContinuationSetup<DynamicLinearOscillator>&, int);

}  // namespace stickslip
