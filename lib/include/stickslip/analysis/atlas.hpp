// The atlas: every periodic motion over a range of one parameter, in three stages that compose
// what exists (and change none of it):
//   1. brute force (analysis/brute_force_map.hpp, one row): at every grid value of the parameter,
//      the attractors simulation finds from rest, from the neighbouring value's final state and
//      from scattered starts, each reduced to its least period;
//   2. exact orbits: FindOrbit (analysis/orbit_finder.hpp) from every attractor, periodic or not
//      yet settled, up to the period limit `max_multiple`. Its transient starts short (the motion
//      is there, or close) and doubles while the section does not repeat: the brute force's fixed
//      transient leaves slowly contracting motions unsettled, FindOrbit's rounds settle them;
//   3. traces (branches/trace.hpp) over the whole range, both ways, from each exact orbit that lies
//      on no branch traced so far (branches/branch_membership.hpp decides, on the exact orbit,
//      not on the simulated state, which a slowly contracting motion has not yet reached), and from
//      its mirror image (orbits/orbit_origin.hpp) where that lies on none either: the other motion of
//      an asymmetric pair, whose basin the brute force may have missed; and, where several margins
//      change sign at a branch's end and more than one adjacent type is confirmed there, from each
//      confirmed switch the trace did not take (TraceOptions::record_other_switches) that lies on
//      no branch: every adjacent type is followed, whichever one the step size made the chain take.
// Every attractor ends accounted for: on a branch (which, and the point), or unexplained with the
// reason (not settled, a period above the limit, FindOrbit's status and message).
//
// Stages 1 and 2 run on every thread; stage 3 is sequential in grid order (whether an orbit needs
// a trace depends on the traces before it), so the result does not depend on the thread count.
//
//   AtlasOptions o;
//   o.brute_force.first = {ParameterId::kOmega, 0.3, 0.95, 65};
//   const Atlas atlas = ComputeAtlas(paper_parameters, o);
//   for (const AtlasAttractor& a : atlas.attractors) if (a.branch < 0) report(a.reason);
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "stickslip/analysis/atlas_fate.hpp"
#include "stickslip/analysis/brute_force_map.hpp"
#include "stickslip/analysis/orbit_finder.hpp"
#include "stickslip/branches/branch_membership.hpp"
#include "stickslip/branches/trace.hpp"
#include "stickslip/progress.hpp"

namespace stickslip {

struct AtlasOptions {
  // The brute force: `first` is the atlas's parameter, its range and grid (steps intervals); the
  // starts, transient, record and threads as a brute-force map's. `second` is not used (the
  // atlas is one row), nor are shard and shards.
  BruteForceMapOptions brute_force;
  // The period limit: attractors of a longer period are listed, not solved (1 to kMaxMultiple).
  int max_multiple = 4;
  // FindOrbit from each attractor (its max_multiple is the atlas's). The transient starts at 250
  // forcing periods and doubles four times (up to 7750 in all) while the section does not repeat.
  FindOrbitOptions find = [] {
    FindOrbitOptions o;
    o.transient_periods = 250;
    return o;
  }();
  // Every trace: its range is the grid's; resonances, loops and switching as a trace's.
  ContinuationOptions continuation;
  TraceOptions trace;
  // Every trace's branches end as a resonance where, never sticking, they approach an undamped
  // slip's natural frequency to within this (OrbitContinuationSetup; 0 to 1, 0: never).
  double resonance_approach = kDefaultResonanceApproach;
  BranchMembershipOptions membership;  // its parameter is the atlas's
  // At most this many traces (1 to kMaxTraces); starts beyond it are not traced (an attractor then
  // says so: off-branch).
  int max_traces = 500;
  // Called per stage: "cells" of the brute force, then "attractors" solved, then "attractors"
  // placed (value = the parameter). Empty: no reports.
  ProgressCallback progress = {};

  static constexpr int kMaxMultiple = 100;
  static constexpr int kMaxTraces = 100000;
  // Throws InvalidInput naming the field ("grid" for a grid value where the parameters fail
  // Validate, "max_multiple", "resonance_approach", the brute force's, find's, trace's and
  // continuation's own fields).
  void Validate(const Parameters& base) const;
};


struct AtlasAttractor {
  int grid = 0;         // the grid index (the brute-force cell's i)
  double value = 0.0;   // the parameter there
  int index = 0;        // the attractor's index in its cell
  Attractor attractor;  // as the brute force found it
  std::optional<FindOrbitResult> found;  // where FindOrbit ran
  AttractorFate fate = AttractorFate::kNotSettled;
  int branch = -1;      // kOnBranch: index into Atlas::Branches()
  int point = -1;       // kOnBranch: the branch's point on the near side of the passage
  bool started_trace = false;  // the trace its exact orbit started is traces[trace]
  std::string reason;   // one line: where it lies, or why on none
};

// A trace of the atlas, from one attractor's exact orbit.
struct AtlasTrace {
  int attractor = 0;   // index into Atlas::attractors: the attractor being placed when it started
  bool mirror = false;  // started from the mirror image of the attractor's exact orbit
  // Started from a confirmed switch to the type `adjacent` that another trace did not take, at the
  // end of Branches()[from_branch]; -1 otherwise.
  int from_branch = -1;
  std::string adjacent;
  TraceResult result;
  int first_branch = 0;  // its branches are Atlas::Branches()[first_branch, first_branch + count)
  int count = 0;
};

struct Atlas {
  std::string parameter;      // the atlas's parameter (an orbit variable's name)
  BruteForceMap brute_force;
  std::vector<AtlasAttractor> attractors;  // by grid index, then in their cell's order
  std::vector<AtlasTrace> traces;          // in the order started
  // Every branch of every trace, in trace order, each trace's down chain then its up chain (as
  // a stored trace numbers them, io/trace_files.hpp): pointers into this atlas's `traces`.
  std::vector<const OrbitBranch*> Branches() const;
  // The periodic attractors with period <= max_multiple and an orbit type (those find was asked about
  // and did not find not settled, incomplete or without an orbit type: on a branch, off one, or
  // not solved), and those of them on a branch.
  int PeriodicWithinLimit() const;
  int OnBranches() const;
};

// The parameter the atlas's brute force (one row of a map) holds as its second axis, at its base
// value: one other than the atlas's `parameter`.
ParameterId HeldBeside(ParameterId parameter);

// The atlas around `base` (the parameter replaced at each grid value), sections at forcing phase
// 0. Throws InvalidInput (Validate); every numerical outcome is recorded. Bounded: the brute force's
// runs, one FindOrbit per attractor, and at most one trace per attractor.
Atlas ComputeAtlas(const Parameters& base, const AtlasOptions& options);

}  // namespace stickslip
