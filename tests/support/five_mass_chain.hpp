// The general-oscillator issue's five-mass example and the orbit its motion settles on, shared by
// the trace's test (branches/model_trace_test.cpp) and the model benchmark.
#pragma once

#include <numbers>
#include <stdexcept>

#include "stickslip/analysis/settled_orbit.hpp"
#include "stickslip/model/chain.hpp"
#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

// Five masses in a line (m = 1; springs k = 1 from the ground to the first and between neighbours;
// a damper c = 0.05 from each to the ground), forced on the first, the Coulomb contact on the last
// (its users take F_k = 0.3, F_s = 0.4): the general-oscillator issue's five-mass example, as a
// model whose size is read with its data (ChainData, DynamicLinearOscillator).
inline DynamicLinearOscillator FiveMassChain() {
  Chain chain;
  chain.masses.assign(5, 1.0);
  chain.springs = {{0, kGround, 1.0}, {0, 1, 1.0}, {1, 2, 1.0}, {2, 3, 1.0}, {3, 4, 1.0}};
  for (int i = 0; i < 5; ++i) chain.dampers.push_back({i, kGround, 0.05});
  chain.forcing = {1.0, 0.0, 0.0, 0.0, 0.0};
  chain.contact = 4;
  return DynamicLinearOscillator(ChainData(chain));
}

// The orbit the motion from rest settles on over `periods` forcing periods, as a guess
// (analysis/settled_orbit.hpp); the test fails where there is none.
template <OscillatorModel Model>
BasicOrbit<Model> SettledOrbit(const Model& model, const typename Model::Parameters& p, int periods) {
  const double duration = periods * 2.0 * std::numbers::pi / model.ForcingFrequency(p);
  const SettledOrbitGuess<Model> guess = SettledOrbitGuessOf(model, p, FilledState(model, 0.0), duration, duration);
  if (!guess.orbit) throw std::runtime_error("no settled orbit: " + guess.message);
  return *guess.orbit;
}

}  // namespace stickslip
