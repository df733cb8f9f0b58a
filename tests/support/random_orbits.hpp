// Random orbits (not periodic: margins and their conditions need no periodicity) of signatures
// that hold every end kind (abnormal stop, reversal, stick entry, exits into slip+ and slip-),
// whose slips and sticks have interior minima of x2', G and G1: for derivative tests.
#pragma once

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "stickslip/model/pascal_2014/modal.hpp"
#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

struct RandomOrbit {
  Orbit orbit;
  std::string label;  // "<signature> trial <k>", for messages
};

// `trials` draws per signature (seed 7), leaving out those within 0.05 of a resonance.
inline std::vector<RandomOrbit> RandomOrbitsOfEveryEndKind(int trials) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto in = [&](double lo, double hi) { return lo + (hi - lo) * u(rng); };
  std::vector<RandomOrbit> orbits;
  for (const char* text : {"slip- slip- slip+ stick slip+ stick", "slip+ stick slip- slip+ / antisymmetric",
                           "stick slip- stick slip+ / period 2"}) {
    const Signature signature = Signature::Parse(text);
    for (int trial = 0; trial < trials; ++trial) {
      Orbit o{signature, {}, in(-1, 1), in(-1, 1), in(-1, 1), in(0, 2 * std::numbers::pi), {}};
      for (int i = 0; i < signature.size(); ++i) o.durations.push_back(in(0.5, 6.0));
      o.parameters = {in(0.2, 0.8), in(0.5, 4.0), in(0.3, 1.6), in(0.05, 0.5), 0.0};
      o.parameters.u_r = o.parameters.u_s * in(1.0, 2.0);
      const auto [w1, w2] = NaturalFrequencies(o.parameters.chi, o.parameters.eta);
      if (std::min(std::abs(o.parameters.omega - w1), std::abs(o.parameters.omega - w2)) < 0.05) continue;
      orbits.push_back({o, std::string(text) + " trial " + std::to_string(trial)});
    }
  }
  return orbits;
}

}  // namespace stickslip
