#include "stickslip/analysis/sweep.hpp"

#include <cmath>
#include <functional>
#include <mutex>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "stickslip/analysis/settled_motion.hpp"
#include "stickslip/model/transient.hpp"
#include "stickslip/numerics/parallel_for.hpp"

namespace stickslip {

namespace {

// The header's columns around the parameter's name. The second column, each row's way over the
// range (up, down or fixed), was "pass" until 0.1 (a Python keyword, awkward in pandas).
constexpr const char* kSweepColumnsBefore = "chain,direction,step,";
constexpr const char* kOlderSweepColumnsBefore = "chain,pass,step,";
constexpr const char* kSweepColumnsAfter =
    "section_phase,k,x1,x2,v1,v2,stops_per_period,sticks_per_period,period,amplitude:x2";

double ValueAt(const SweepOptions& o, SweepPass pass, int step) {
  // The last step lands on the range's end exactly: to - (to - from) may miss `from` by an ulp,
  // and a valid end (u_r = u_s) would be refused or simulated outside its range.
  if (step == o.steps) return pass == SweepPass::kDown ? o.from : o.to;
  const double fraction = static_cast<double>(step) / o.steps;
  return pass == SweepPass::kDown ? o.to - fraction * (o.to - o.from) : o.from + fraction * (o.to - o.from);
}

// A simulation of the point that stopped early, named.
std::runtime_error PointError(const SweepOptions& o, int chain, SweepPass pass, int step, const Parameters& p,
                              const std::string& message) {
  return std::runtime_error(fmt::format("sweep: chain {}, {} pass, step {} ({} = {}): the simulation {}", chain,
                                        ToString(pass), step, ToString(o.parameter), p[o.parameter], message));
}

// One point: transients from `start`, then the recorded section (SimulateSettled). Time 0 is a
// section time (the forcing phase there is phi_section, as at every multiple of the period).
SweepPoint SimulatePoint(const Parameters& base, const State& start, double phi_section, const SweepOptions& o,
                         int chain, SweepPass pass, int step) {
  Parameters p = base;
  p[o.parameter] = ValueAt(o, pass, step);
  const SettleOptions settle{o.transient_periods, o.recorded_periods, o.periodicity_tolerance,
                             o.max_events_per_simulation};
  SettledMotion motion = SimulateSettled(p, start, phi_section, settle);
  if (!motion.Completed()) throw PointError(o, chain, pass, step, p, motion.message);
  return SweepPoint{chain,    pass, step, p[o.parameter], std::move(motion.section), motion.stops_per_period,
                    motion.sticks_per_period, motion.period, motion.amplitude_x2};
}

// A chain's up pass and then its down pass, each point from the last section state before it.
std::vector<SweepPoint> ChainedPasses(const Parameters& base, const State& start, double phi_section,
                                      const SweepOptions& o, int chain, const std::function<void()>& point_done) {
  std::vector<SweepPoint> points;
  State x = start;
  for (SweepPass pass : {SweepPass::kUp, SweepPass::kDown}) {
    for (int step = 0; step <= o.steps; ++step) {
      points.push_back(SimulatePoint(base, x, phi_section, o, chain, pass, step));
      x = points.back().section.back();
      point_done();
    }
  }
  return points;
}

}  // namespace

std::string ToString(SweepPass pass) {
  switch (pass) {
    case SweepPass::kUp: return "up";
    case SweepPass::kDown: return "down";
    case SweepPass::kFixed: return "fixed";
  }
  return "?";
}

std::vector<SweepPoint> Sweep(const Parameters& base, const std::vector<State>& starts, double phi_section,
                              const SweepOptions& options) {
  if (starts.empty()) throw InvalidInput("starts", "none", "at least one starting state");
  if (options.steps < 1) throw InvalidInput("steps", options.steps, "steps >= 1");
  if (options.transient_periods < 0 || options.transient_periods > kMaxTransientPeriods) {
    throw InvalidInput("transient_periods", options.transient_periods,
                       fmt::format("0 <= transient_periods <= {}", kMaxTransientPeriods));
  }
  if (options.recorded_periods < 1) {
    throw InvalidInput("recorded_periods", options.recorded_periods, "recorded_periods >= 1");
  }
  auto invalid_at = [&](double value) {
    Parameters p = base;
    p[options.parameter] = value;
    return Validate(p);
  };
  for (const auto& [field, value] : {std::pair{"from", options.from}, std::pair{"to", options.to}}) {
    if (const auto invalid = invalid_at(value)) throw InvalidInput::WithMessage(field, fmt::format("{}: {}", field, invalid->what()));
  }
  // Every value simulated, not only the ends: an interior one may fall on a natural frequency.
  const bool chained = options.start == SweepStart::kChained;
  for (SweepPass pass : chained ? std::vector{SweepPass::kUp, SweepPass::kDown} : std::vector{SweepPass::kFixed}) {
    for (int step = 0; step <= options.steps; ++step) {
      const double value = ValueAt(options, pass, step);
      if (const auto invalid = invalid_at(value)) {
        throw InvalidInput::WithMessage(
            "steps", fmt::format("steps = {} puts step {} of the {} pass at {} = {}: {}", options.steps, step,
                                 ToString(pass), ToString(options.parameter), value, invalid->what()));
      }
    }
  }
  const int chains = static_cast<int>(starts.size());
  const int per_chain = options.steps + 1;
  // Each work item fills its own slot; the slots are joined in index order, so the output is the
  // same for any number of threads.
  const int items = chained ? chains : chains * per_chain;
  std::vector<std::vector<SweepPoint>> slots(items);
  // Progress: the points done, counted and reported under one lock, so that the callback sees
  // one call at a time with the count increasing.
  const double total = static_cast<double>(chained ? chains * 2 * per_chain : items);
  std::mutex progress_mutex;
  long done = 0;
  const std::function<void()> point_done = [&] {
    if (!options.progress) return;
    std::lock_guard<std::mutex> lock(progress_mutex);
    options.progress({static_cast<double>(++done), total, "points"});
  };
  ParallelFor(items, options.threads, [&](int i) {
    if (chained) {
      slots[i] = ChainedPasses(base, starts[i], phi_section, options, i, point_done);
    } else {
      const int chain = i / per_chain;
      slots[i] = {SimulatePoint(base, starts[chain], phi_section, options, chain, SweepPass::kFixed, i % per_chain)};
      point_done();
    }
  });
  std::vector<SweepPoint> points;
  for (std::vector<SweepPoint>& slot : slots) {
    for (SweepPoint& p : slot) points.push_back(std::move(p));
  }
  return points;
}

std::vector<State> ScatteredStarts(const State& centre, double half_width, int count, std::uint64_t seed) {
  // splitmix64 (Steele, Lea and Flood 2014): fixed arithmetic, unlike the standard library's
  // distributions, whose output is left to the implementation.
  auto next = [&seed] {
    std::uint64_t z = (seed += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  };
  std::vector<State> starts;
  if (count > 0) starts.push_back(centre);
  for (int c = 1; c < count; ++c) {
    State x = centre;
    for (int i = 0; i < 4; ++i) {
      const double unit = static_cast<double>(next() >> 11) * 0x1.0p-53;  // [0, 1), 53 random bits
      x(i) += half_width * (2.0 * unit - 1.0);
    }
    starts.push_back(x);
  }
  return starts;
}

bool IsSweepCsvHeader(std::string_view line) {
  const std::string_view before = line.starts_with(kOlderSweepColumnsBefore) ? kOlderSweepColumnsBefore : kSweepColumnsBefore;
  const std::string_view after = kSweepColumnsAfter;
  if (line.size() < before.size() + after.size() + 1 || !line.starts_with(before) || !line.ends_with(after)) return false;
  const std::string_view parameter = line.substr(before.size(), line.size() - before.size() - after.size() - 1);
  return line[line.size() - after.size() - 1] == ',' && ParameterFromString(parameter).has_value();
}

std::string SweepCsv(const std::vector<SweepPoint>& points, ParameterId parameter, double phi_section) {
  std::string out = fmt::format("{}{},{}\n", kSweepColumnsBefore, ToString(parameter), kSweepColumnsAfter);
  for (const SweepPoint& p : points) {
    for (std::size_t k = 0; k < p.section.size(); ++k) {
      const State& x = p.section[k];
      out += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", p.chain, ToString(p.pass), p.step, p.value,
                         phi_section, k, x(0), x(1), x(2), x(3), p.stops_per_period, p.sticks_per_period, p.period,
                         p.amplitude_x2);
    }
  }
  return out;
}

}  // namespace stickslip
