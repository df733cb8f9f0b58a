#include "stickslip/model/sweep.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "stickslip/model/simulation.hpp"

namespace stickslip {

namespace {

std::vector<SweepPoint> SweepDirection(const Parameters& base, const State& start, double phi_section,
                                       const SweepOptions& o, int direction) {
  std::vector<SweepPoint> points;
  State x = start;
  for (int step = 0; step <= o.steps; ++step) {
    const double fraction = static_cast<double>(step) / o.steps;
    Parameters p = base;
    p[o.parameter] = direction > 0 ? o.from + fraction * (o.to - o.from) : o.to - fraction * (o.to - o.from);
    const double period = 2.0 * std::numbers::pi / p.omega;
    // Time 0 is a section time: the forcing phase there is phi_section, as at every multiple of
    // the period, so the last section state starts the next point.
    SimulationOptions transient;
    transient.duration = o.transient_periods * period;
    x = SimulateExact(p, x, phi_section, transient).segments.back().end;
    SimulationOptions record;
    record.duration = o.recorded_periods * period;
    record.sample_step = period;
    const SimulationResult r = SimulateExact(p, x, phi_section, record);
    SweepPoint point{direction, step, p[o.parameter], {}, 0.0, 0.0, 0};
    for (std::size_t k = 1; k < r.samples.size(); ++k) point.section.push_back(r.samples[k].state);
    for (const Event& e : r.events) {
      point.stops_per_period += e.kind == EventKind::kStop;
      point.sticks_per_period += e.mode_after == Mode::kStick;
    }
    point.stops_per_period /= o.recorded_periods;
    point.sticks_per_period /= o.recorded_periods;
    const int n = static_cast<int>(point.section.size());
    for (int candidate = 1; candidate <= n / 2 && point.period == 0; ++candidate) {
      bool repeats = true;
      for (int k = 0; k + candidate < n && repeats; ++k) {
        repeats = (point.section[k + candidate] - point.section[k]).lpNorm<Eigen::Infinity>() <= o.periodicity_tolerance;
      }
      if (repeats) point.period = candidate;
    }
    x = point.section.empty() ? x : point.section.back();
    points.push_back(std::move(point));
  }
  return points;
}

}  // namespace

std::vector<SweepPoint> Sweep(const Parameters& base, const State& start, double phi_section,
                              const SweepOptions& options) {
  std::vector<SweepPoint> up = SweepDirection(base, start, phi_section, options, 1);
  // Down from where the upward sweep ended: the hysteresis a brute-force diagram must show.
  const State turn = up.back().section.empty() ? start : up.back().section.back();
  std::vector<SweepPoint> down = SweepDirection(base, turn, phi_section, options, -1);
  up.insert(up.end(), down.begin(), down.end());
  return up;
}

std::string SweepCsv(const std::vector<SweepPoint>& points, ParameterId parameter, double phi_section) {
  std::string out = fmt::format(
      "direction,step,{},section_phase,k,x1,x2,v1,v2,stops_per_period,sticks_per_period,period\n", ToString(parameter));
  for (const SweepPoint& p : points) {
    for (std::size_t k = 0; k < p.section.size(); ++k) {
      const State& x = p.section[k];
      out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{}\n", p.direction > 0 ? "up" : "down", p.step, p.value,
                         phi_section, k,
                         x(0), x(1), x(2), x(3), p.stops_per_period, p.sticks_per_period, p.period);
    }
  }
  return out;
}

}  // namespace stickslip
