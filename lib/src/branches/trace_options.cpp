// TraceOptions' own checks, apart from the trace: the run-file reader (and its fuzzer) needs them
// without the orbit layers.
#include <cmath>

#include <fmt/format.h>

#include "stickslip/branches/trace.hpp"
#include "stickslip/invalid_input.hpp"

namespace stickslip {

void TraceOptions::ValidateOwnFields() const {
  if (!(max_branches >= 1 && max_branches <= kMaxTraceBranches)) {
    throw InvalidInput("max_branches", max_branches, WholeNumberRange("max_branches", 1, kMaxTraceBranches));
  }
  if (!(max_amplitude > 0.0 && std::isfinite(max_amplitude))) {
    throw InvalidInput("max_amplitude", max_amplitude, "a finite max_amplitude > 0");
  }
  if (!(follow_bifurcations >= 0 && follow_bifurcations <= kMaxTraceBranches)) {
    throw InvalidInput("follow_bifurcations", follow_bifurcations,
                       WholeNumberRange("follow_bifurcations", 0, kMaxTraceBranches));
  }
  if (!(loop_tolerance > 0.0 && loop_tolerance <= 1e-2)) {
    throw InvalidInput("loop_tolerance", loop_tolerance, "0 < loop_tolerance <= 1e-2");
  }
}

}  // namespace stickslip
