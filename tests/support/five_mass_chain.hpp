// The general-oscillator issue's five-mass example and the orbit its motion settles on, shared by
// the trace's test (branches/model_trace_test.cpp) and the model benchmark.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "stickslip/model/chain.hpp"
#include "stickslip/model/exact_simulator.hpp"
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

// The orbit a motion settles on, as a guess: simulated exactly from rest over `periods` forcing
// periods, its last whole forcing period from a stop (an orbit's origin is a stop); written over
// half a period where its second half mirrors its first (an antisymmetric orbit, whose symmetric
// segments then vanish together as one).
template <OscillatorModel Model>
BasicOrbit<Model> SettledOrbitGuess(const Model& model, const typename Model::Parameters& p, int periods) {
  const double period = 2.0 * std::numbers::pi / model.ForcingFrequency(p);
  BasicSimulationOptions<typename Model::State> options;
  options.duration = periods * period;
  const BasicSimulationResult<Model> r = SimulateExact(model, p, FilledState(model, 0.0), 0.0, options);
  std::size_t first = 0;
  for (std::size_t k = 1; k < r.segments.size(); ++k) {
    if (r.segments[k - 1].end_reason == SegmentEnd::kStop && r.segments[k].t_start <= options.duration - period) first = k;
  }
  const double t0 = r.segments[first].t_start;
  std::vector<Mode> modes;
  std::vector<double> durations;
  for (std::size_t k = first; k < r.segments.size() && r.segments[k].t_start < t0 + (1.0 - 1e-6) * period; ++k) {
    modes.push_back(r.segments[k].mode);
    durations.push_back(std::min(r.segments[k].t_end, t0 + period) - r.segments[k].t_start);
  }
  const std::size_t half = modes.size() / 2;
  bool antisymmetric = modes.size() % 2 == 0;
  for (std::size_t k = 0; antisymmetric && k < half; ++k) {
    antisymmetric = modes[k + half] == Mirror(modes[k]) && std::abs(durations[k + half] - durations[k]) <= 1e-6 * period;
  }
  if (antisymmetric) {
    modes.resize(half);
    durations.resize(half);
  }
  return {Signature(modes, antisymmetric), p, r.segments[first].start,
          std::remainder(model.ForcingFrequency(p) * t0, 2.0 * std::numbers::pi), durations};
}

}  // namespace stickslip
