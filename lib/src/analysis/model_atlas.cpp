#include "stickslip/analysis/model_atlas.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numbers>
#include <utility>

#include <fmt/format.h>

#include "stickslip/analysis/atlas_placement.hpp"
#include "stickslip/branches/model_branch_membership.hpp"
#include "stickslip/branches/model_trace.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/numerics/parallel_for.hpp"
#include "stickslip/orbits/orbit_origin.hpp"

namespace stickslip {

namespace {

using Model = DynamicLinearOscillator;
using ModelBranch = BasicOrbitBranch<Model>;

void CheckCount(const char* field, long long value, long long low, long long high) {
  if (value < low || value > high) {
    throw InvalidInput(field, std::to_string(value), fmt::format("whole numbers {} <= {} <= {}", low, field, high));
  }
}

// The grid's values; the last is `to` exactly.
std::vector<double> GridOf(const ModelAtlasOptions& o) {
  std::vector<double> grid;
  for (int i = 0; i <= o.steps; ++i) grid.push_back(i == o.steps ? o.to : o.from + static_cast<double>(i) / o.steps * (o.to - o.from));
  return grid;
}

// The longest period FindModelOrbit reads: max_multiple forcing periods, or one stick-slip cycle
// without forcing.
int PeriodLimit(const Model& model, const ModelAtlasOptions& o) { return model.Autonomous() ? 1 : o.max_multiple; }

// The brute force's sweep options: every value from each start afresh (kFixed), or from the
// neighbouring value's end up and down (kChained).
SweepOptions SweepOf(const Model& model, const ModelAtlasOptions& o, SweepStart start) {
  SweepOptions s;
  s.parameter = *model.Description().ParameterIndex(o.parameter);
  s.from = o.from;
  s.to = o.to;
  s.steps = o.steps;
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

// Stage 1: the attractors of every grid value, in the order the runs found them (the fresh starts
// by start, then the chained sweep's up and down passes).
std::vector<ModelAtlasAttractor> BruteForce(const Model& model, const Model::Parameters& base, const ModelAtlasOptions& o,
                                            const std::vector<double>& grid) {
  // Rest, then the given centre and states scattered around it (as the paper's brute force starts).
  std::vector<Model::State> fresh = {Model::State::Zero(model.StateSize())};
  for (Model::State& x : ScatteredStarts<Model::State>(o.centre.size() == 0 ? fresh.front() : o.centre, o.scatter,
                                                       o.scattered_starts, o.seed)) {
    fresh.push_back(std::move(x));
  }
  SweepOptions fixed = SweepOf(model, o, SweepStart::kFixed);
  SweepOptions chained = SweepOf(model, o, SweepStart::kChained);
  const double total = static_cast<double>((o.steps + 1) * (fresh.size() + 2));
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
  std::vector<std::vector<ModelAttractor>> cells(o.steps + 1);
  for (const SweepPoint& p : points) {
    const int i = p.pass == SweepPass::kDown ? o.steps - p.step : p.step;
    std::vector<ModelAttractor>& cell = cells[i];
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
  std::vector<ModelAtlasAttractor> attractors;
  for (int i = 0; i <= o.steps; ++i) {
    for (std::size_t k = 0; k < cells[i].size(); ++k) {
      ModelAtlasAttractor a{.grid = i, .value = grid[i], .index = static_cast<int>(k), .attractor = cells[i][k]};
      if (a.attractor.status == AttractorStatus::kIncomplete) {
        a.fate = AttractorFate::kIncomplete;
        a.reason = fmt::format("{} run(s) stopped early, the first: {}", a.attractor.starts, a.attractor.incomplete);
      } else if (a.attractor.status == AttractorStatus::kNotSettled) {
        a.reason = fmt::format("{} run(s) settled on no period of at most {} on the section", a.attractor.starts,
                               o.recorded_periods / 2);
      } else if (a.attractor.period > PeriodLimit(model, o)) {
        a.fate = AttractorFate::kAboveLimit;
        a.reason = model.Autonomous()
                       ? fmt::format("{} stick-slip cycles to a period: find reads one", a.attractor.period)
                       : fmt::format("period {} is above the period limit {}", a.attractor.period, o.max_multiple);
      }
      attractors.push_back(std::move(a));
    }
  }
  return attractors;
}

// FindModelOrbit is asked about every attractor but one periodic above the limit or stopped early: a
// run not settled on the section may settle in its longer simulations.
bool Asked(const ModelAtlasAttractor& a, int max_multiple) {
  return a.attractor.status == AttractorStatus::kNotSettled ||
         (a.attractor.status == AttractorStatus::kPeriodic && a.attractor.period <= max_multiple);
}

// As the paper's atlas decides: a motion that had not settled is one not settled unless the brute
// force found it periodic (then find failed on it: not solved).
AttractorFate FateOfFind(const ModelAttractor& a, const ModelFindResult<Model>& found) {
  switch (found.status) {
    case FindOrbitStatus::kFound: return AttractorFate::kOffBranch;  // until stage 3 places it
    case FindOrbitStatus::kSimulationIncomplete: return AttractorFate::kIncomplete;
    case FindOrbitStatus::kNoOrbitType:
      if (!MotionNotSettled(found)) return AttractorFate::kNoOrbitType;
      return a.status == AttractorStatus::kPeriodic ? AttractorFate::kNotSolved : AttractorFate::kNotSettled;
    default: return AttractorFate::kNotSolved;
  }
}

// FindModelOrbit from the attractor's first section point (where the first run not settled ended),
// its simulation doubled while the motion it reads has not settled.
ModelFindResult<Model> FoundFrom(const Model& model, const Model::Parameters& p, const ModelAtlasAttractor& a,
                                 const ModelAtlasOptions& o) {
  const double unit = model.Autonomous() ? o.time_unit : 2.0 * std::numbers::pi / model.ForcingFrequency(p);
  ModelFindOptions find;
  find.max_multiple = PeriodLimit(model, o);
  find.phi0 = o.section_phase;
  ModelFindResult<Model> found;
  for (int round = 0; round < o.find_rounds; ++round) {
    find.duration = std::ldexp(o.find_periods * unit, round);
    // As find --model reads it: the last 2 max_multiple + 2 forcing periods (at least ten), or half.
    find.record = model.Autonomous() ? find.duration / 2 : std::min(find.duration, std::max(10, 2 * o.max_multiple + 2) * unit);
    found = FindModelOrbit(model, p, a.attractor.section.front(), find);
    if (!MotionNotSettled(found)) break;  // a permanent stick is one at any length
  }
  return found;
}

// Stage 2: the exact orbit of every attractor asked about, on every thread.
void SolveAttractors(const Model& model, const Model::Parameters& base, std::vector<ModelAtlasAttractor>& attractors,
                     const ModelAtlasOptions& o) {
  std::vector<int> asked;
  for (std::size_t k = 0; k < attractors.size(); ++k) {
    if (Asked(attractors[k], o.max_multiple)) asked.push_back(static_cast<int>(k));
  }
  const int parameter = *model.Description().ParameterIndex(o.parameter);
  std::mutex report;
  int done = 0;
  ParallelFor(static_cast<int>(asked.size()), o.threads, [&](int i) {
    ModelAtlasAttractor& a = attractors[asked[i]];
    Model::Parameters p = base;
    Model::ParameterAt(p, parameter) = a.value;
    try {
      a.found = FoundFrom(model, p, a, o);
      a.fate = FateOfFind(a.attractor, *a.found);
      a.reason = a.found->message;
    } catch (const InvalidInput& e) {  // a solution the simulators refuse (a period <= 0, a state not finite)
      a.found.reset();
      a.fate = AttractorFate::kNotSolved;
      a.reason = fmt::format("find cannot check its orbit: {}", e.what());
    }
    if (!o.progress) return;
    const std::lock_guard<std::mutex> lock(report);
    o.progress({static_cast<double>(++done), static_cast<double>(asked.size()), "attractors solved", a.value});
  });
}

// A [model] in stage 3: its traces at least period (a belt's antisymmetric orbit over its whole
// period in v_b, as find --model --trace), its membership, and the mirror image of an asymmetric
// orbit where the model has the symmetry (no belt speed).
AtlasPlacementHooks<Model> PlacementOf(const Model& model, const ModelAtlasOptions& options) {
  BranchMembershipOptions membership = options.membership;
  membership.parameter = options.parameter;
  const int k = *model.Description().ParameterIndex(options.parameter);
  return {
      .setup = [&model, &options, k](const BasicOrbit<Model>& start, const UnknownChoice& unknowns) {
        const bool unfold = k == Model::kRestVelocityParameter && start.signature.antisymmetric();
        BasicOrbitContinuationSetup<Model> setup{unfold ? Unfolded(start, 1) : start, unknowns, options.parameter,
                                                 ShootingChoice::kAuto, LinearSolverType::kKlu, options.continuation,
                                                 {}, {}, {}, options.trace.max_amplitude, options.resonance_approach,
                                                 model};
        setup.options.parameter_name = options.parameter;
        setup.options.lambda_min = options.from;
        setup.options.lambda_max = options.to;
        return AtLeastPeriod(std::move(setup));
      },
      .membership = [&model, membership](const BasicOrbit<Model>& orbit, const std::vector<const ModelBranch*>& branches) {
        return FindOnModelBranches(model, orbit, branches, membership);
      },
      .mirror = [](const BasicOrbit<Model>& orbit) -> std::optional<BasicOrbit<Model>> {
        const bool symmetric = Model::ParameterAt(orbit.parameters, Model::kRestVelocityParameter) == 0.0;
        if (orbit.signature.antisymmetric() || !symmetric) return std::nullopt;
        return MirrorImage(orbit);
      }};
}

}  // namespace

void ModelAtlasOptions::Validate(const Model& model, const Model::Parameters& base) const {
  const std::optional<int> k = model.Description().ParameterIndex(parameter);
  if (!k || (*k == Model::kForcingFrequencyParameter && model.Autonomous())) {
    std::string names;
    for (const ParameterDescription& d : model.Description().parameters) {
      if (!(d.name == "omega" && model.Autonomous())) names += (names.empty() ? "" : ", ") + d.name;
    }
    throw InvalidInput("parameter", "'" + parameter + "'",
                       model.Autonomous() ? names + " (omega plays no part without forcing: name one of these)" : names);
  }
  if (!(std::isfinite(from) && std::isfinite(to) && from < to)) {
    throw InvalidInput("range", fmt::format("'{},{}'", from, to), "finite LO < HI");
  }
  CheckCount("steps", steps, 1, kMaxSteps);
  CheckCount("transients", transient_periods, 0, kMaxPeriods);
  CheckCount("periods", recorded_periods, 2, kMaxPeriods);
  CheckCount("starts", scattered_starts, 0, kMaxScatteredStarts);
  CheckCount("max-multiple", max_multiple, 1, ModelFindOptions::kMaxMultiple);
  CheckCount("find-periods", find_periods, kMinFindPeriods, kMaxPeriods);
  CheckCount("find-rounds", find_rounds, 1, kMaxFindRounds);
  CheckCount("max-traces", max_traces, 1, kMaxTraces);
  CheckCount("threads", threads, 0, 1024);
  if (static_cast<long long>(steps + 1) * (scattered_starts + 3) > kMaxRuns) {
    throw InvalidInput("steps", steps, fmt::format("(steps + 1) (starts + 3) <= {} runs", kMaxRuns));
  }
  if (!(scatter >= 0.0 && scatter <= 1e6)) throw InvalidInput("scatter", scatter, "0 <= scatter <= 1e6");
  if (centre.size() != 0 && centre.size() != model.StateSize()) {
    throw InvalidInput("centre", fmt::format("a state of size {}", centre.size()), fmt::format("the model's, {}", model.StateSize()));
  }
  if (!centre.allFinite() || !std::isfinite(section_phase)) {
    throw InvalidInput::WithMessage("centre", "centre or section_phase is invalid: valid finite numbers");
  }
  if (!(periodicity_tolerance >= 1e-14 && periodicity_tolerance <= 1e-2)) {
    throw InvalidInput("tolerance", periodicity_tolerance, "1e-14 <= tolerance <= 1e-2");
  }
  if (model.Autonomous() && !(std::isfinite(time_unit) && time_unit > 0.0)) {
    throw InvalidInput("time-unit", time_unit, "a finite time unit > 0 for a model without forcing");
  }
  if (2 * max_multiple > recorded_periods && !model.Autonomous()) {
    throw InvalidInput("periods", recorded_periods,
                       fmt::format("at least 2 x max-multiple = {} (a period of k is read off 2 k recorded periods)",
                                   2 * max_multiple));
  }
  trace.Validate();
  CheckResonanceLimits(trace.max_amplitude, resonance_approach);
  membership.ValidateTolerances();
  ContinuationOptions c = continuation;
  c.parameter_index = 0;  // set for the trace's parameter
  c.lambda_min = from;
  c.lambda_max = to;
  c.Validate();
  // Every grid value one the model takes: the sweep refuses the others, naming them.
  for (const double value : GridOf(*this)) {
    Model::Parameters p = base;
    Model::ParameterAt(p, *k) = value;
    if (const std::optional<InvalidInput> invalid = model.Validate(p)) {
      throw InvalidInput::WithMessage("range", fmt::format("range = '{},{}' is invalid: grid value {} = {}: {}", from,
                                                           to, parameter, Model::ParameterAt(p, *k), invalid->what()));
    }
  }
}

std::vector<const ModelBranch*> ModelAtlas::Branches() const {
  std::vector<const ModelBranch*> branches;
  for (const ModelAtlasTrace& t : traces) {
    for (const auto* chain : {&t.result.down, &t.result.up}) {
      for (const auto& link : chain->links) branches.push_back(&link.branch);
    }
  }
  return branches;
}

int ModelAtlas::PeriodicWithinLimit() const {
  int n = 0;
  for (const ModelAtlasAttractor& a : attractors) {
    n += a.fate == AttractorFate::kOnBranch || a.fate == AttractorFate::kOffBranch || a.fate == AttractorFate::kNotSolved;
  }
  return n;
}

int ModelAtlas::OnBranches() const {
  int n = 0;
  for (const ModelAtlasAttractor& a : attractors) n += a.fate == AttractorFate::kOnBranch;
  return n;
}

ModelAtlas ComputeModelAtlas(const Model& model, const Model::Parameters& base, const ModelAtlasOptions& options) {
  options.Validate(model, base);
  ModelAtlas atlas{.model = model, .parameter = options.parameter};
  atlas.grid = GridOf(options);
  atlas.attractors = BruteForce(model, base, options, atlas.grid);
  SolveAttractors(model, base, atlas.attractors, options);
  AtlasPlacer<Model, ModelAtlas> placer(atlas, PlacementOf(atlas.model, options), options.trace, options.max_traces);
  for (std::size_t k = 0; k < atlas.attractors.size(); ++k) {
    const ModelAtlasAttractor& a = atlas.attractors[k];
    if (!a.found || a.found->status != FindOrbitStatus::kFound) continue;
    placer.Place(static_cast<int>(k), a.found->solution->orbit, UnknownChoice{});
    if (options.progress) {
      options.progress({static_cast<double>(k + 1), static_cast<double>(atlas.attractors.size()), "attractors placed", a.value});
    }
  }
  return atlas;
}

}  // namespace stickslip
