// Random starts, phases, durations and valid parameters for the tests of the flows.
#pragma once

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "stickslip/model/pascal_2014/flows.hpp"
#include "stickslip/model/pascal_2014/modal.hpp"

namespace stickslip {

struct FlowCase {
  Mode mode = Mode::kSlipNegative;
  State start = State::Zero();
  double phase = 0.0;
  double s = 0.0;
  Parameters p;
};

struct RandomFlowCaseOptions {
  // Keep omega this far from omega1 and omega2, where Q and its derivatives blow up and
  // differences lose digits.
  double resonance_gap = 0.05;
  double max_duration = 12.0;
  // In a stick, start at rest (x2' = 0, as in every real stick); otherwise x2 drifts (eq. 9).
  bool stick_at_rest = true;
};

// chi in (0.1, 0.9), eta in (0.5, 5), omega in (0.2, 2), u_s in (0.01, 0.5), u_r/u_s in (1, 3);
// the start in [-2, 2]^4, the phase in [0, 2 pi), the duration in [0, max_duration].
inline std::vector<FlowCase> RandomFlowCases(Mode mode, int count, unsigned seed,
                                             const RandomFlowCaseOptions& options = {}) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto in = [&](double lo, double hi) { return lo + (hi - lo) * u(rng); };
  std::vector<FlowCase> cases;
  while (static_cast<int>(cases.size()) < count) {
    FlowCase c;
    c.mode = mode;
    c.p = {in(0.1, 0.9), in(0.5, 5.0), in(0.2, 2.0), in(0.01, 0.5), 0.0};
    c.p.u_r = c.p.u_s * in(1.0, 3.0);
    if (Validate(c.p)) continue;
    const auto [omega1, omega2] = NaturalFrequencies(c.p.chi, c.p.eta);
    if (std::abs(c.p.omega - omega1) <= options.resonance_gap || std::abs(c.p.omega - omega2) <= options.resonance_gap) {
      continue;
    }
    for (int i = 0; i < 4; ++i) c.start(i) = in(-2.0, 2.0);
    if (mode == Mode::kStick && options.stick_at_rest) c.start(3) = 0.0;
    c.phase = in(0.0, 2.0 * std::numbers::pi);
    c.s = in(0.0, options.max_duration);
    cases.push_back(c);
  }
  return cases;
}

}  // namespace stickslip
