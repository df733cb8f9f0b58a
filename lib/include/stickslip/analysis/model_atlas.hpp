// The atlas (atlas.hpp) of an oscillator of the user's (model/linear_oscillator.hpp): every periodic
// motion over a range of one of its parameters, in the paper's atlas's three stages, built from the
// parts every model has:
//   1. brute force (model_brute_force.hpp): at every grid value, runs from rest, from scattered
//      starts and from the neighbouring value's end both ways, merged into attractors: a one-row
//      brute-force map (model_brute_force_map.hpp), its second axis the model's first other
//      parameter held at its value (as the paper's atlas holds chi);
//   2. exact orbits (model_orbit_finder.hpp): FindModelOrbit from every attractor of period up to
//      max_multiple and from where the first run not settled ended, its simulation doubled
//      (find_rounds simulations at most) while the motion it reads has not settled;
//   3. traces (branches/model_trace.hpp), in grid order, from every exact orbit on no branch traced
//      before it (branches/model_branch_membership.hpp decides, on the exact orbit), from its mirror
//      image where the model has the symmetry (no belt speed: orbits/orbit_origin.hpp), and from
//      each confirmed switch a trace did not take at a branch's end that lies on none.
// Every attractor ends accounted for, with the fates of the paper's atlas (AttractorFate).
//
// Stages 1 and 2 run on every thread; stage 3 is sequential: the result does not depend on the
// thread count.
//
//   ModelAtlasOptions o;
//   o.parameter = "omega", o.from = 0.3, o.to = 0.95, o.steps = 26;
//   const ModelAtlas<DynamicLinearOscillator> atlas = ComputeModelAtlas(model, parameters, o);
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "stickslip/analysis/atlas_fate.hpp"
#include "stickslip/analysis/model_brute_force_map.hpp"
#include "stickslip/analysis/model_orbit_finder.hpp"
#include "stickslip/branches/branch_membership.hpp"
#include "stickslip/branches/trace.hpp"
#include "stickslip/orbits/linear_oscillator_problem.hpp"
#include "stickslip/progress.hpp"

namespace stickslip {

struct ModelAtlasOptions {
  std::string parameter = "omega";  // the atlas's parameter, by the model's name
  double from = 0.0;  // the range (from < to), every grid value one the model takes
  double to = 0.0;
  int steps = 20;     // grid intervals over the range (1 to kMaxSteps)
  // Its runs, periods and section; its threads are every stage's (its progress is replaced by the
  // atlas's).
  ModelBruteForceOptions brute_force;
  // The period limit, forcing periods (1 to ModelFindOptions::kMaxMultiple); without forcing one
  // stick-slip cycle, which is what FindModelOrbit reads.
  int max_multiple = 4;
  // FindModelOrbit from an attractor: find_periods periods first, doubled while the motion read
  // has not settled, find_rounds simulations at most (1 to kMaxFindRounds).
  int find_periods = 100;  // kMinFindPeriods to ModelBruteForceOptions::kMaxPeriods
  int find_rounds = 5;
  ContinuationOptions continuation;  // every trace's; its range is the atlas's
  TraceOptions trace;  // its max_amplitude in the model's units
  double resonance_approach = kDefaultResonanceApproach;
  BranchMembershipOptions membership;  // its parameter is the atlas's
  int max_traces = 500;  // 1 to kMaxTraces
  // Called per stage: "points" of the brute force, "attractors solved", "attractors placed".
  ProgressCallback progress = {};

  static constexpr int kMaxSteps = 10000;
  static constexpr int kMinFindPeriods = 2;
  static constexpr int kMaxFindRounds = 10;
  static constexpr int kMaxTraces = 100000;
  // Brute-force runs of one atlas, at most: (steps + 1) x (scattered_starts + 3).
  static constexpr long long kMaxRuns = 10000000;

  // Throws InvalidInput naming the field as the command line's flag ("parameter", "range" for a
  // value the model refuses, "steps", "max-multiple", "tolerance", ...), before any simulation.
  void Validate(const DynamicLinearOscillator& model, const DynamicLinearOscillator::Parameters& base) const;
};

struct ModelAtlasAttractor {
  int grid = 0;        // the grid index
  double value = 0.0;  // the parameter there
  int index = 0;       // in its grid value's order
  ModelAttractor attractor = {};
  std::optional<ModelFindResult<DynamicLinearOscillator>> found = {};  // where FindModelOrbit ran
  AttractorFate fate = AttractorFate::kNotSettled;
  int branch = -1;  // kOnBranch: index into ModelAtlas::Branches()
  int point = -1;   // kOnBranch: the branch's point on the near side of the passage
  bool started_trace = false;  // the trace its exact orbit started is in ModelAtlas::traces
  std::string reason = {};
};

struct ModelAtlasTrace {
  int attractor = 0;      // index into ModelAtlas::attractors: the one being placed when it started
  bool mirror = false;    // started from the mirror image of the attractor's exact orbit
  int from_branch = -1;   // a switch at the end of Branches()[from_branch] another trace did not take; else -1
  std::string adjacent = {};  // that switch's type
  BasicTraceResult<DynamicLinearOscillator> result = {};
  int first_branch = 0;   // its branches are Branches()[first_branch, first_branch + count)
  int count = 0;
};

struct ModelAtlas {
  DynamicLinearOscillator model;
  std::string parameter;
  std::vector<double> grid = {};  // the grid values
  ModelBruteForceMap brute_force = {};  // stage 1: one row, a cell per grid value
  std::vector<ModelAtlasAttractor> attractors = {};  // by grid index, then in their grid value's order
  std::vector<ModelAtlasTrace> traces = {};          // in the order started
  std::vector<const BasicOrbitBranch<DynamicLinearOscillator>*> Branches() const;
  int PeriodicWithinLimit() const;  // as Atlas's
  int OnBranches() const;
};

// The atlas of `model` around `base` (the parameter replaced at each grid value). Throws InvalidInput (Validate); every numerical outcome is recorded.
ModelAtlas ComputeModelAtlas(const DynamicLinearOscillator& model, const DynamicLinearOscillator::Parameters& base,
                             const ModelAtlasOptions& options);

}  // namespace stickslip
