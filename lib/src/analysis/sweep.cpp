#include "stickslip/analysis/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "stickslip/analysis/settled_motion.hpp"
#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/model/transient.hpp"
#include "stickslip/orbits/orbit_measures.hpp"
#include "stickslip/numerics/parallel_for.hpp"

namespace stickslip {

namespace {

// The header's columns around the parameter's name. The second column, each row's way over the
// range (up, down or fixed), was "pass" until 0.1 (a Python keyword, awkward in pandas).
constexpr const char* kSweepColumnsBefore = "chain,direction,step,";
constexpr const char* kOlderSweepColumnsBefore = "chain,pass,step,";
// The columns between the parameter and the state, and after the state up to the amplitude's name.
constexpr const char* kSectionColumns = "section_phase,k";
constexpr const char* kMotionColumns = "stops_per_period,sticks_per_period,period,amplitude:";

double ValueAt(const SweepOptions& o, SweepPass pass, int step) {
  // The last step lands on the range's end exactly: to - (to - from) may miss `from` by an ulp,
  // and a valid end (u_r = u_s) would be refused or simulated outside its range.
  if (step == o.steps) return pass == SweepPass::kDown ? o.from : o.to;
  const double fraction = static_cast<double>(step) / o.steps;
  return pass == SweepPass::kDown ? o.to - fraction * (o.to - o.from) : o.from + fraction * (o.to - o.from);
}

// The swept parameter's index among the model's.
template <OscillatorModel Model>
int SweptParameter(const SweepOptions& o) {
  return o.parameter == SweepOptions::kForcingFrequency ? Model::kForcingFrequencyParameter : o.parameter;
}

// One point: transients from `start`, then the recorded section (SimulateSettled). Time 0 is a
// section time (the forcing phase there is phi_section, as at every multiple of the period). A
// simulation that stops early throws, naming the point, or is recorded so (record_incomplete).
template <OscillatorModel Model>
SweepPoint SimulatePoint(const Model& model, const typename Model::Parameters& base,
                         const typename Model::State& start, double phi_section, const SweepOptions& o, int chain,
                         SweepPass pass, int step) {
  typename Model::Parameters p = base;
  const int k = SweptParameter<Model>(o);
  Model::ParameterAt(p, k) = ValueAt(o, pass, step);
  const SettleOptions settle{o.transient_periods, o.recorded_periods, o.periodicity_tolerance,
                             o.max_events_per_simulation, o.relative_tolerance, o.chunk_periods, o.time_unit};
  BasicSettledMotion<Model> motion = SimulateSettled(model, p, start, phi_section, settle);
  if (!motion.Completed()) {
    std::string why = fmt::format("sweep: chain {}, {} pass, step {} ({} = {}): the simulation {}", chain, ToString(pass),
                                  step, model.Description().parameters[k].name, Model::ParameterAt(p, k), motion.message);
    if (!o.record_incomplete) throw std::runtime_error(why);
    // No amplitude: the motion was not followed to the end (nan, as a search cut short leaves it).
    SweepPoint point{chain, pass, step,          Model::ParameterAt(p, k), {Eigen::VectorXd(start)}, 0.0, 0.0, 0,
                     std::numeric_limits<double>::quiet_NaN(), {}};
    point.incomplete = std::move(why);
    return point;
  }
  std::vector<Eigen::VectorXd> section(motion.section.begin(), motion.section.end());
  return SweepPoint{chain, pass, step, Model::ParameterAt(p, k), std::move(section), motion.stops_per_period,
                    motion.sticks_per_period, motion.period, motion.contact_amplitude};
}

// A chain's up pass and then its down pass, each point from the last section state before it.
template <OscillatorModel Model>
std::vector<SweepPoint> ChainedPasses(const Model& model, const typename Model::Parameters& base,
                                      const typename Model::State& start, double phi_section, const SweepOptions& o,
                                      int chain, const std::function<void()>& point_done) {
  std::vector<SweepPoint> points;
  typename Model::State x = start;
  for (SweepPass pass : {SweepPass::kUp, SweepPass::kDown}) {
    for (int step = 0; step <= o.steps; ++step) {
      points.push_back(SimulatePoint(model, base, x, phi_section, o, chain, pass, step));
      if (points.back().incomplete.empty()) x = points.back().section.back();
      point_done();
    }
  }
  return points;
}

// Throws InvalidInput for what Sweep refuses before any simulation.
template <OscillatorModel Model>
void CheckSweep(const Model& model, const typename Model::Parameters& base,
                const std::vector<typename Model::State>& starts, const SweepOptions& options) {
  if (model.Autonomous() && !(options.time_unit > 0.0)) {
    throw InvalidInput("time_unit", options.time_unit, "time_unit > 0 for a model without forcing");
  }
  if (starts.empty()) throw InvalidInput("starts", "none", "at least one starting state");
  for (const auto& x : starts) {
    if (x.size() != model.StateSize()) throw InvalidInput("starts", fmt::format("a state of size {}", x.size()), fmt::format("the model's, {}", model.StateSize()));
  }
  const int k = SweptParameter<Model>(options);
  if (k < 0 || k >= Model::kParameterCount) {
    throw InvalidInput("parameter", options.parameter, fmt::format("0 <= parameter < {}", int{Model::kParameterCount}));
  }
  const ModelDescription& d = model.Description();
  if (model.Autonomous() && k == Model::kForcingFrequencyParameter) {
    throw InvalidInput("parameter", "'" + d.parameters[k].name + "'",
                       "one of the parameters of a model without forcing (its forcing frequency plays no part)");
  }
  if (std::find(d.state_columns.begin(), d.state_columns.end(), d.parameters[k].name) != d.state_columns.end()) {
    throw InvalidInput("parameter", "'" + d.parameters[k].name + "'",
                       "a parameter no state column shares its name with (a coordinate 'b' has the velocity column "
                       "v_b: rename it to sweep the belt's speed)");
  }
  if (options.steps < 1) throw InvalidInput("steps", options.steps, "steps >= 1");
  if (options.transient_periods < 0 || options.transient_periods > kMaxTransientPeriods) {
    throw InvalidInput("transient_periods", options.transient_periods,
                       fmt::format("0 <= transient_periods <= {}", kMaxTransientPeriods));
  }
  if (options.recorded_periods < 1) {
    throw InvalidInput("recorded_periods", options.recorded_periods, "recorded_periods >= 1");
  }
  auto invalid_at = [&](double value) {
    typename Model::Parameters p = base;
    Model::ParameterAt(p, k) = value;
    return model.Validate(p);
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
                                 ToString(pass), model.Description().parameters[k].name, value, invalid->what()));
      }
    }
  }
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

