// The test functions the engine watches between two accepted points, and the detection of their
// sign changes: its own (LP, BP, UZ, the parameter bounds) and the monitor's.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "arclength_corrector.hpp"

namespace stickslip::detail {

struct Event {
  std::string type;  // special-point code: "LP", "BP", "UZ", "EP" or the monitor's
  std::string name;  // the test function, in reports
  std::function<double(const Sample&)> g;  // continuous, or a sign (BP)
  bool sign_only = false;  // g is a sign: located by bisection
  bool terminal = false;   // ends the branch when it leaves its positive side
  bool bound = false;      // a parameter bound, or a bound on another unknown: ends the branch
  int bound_index = 0;     // the bounded unknown (lambda's for the parameter bounds)
  std::string bound_name = {};  // its name in the end message ("reached omega = 0.2")
  double noise = 0.0;      // a sign change between values both below this is noise
  int priority = 0;        // order of events located at the same point
  bool may_have_poles = false;  // a sign change may be a pole (TestFunctionInfo)
  std::string positive_side = {};  // what the positive side of a terminal one means
};

// Built once per branch. The functions keep references to `options`, which must outlive them.
std::vector<Event> MakeEvents(const ContinuationOptions& options, const std::vector<TestFunctionInfo>& monitored);

// Whether g changes sign from ga (at the last accepted point) to gb (at the next): both finite,
// not both zero and not both within noise; or from +inf ("none yet") to a finite negative value. A zero at the last accepted point was counted at the
// step that reached it.
bool ChangesSign(const Event& event, double ga, double gb);

}  // namespace stickslip::detail
