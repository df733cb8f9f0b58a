#include "stickslip/analysis/model_brute_force.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <optional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "stickslip/analysis/sweep.hpp"
#include "stickslip/invalid_input.hpp"

namespace stickslip {

namespace {

using Model = DynamicLinearOscillator;

// The sweep's options: every value from each start afresh (kFixed), or from the neighbouring
// value's end up and down (kChained).
SweepOptions SweepOf(int parameter, const ModelAxis& axis, const ModelBruteForceOptions& o, SweepStart start) {
  SweepOptions s;
  s.parameter = parameter;
  s.from = axis.from;
  s.to = axis.to;
  s.steps = axis.steps;
  s.transient_periods = o.transient_periods;
  s.recorded_periods = o.recorded_periods;
  s.periodicity_tolerance = o.periodicity_tolerance;
  s.relative_tolerance = true;  // the model's units are its own
  s.chunk_periods = 20;         // short chunks: each event holds a state of the model's size
  s.time_unit = o.time_unit;
  s.start = start;
  s.threads = o.threads;
  s.record_incomplete = true;  // one motion that grows without bound ends as an attractor "incomplete"
  return s;
}

// The largest |component| of a section orbit's points (never 0: a rest point compares absolutely).
double SectionSize(const std::vector<Eigen::VectorXd>& section, int period) {
  double size = std::numeric_limits<double>::min();
  for (int k = 0; k < period; ++k) size = std::max(size, section[k].lpNorm<Eigen::Infinity>());
  return size;
}

// Whether two periodic runs end on one section orbit: the same period and the same points under a
// cyclic shift, within the tolerance times the larger size.
bool SameSectionOrbit(const ModelAttractor& a, const SweepPoint& p, double tolerance) {
  if (a.period != p.period) return false;
  const double within = tolerance * std::max(SectionSize(a.section, a.period), SectionSize(p.section, p.period));
  for (int shift = 0; shift < p.period; ++shift) {
    bool same = true;
    for (int k = 0; k < p.period && same; ++k) {
      same = (a.section[k] - p.section[(k + shift) % p.period]).lpNorm<Eigen::Infinity>() <= within;
    }
    if (same) return true;
  }
  return false;
}

AttractorStatus StatusOf(const SweepPoint& p) {
  if (!p.incomplete.empty()) return AttractorStatus::kIncomplete;
  return p.period > 0 ? AttractorStatus::kPeriodic : AttractorStatus::kNotSettled;
}

ModelAttractor AttractorOf(const SweepPoint& p) {
  ModelAttractor a{StatusOf(p), p.period, p.stops_per_period, p.sticks_per_period, p.contact_amplitude, 1, {}, p.incomplete};
  a.section.assign(p.section.begin(), p.section.begin() + (p.period > 0 ? p.period : 1));
  if (p.period == 0) a.section.front() = p.section.back();
  return a;
}

}  // namespace

double ModelAxis::ValueAt(int index) const { return GridValueAt(from, to, steps, index); }

int ModelAxis::IndexIn(const Model& model, const char* field) const {
  const ModelDescription& d = model.Description();
  const int k = d.VariedParameter(field, parameter, model.Autonomous());
  // The brute force's files name the parameter and the state's columns side by side.
  if (std::find(d.state_columns.begin(), d.state_columns.end(), parameter) != d.state_columns.end()) {
    throw InvalidInput(field, "'" + parameter + "'",
                       "a parameter no state column shares its name with (a coordinate 'b' has the velocity column "
                       "v_b: rename it to vary the belt's speed)");
  }
  return k;
}

void ModelBruteForceOptions::Validate(const Model& model) const {
  WholeNumber("transients", transient_periods, 0, kMaxPeriods);
  WholeNumber("periods", recorded_periods, 2, kMaxPeriods);
  WholeNumber("starts", scattered_starts, 0, kMaxScatteredStarts);
  WholeNumber("threads", threads, 0, 1024);
  if (!(scatter >= 0.0 && scatter <= 1e6)) throw InvalidInput("scatter", scatter, "0 <= scatter <= 1e6");
  if (centre.size() != 0 && centre.size() != model.StateSize()) {
    throw InvalidInput("centre", fmt::format("a state of size {}", centre.size()), fmt::format("the model's, {}", model.StateSize()));
  }
  if (!centre.allFinite() || !std::isfinite(section_phase)) {
    throw InvalidInput::WithMessage("centre", "centre or section_phase is invalid: valid finite numbers");
  }
  if (!(periodicity_tolerance >= kMinTolerance && periodicity_tolerance <= kMaxTolerance)) {
    throw InvalidInput("tolerance", periodicity_tolerance, "1e-14 <= tolerance <= 1e-2");
  }
  if (model.Autonomous() && !(std::isfinite(time_unit) && time_unit > 0.0)) {
    throw InvalidInput("time-unit", time_unit, "a finite time unit > 0 for a model without forcing");
  }
}

std::vector<std::vector<ModelAttractor>> ModelBruteForce(const Model& model, const Model::Parameters& base,
                                                         const ModelAxis& axis, const ModelBruteForceOptions& o) {
  const int parameter = axis.IndexIn(model, "parameter");
  o.Validate(model);
  // Rest, then the given centre and states scattered around it (as the paper's brute force starts).
  std::vector<Model::State> fresh = {Model::State::Zero(model.StateSize())};
  for (Model::State& x : ScatteredStarts<Model::State>(o.centre.size() == 0 ? fresh.front() : o.centre, o.scatter,
                                                       o.scattered_starts, o.seed)) {
    fresh.push_back(std::move(x));
  }
  SweepOptions fixed = SweepOf(parameter, axis, o, SweepStart::kFixed);
  SweepOptions chained = SweepOf(parameter, axis, o, SweepStart::kChained);
  const double total = static_cast<double>(axis.Count()) * o.RunsPerValue();
  double done = 0.0;
  std::mutex report;
  const auto counted = [&](const Progress& r) {
    if (!o.progress) return;
    const std::lock_guard<std::mutex> lock(report);
    done += 1.0;
    o.progress({done, total, "points", r.value});
  };
  fixed.progress = counted;
  chained.progress = counted;
  std::vector<SweepPoint> points = Sweep(model, base, fresh, o.section_phase, fixed);
  std::vector<SweepPoint> followed = Sweep(model, base, {fresh.front()}, o.section_phase, chained);
  points.insert(points.end(), followed.begin(), followed.end());
  std::vector<std::vector<ModelAttractor>> cells(axis.Count());
  for (const SweepPoint& p : points) {
    std::vector<ModelAttractor>& cell = cells[p.pass == SweepPass::kDown ? axis.steps - p.step : p.step];
    // The runs not settled are one entry, as are those stopped early: they cannot be told apart.
    const auto same = std::find_if(cell.begin(), cell.end(), [&](const ModelAttractor& a) {
      return StatusOf(p) == AttractorStatus::kPeriodic ? SameSectionOrbit(a, p, o.periodicity_tolerance)
                                                       : a.status == StatusOf(p);
    });
    if (same == cell.end()) {
      cell.push_back(AttractorOf(p));
    } else {
      ++same->starts;
    }
  }
  return cells;
}

}  // namespace stickslip
