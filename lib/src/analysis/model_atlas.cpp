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


// The grid's values; the last is `to` exactly.
std::vector<double> GridOf(const ModelAtlasOptions& o) {
  std::vector<double> grid;
  for (int i = 0; i <= o.steps; ++i) grid.push_back(GridValueAt(o.from, o.to, o.steps, i));
  return grid;
}

// The longest period FindModelOrbit reads: max_multiple forcing periods, or one stick-slip cycle
// without forcing.
int PeriodLimit(const Model& model, const ModelAtlasOptions& o) { return model.Autonomous() ? 1 : o.max_multiple; }

// Stage 1 as a brute-force map of one row: the grid along i, the model's first parameter that is
// neither the atlas's nor omega without forcing along j, held at its value.
ModelBruteForceMapOptions BruteForceOf(const Model& model, const Model::Parameters& base, const ModelAtlasOptions& o) {
  ModelBruteForceMapOptions map{.first = {o.parameter, o.from, o.to, o.steps}, .runs = o.brute_force};
  const ModelDescription& d = model.Description();
  for (int k = model.Autonomous() ? 1 : 0; k < d.ParameterCount() && map.second.parameter.empty(); ++k) {
    if (d.parameters[k].name == o.parameter) continue;
    const double value = Model::ParameterAt(base, k);
    map.second = {d.parameters[k].name, value, value, 0};
  }
  map.progress = o.progress;
  return map;
}

// The attractors of every grid value (the map's cells), in the order the runs found them (the
// fresh starts by start, then the chained sweep's up and down passes), each with its fate where
// the brute force decides it.
std::vector<ModelAtlasAttractor> AttractorsOf(const Model& model, const ModelBruteForceMap& map, const ModelAtlasOptions& o) {
  std::vector<ModelAtlasAttractor> attractors;
  for (const ModelMapCell& cell : map.cells) {
    for (std::size_t k = 0; k < cell.attractors.size(); ++k) {
      ModelAtlasAttractor a{.grid = cell.i, .value = cell.first, .index = static_cast<int>(k), .attractor = cell.attractors[k]};
      if (a.attractor.status == AttractorStatus::kIncomplete) {
        a.fate = AttractorFate::kIncomplete;
        a.reason = fmt::format("{} run(s) stopped early, the first: {}", a.attractor.starts, a.attractor.incomplete);
      } else if (a.attractor.status == AttractorStatus::kNotSettled) {
        a.reason = fmt::format("{} run(s) settled on no period of at most {} on the section", a.attractor.starts,
                               o.brute_force.recorded_periods / 2);
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
  const double unit = model.Autonomous() ? o.brute_force.time_unit : 2.0 * std::numbers::pi / model.ForcingFrequency(p);
  ModelFindOptions find;
  find.max_multiple = PeriodLimit(model, o);
  find.phi0 = o.brute_force.section_phase;
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
  ParallelFor(static_cast<int>(asked.size()), o.brute_force.threads, [&](int i) {
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
  const int k = ModelAxis{parameter}.IndexIn(model, "parameter");
  if (!(std::isfinite(from) && std::isfinite(to) && from < to)) {
    throw InvalidInput("range", fmt::format("'{},{}'", from, to), "finite LO < HI");
  }
  WholeNumber("steps", steps, 1, kMaxSteps);
  brute_force.Validate(model);
  WholeNumber("max-multiple", max_multiple, 1, ModelFindOptions::kMaxMultiple);
  WholeNumber("find-periods", find_periods, kMinFindPeriods, ModelBruteForceOptions::kMaxPeriods);
  WholeNumber("find-rounds", find_rounds, 1, kMaxFindRounds);
  WholeNumber("max-traces", max_traces, 1, kMaxTraces);
  if (static_cast<long long>(steps + 1) * brute_force.RunsPerValue() > kMaxRuns) {
    throw InvalidInput("steps", steps, fmt::format("(steps + 1) (starts + 3) <= {} runs", kMaxRuns));
  }
  if (2 * max_multiple > brute_force.recorded_periods && !model.Autonomous()) {
    throw InvalidInput("periods", brute_force.recorded_periods,
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
    Model::ParameterAt(p, k) = value;
    if (const std::optional<InvalidInput> invalid = model.Validate(p)) {
      throw InvalidInput::WithMessage("range", fmt::format("range = '{},{}' is invalid: grid value {} = {}: {}", from,
                                                           to, parameter, Model::ParameterAt(p, k), invalid->what()));
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
  atlas.brute_force = ComputeModelBruteForceMap(model, base, BruteForceOf(model, base, options));
  atlas.attractors = AttractorsOf(model, atlas.brute_force, options);
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
