#include "stickslip/model/transient.hpp"

#include <algorithm>
#include <numbers>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {

void TransientOptions::Validate() const {
  if (periods < 0 || periods > kMaxTransientPeriods) {
    throw InvalidInput("periods", periods, fmt::format("0 <= periods <= {}", kMaxTransientPeriods));
  }
  if (chunk_periods < 1) throw InvalidInput("chunk_periods", chunk_periods, "chunk_periods >= 1");
}

Transient SimulateTransient(const Simulator& simulate, const Parameters& p, const State& x0, double phi,
                            const TransientOptions& options) {
  options.Validate();
  const double period = 2.0 * std::numbers::pi / p.omega;
  Transient transient{x0, 0.0, SimulationEnd::kDuration, ""};
  // Bounded by periods / chunk_periods chunks.
  for (int done = 0; done < options.periods;) {
    const int chunk = std::min(options.chunk_periods, options.periods - done);
    SimulationOptions o = options.simulation;
    o.duration = chunk * period;
    o.sample_step = 0.0;
    if (options.simulation.progress) {
      o.progress = [&, done](const Progress& within) {
        options.simulation.progress({done + within.done, static_cast<double>(options.periods), "periods"});
      };
    }
    const SimulationResult r = simulate(p, transient.state, phi, o);
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

}  // namespace stickslip