template <OscillatorModel Model>
std::vector<SweepPoint> Sweep(const Model& model, const typename Model::Parameters& base,
                              const std::vector<typename Model::State>& starts, double phi_section,
                              const SweepOptions& options) {
  CheckSweep(model, base, starts, options);
  const bool chained = options.start == SweepStart::kChained;
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
      slots[i] = ChainedPasses(model, base, starts[i], phi_section, options, i, point_done);
    } else {
      const int chain = i / per_chain;
      slots[i] = {SimulatePoint(model, base, starts[chain], phi_section, options, chain, SweepPass::kFixed, i % per_chain)};
      point_done();
    }
  });
  std::vector<SweepPoint> points;
  for (std::vector<SweepPoint>& slot : slots) {
    for (SweepPoint& p : slot) points.push_back(std::move(p));
  }
  return points;
}

std::vector<SweepPoint> Sweep(const Parameters& base, const std::vector<State>& starts, double phi_section,
                              const SweepOptions& options) {
  return Sweep(Pascal2014{}, base, starts, phi_section, options);
}

template <typename StateVector>
std::vector<StateVector> ScatteredStarts(const StateVector& centre, double half_width, int count, std::uint64_t seed) {
  // splitmix64 (Steele, Lea and Flood 2014): fixed arithmetic, unlike the standard library's
  // distributions, whose output is left to the implementation.
  auto next = [&seed] {
    std::uint64_t z = (seed += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  };
  std::vector<StateVector> starts;
  if (count > 0) starts.push_back(centre);
  for (int c = 1; c < count; ++c) {
    StateVector x = centre;
    for (Eigen::Index i = 0; i < x.size(); ++i) {
      const double unit = static_cast<double>(next() >> 11) * 0x1.0p-53;  // [0, 1), 53 random bits
      x(i) += half_width * (2.0 * unit - 1.0);
    }
    starts.push_back(x);
  }
  return starts;
}

bool IsSweepCsvHeader(std::string_view line) {
  // chain,direction,step,<parameter>,section_phase,k,<state...>,stops_per_period,...,amplitude:<q_c>
  const std::string_view before = line.starts_with(kOlderSweepColumnsBefore) ? kOlderSweepColumnsBefore : kSweepColumnsBefore;
  if (!line.starts_with(before)) return false;
  const std::string_view rest = line.substr(before.size());
  const std::size_t section = rest.find(fmt::format(",{},", kSectionColumns));
  const std::size_t motion = rest.rfind(fmt::format(",{}", kMotionColumns));
  if (section == std::string_view::npos || section == 0 || motion == std::string_view::npos || motion <= section) return false;
  const std::string_view contact = rest.substr(motion + 1 + std::string_view(kMotionColumns).size());
  return !contact.empty() && contact.find(',') == std::string_view::npos;
}

template <OscillatorModel Model>
std::string SweepCsv(const Model& model, const std::vector<SweepPoint>& points, int parameter, double phi_section) {
  const ModelDescription& d = model.Description();
  const int k = SweptParameter<Model>(SweepOptions{.parameter = parameter});
  std::string out = fmt::format("{}{},{},{},{}{}\n", kSweepColumnsBefore, d.parameters[k].name, kSectionColumns,
                                fmt::join(d.state_columns, ","), kMotionColumns, d.coordinates[ContactCoordinate(model)]);
  for (const SweepPoint& p : points) {
    for (std::size_t j = 0; j < p.section.size(); ++j) {
      out += fmt::format("{},{},{},{},{},{},{},{},{},{},{}\n", p.chain, ToString(p.pass), p.step, p.value, phi_section, j,
                         fmt::join(p.section[j], ","), p.stops_per_period, p.sticks_per_period, p.period,
                         p.contact_amplitude);
    }
  }
  return out;
}

template std::vector<SweepPoint> Sweep(const Pascal2014&, const Parameters&, const std::vector<State>&, double,
                                       const SweepOptions&);
template std::vector<SweepPoint> Sweep(const DynamicLinearOscillator&, const DynamicLinearOscillator::Parameters&,
                                       const std::vector<Eigen::VectorXd>&, double, const SweepOptions&);
template std::string SweepCsv(const Pascal2014&, const std::vector<SweepPoint>&, int, double);
template std::string SweepCsv(const DynamicLinearOscillator&, const std::vector<SweepPoint>&, int, double);
template std::vector<State> ScatteredStarts(const State&, double, int, std::uint64_t);
template std::vector<Eigen::VectorXd> ScatteredStarts(const Eigen::VectorXd&, double, int, std::uint64_t);

}  // namespace stickslip
