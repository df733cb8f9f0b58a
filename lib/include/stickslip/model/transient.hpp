// Transients simulated out: the state after a whole number of forcing periods, simulated in
// chunks so that neither memory nor any one simulation's max_events grows with their number.
// After k whole periods the forcing cos(omega t + phi) has its phase phi again, so the state at
// t = k 2 pi/omega starts the rest of the motion with the same phi and time counted on from there.
//
//   TransientOptions o;
//   o.periods = 500;
//   const Transient settled = SimulateTransient(SimulateExact, p, x0, phi, o);
//   // settled.state is the state at t = 500 * 2 pi / omega
#pragma once

#include <algorithm>
#include <functional>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/model/oscillator_model.hpp"
#include "stickslip/model/simulation.hpp"

namespace stickslip {

// The largest number of transient periods (as for simulate --periods and sweep --transients).
inline constexpr int kMaxTransientPeriods = 1000000;

template <typename StateType>
struct BasicTransientOptions {
  int periods = 0;  // forcing periods simulated and discarded, 0 to kMaxTransientPeriods
  // At most this many periods per simulation (>= 1): each chunk's events and segments are
  // dropped before the next.
  int chunk_periods = 1000;
  // max_events and zeros per chunk; progress with done and total counted over the whole
  // transient (periods). duration and sample_step are set here.
  BasicSimulationOptions<StateType> simulation;

  // Throws InvalidInput naming the first field out of range.
  void Validate() const {
    if (periods < 0 || periods > kMaxTransientPeriods) {
      throw InvalidInput("periods", periods, fmt::format("0 <= periods <= {}", kMaxTransientPeriods));
    }
    if (chunk_periods < 1) throw InvalidInput("chunk_periods", chunk_periods, "chunk_periods >= 1");
  }
};
using TransientOptions = BasicTransientOptions<State>;

template <typename StateType>
struct BasicTransient {
  StateType state = FixedSizeDefault<StateType>();  // at t = periods * 2 pi / omega, or where the simulation stopped
  double t = 0.0;                                   // ... that time
  SimulationEnd end = SimulationEnd::kDuration;
  std::string message;  // why a chunk stopped early, if one did
  bool Completed() const { return end == SimulationEnd::kDuration; }
};
using Transient = BasicTransient<State>;

// The transient from x0 at t = 0 (forcing phase phi) of a model forced at `forcing_frequency`, by
// `simulate(p, x, phi, options)` (an exact or an Odeint simulation of the model). Throws
// InvalidInput for options out of range; the preconditions of the simulator otherwise.
template <typename Simulate, typename Parameters, typename StateType>
BasicTransient<StateType> SimulateTransientAt(double forcing_frequency, const Simulate& simulate, const Parameters& p,
                                              const StateType& x0, double phi,
                                              const BasicTransientOptions<StateType>& options) {
  options.Validate();
  const double period = 2.0 * std::numbers::pi / forcing_frequency;
  BasicTransient<StateType> transient{x0, 0.0, SimulationEnd::kDuration, ""};
  // Bounded by periods / chunk_periods chunks.
  for (int done = 0; done < options.periods;) {
    const int chunk = std::min(options.chunk_periods, options.periods - done);
    BasicSimulationOptions<StateType> o = options.simulation;
    o.duration = chunk * period;
    o.sample_step = 0.0;
    if (options.simulation.progress) {
      o.progress = [&, done](const Progress& within) {
        options.simulation.progress({done + within.done, static_cast<double>(options.periods), "periods"});
      };
    }
    const auto r = simulate(p, transient.state, phi, o);
    if (!r.Completed()) {
      transient.end = r.end;
      transient.message = r.message;
      if (!r.segments.empty()) {
        transient.state = r.segments.back().end;
        transient.t = done * period + r.segments.back().t_end;
      }
      return transient;
    }
    transient.state = r.segments.back().end;
    done += chunk;
    transient.t = done * period;
  }
  return transient;
}

// SimulateExact or SimulateOdeint.
using Simulator = std::function<SimulationResult(const Parameters&, const State&, double, const SimulationOptions&)>;

// The paper's model's transient (SimulateTransientAt at omega).
Transient SimulateTransient(const Simulator& simulate, const Parameters& p, const State& x0, double phi,
                            const TransientOptions& options);

}  // namespace stickslip
