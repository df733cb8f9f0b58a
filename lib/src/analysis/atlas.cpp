#include "stickslip/analysis/atlas.hpp"

#include <atomic>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "stickslip/analysis/atlas_placement.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/numerics/parallel_for.hpp"
#include "stickslip/orbits/orbit_origin.hpp"

namespace stickslip {

const char* ToString(AttractorFate fate) {
  switch (fate) {
    case AttractorFate::kOnBranch: return "on-branch";
    case AttractorFate::kNotSettled: return "not-settled";
    case AttractorFate::kAboveLimit: return "above-period-limit";
    case AttractorFate::kIncomplete: return "incomplete";
    case AttractorFate::kNoOrbitType: return "no-orbit-type";
    case AttractorFate::kNotSolved: return "not-solved";
    case AttractorFate::kOffBranch: break;
  }
  return "off-branch";
}

namespace {

// The brute force of the atlas: one row, its second axis a parameter other than the atlas's held
// at its base value.
BruteForceMapOptions OneRow(const Parameters& base, const AtlasOptions& options) {
  BruteForceMapOptions row = options.brute_force;
  const ParameterId held = HeldBeside(row.first.parameter);
  row.second = {held, base[held], base[held], 0};
  row.shard = 1;
  row.shards = 1;
  row.progress = options.progress;
  return row;
}

FindOrbitOptions FindOf(const AtlasOptions& options) {
  FindOrbitOptions find = options.find;
  find.max_multiple = options.max_multiple;
  find.progress = {};
  return find;
}

// The fate of an attractor that FindOrbit is not asked about, if any.
std::optional<AttractorFate> FateWithoutFind(const Attractor& a, int max_multiple) {
  if (a.status == AttractorStatus::kIncomplete) return AttractorFate::kIncomplete;
  if (a.status == AttractorStatus::kPeriodic && a.period > max_multiple) return AttractorFate::kAboveLimit;
  return std::nullopt;
}

std::string ReasonWithoutFind(const AtlasAttractor& a, int max_multiple) {
  if (a.fate == AttractorFate::kIncomplete) return "a simulation stopped early (chattering or the event search's bound)";
  return fmt::format("period {} is above the period limit {}", a.attractor.period, max_multiple);
}

// Stage 1: the attractors of every grid value, in grid order, with the fate of those FindOrbit is
// not asked about.
std::vector<AtlasAttractor> AttractorsOf(const BruteForceMap& map, int max_multiple) {
  std::vector<AtlasAttractor> attractors;
  for (const MapCell& cell : map.cells) {
    for (std::size_t k = 0; k < cell.attractors.size(); ++k) {
      AtlasAttractor a{.grid = cell.i, .value = cell.first, .index = static_cast<int>(k), .attractor = cell.attractors[k]};
      if (const auto fate = FateWithoutFind(a.attractor, max_multiple)) {
        a.fate = *fate;
        a.reason = ReasonWithoutFind(a, max_multiple);
      }
      attractors.push_back(std::move(a));
    }
  }
  return attractors;
}

AttractorFate FateOfFind(const AtlasAttractor& a) {
  switch (a.found->status) {
    case FindOrbitStatus::kFound: return AttractorFate::kOffBranch;  // until stage 3 places it
    case FindOrbitStatus::kSimulationIncomplete: return AttractorFate::kIncomplete;
    case FindOrbitStatus::kNoOrbitType: return AttractorFate::kNoOrbitType;
    case FindOrbitStatus::kNotPeriodic:
      return a.attractor.status == AttractorStatus::kPeriodic ? AttractorFate::kNotSolved : AttractorFate::kNotSettled;
    default: return AttractorFate::kNotSolved;
  }
}

// Stage 2: FindOrbit from every attractor that needs it, on every thread (each writes its own).
void SolveAttractors(std::vector<AtlasAttractor>& attractors, const Parameters& base, ParameterId parameter,
                     double section_phase, const AtlasOptions& options) {
  std::vector<int> asked;
  for (std::size_t k = 0; k < attractors.size(); ++k) {
    if (!FateWithoutFind(attractors[k].attractor, options.max_multiple)) asked.push_back(static_cast<int>(k));
  }
  const FindOrbitOptions find = FindOf(options);
  std::mutex report;
  int done = 0;
  ParallelFor(static_cast<int>(asked.size()), options.brute_force.threads, [&](int i) {
    AtlasAttractor& a = attractors[asked[i]];
    Parameters p = base;
    p[parameter] = a.value;
    try {
      a.found = FindOrbit(p, a.attractor.section.front(), section_phase, find);
      a.fate = FateOfFind(a);
      a.reason = a.found->message;
    } catch (const InvalidInput& e) {  // a simulated state find does not take as a start (|x| > 1e6)
      a.fate = AttractorFate::kNotSolved;
      a.reason = fmt::format("find cannot start from its state: {}", e.what());
    }
    if (!options.progress) return;
    const std::lock_guard<std::mutex> lock(report);
    options.progress({static_cast<double>(++done), static_cast<double>(asked.size()), "attractors solved", a.value});
  });
}

OrbitContinuationSetup TraceStart(const Orbit& start, const UnknownChoice& unknowns, const std::string& parameter,
                                  const AtlasOptions& options) {
  OrbitContinuationSetup setup{start, unknowns, parameter, ShootingChoice::kAuto, LinearSolverType::kKlu,
                               options.continuation, {}, {}, {}};
  setup.options.parameter_name = parameter;
  setup.options.lambda_min = options.brute_force.first.from;
  setup.options.lambda_max = options.brute_force.first.to;
  setup.max_amplitude = options.trace.max_amplitude;
  setup.resonance_approach = options.resonance_approach;
  return setup;
}

// The paper's model in stage 3: its traces at least period, its membership, the mirror image of
// every asymmetric orbit (the model is odd under x -> -x with the forcing half a period on).
AtlasPlacementHooks<Pascal2014> PlacementOf(const std::string& parameter, const AtlasOptions& options) {
  BranchMembershipOptions membership = options.membership;
  membership.parameter = parameter;
  return {
      .setup = [parameter, &options](const Orbit& start, const UnknownChoice& unknowns) {
        return AtLeastPeriod(TraceStart(start, unknowns, parameter, options));
      },
      .membership = [membership](const Orbit& orbit, const std::vector<const OrbitBranch*>& branches) {
        return FindOnBranches(orbit, branches, membership);
      },
      .mirror = [](const Orbit& orbit) {
        return orbit.signature.antisymmetric() ? std::nullopt : std::optional<Orbit>(MirrorImage(orbit));
      }};
}

}  // namespace

ParameterId HeldBeside(ParameterId parameter) { return kAllParameters[parameter == kAllParameters[0] ? 1 : 0]; }

void AtlasOptions::Validate(const Parameters& base) const {
  if (max_multiple < 1 || max_multiple > kMaxMultiple) {
    throw InvalidInput("max_multiple", std::to_string(max_multiple), fmt::format("1 <= max_multiple <= {}", kMaxMultiple));
  }
  if (max_traces < 1 || max_traces > kMaxTraces) {
    throw InvalidInput("max_traces", std::to_string(max_traces), fmt::format("1 <= max_traces <= {}", kMaxTraces));
  }
  OneRow(base, *this).Validate(base);
  FindOf(*this).Validate();
  trace.Validate();
  CheckResonanceLimits(trace.max_amplitude, resonance_approach);
  membership.Validate();
  ContinuationOptions c = continuation;
  c.parameter_index = 0;  // ContinueOrbit sets it for the trace's parameter
  c.lambda_min = brute_force.first.from;
  c.lambda_max = brute_force.first.to;
  c.Validate();
}

std::vector<const OrbitBranch*> Atlas::Branches() const {
  std::vector<const OrbitBranch*> branches;
  for (const AtlasTrace& t : traces) {
    const std::vector<const OrbitBranch*> of_trace = BranchesOf(t.result);
    branches.insert(branches.end(), of_trace.begin(), of_trace.end());
  }
  return branches;
}

int Atlas::PeriodicWithinLimit() const {
  int n = 0;
  for (const AtlasAttractor& a : attractors) {
    n += a.fate == AttractorFate::kOnBranch || a.fate == AttractorFate::kOffBranch || a.fate == AttractorFate::kNotSolved;
  }
  return n;
}

int Atlas::OnBranches() const {
  int n = 0;
  for (const AtlasAttractor& a : attractors) n += a.fate == AttractorFate::kOnBranch;
  return n;
}

Atlas ComputeAtlas(const Parameters& base, const AtlasOptions& options) {
  options.Validate(base);
  const ParameterId parameter = options.brute_force.first.parameter;
  Atlas atlas;
  atlas.parameter = ToString(parameter);
  atlas.brute_force = ComputeBruteForceMap(base, 0.0, OneRow(base, options));
  atlas.attractors = AttractorsOf(atlas.brute_force, options.max_multiple);
  SolveAttractors(atlas.attractors, base, parameter, atlas.brute_force.section_phase, options);
  // Stage 3, in grid order: whether an orbit needs a trace depends on the traces before it.
  AtlasPlacer<Pascal2014, Atlas> placer(atlas, PlacementOf(atlas.parameter, options), options.trace, options.max_traces);
  for (std::size_t k = 0; k < atlas.attractors.size(); ++k) {
    const AtlasAttractor& a = atlas.attractors[k];
    if (!a.found || !a.found->Found()) continue;
    placer.Place(static_cast<int>(k), a.found->solution->orbit, a.found->problem->unknowns);
    if (options.progress) {
      options.progress({static_cast<double>(k + 1), static_cast<double>(atlas.attractors.size()), "attractors placed", a.value});
    }
  }
  return atlas;
}

}  // namespace stickslip
