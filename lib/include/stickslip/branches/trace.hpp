// A trace: the chain of orbit branches through the changes of orbit type, from one start in both
// directions of the continued parameter (as AUTO-07p's users chain runs with ch("IRS", ...); run(),
// and BifurcationKit's branch switching, automatically). Each branch ends as ContinueOrbit ends it:
// at a change of type (a margin leaving its admissible side). There SwitchAt (type_switch.hpp) tries
// the adjacent types of every margin located at that end, and the next branch starts on the first
// confirmed one, from its start (the located orbit on the new type) or, where that start is
// singular (a grazing), from the confirmed orbit past the boundary, in the direction the switch
// gives. A direction ends (TraceEnd):
//   parameter-bound      the branch reached the range bound (setup.options.lambda_min/max)
//   loop                 the chain came back to a point it visited: a branch ended where an earlier
//                        branch (of either direction) began or ended, with the same signature, the
//                        parameter and the orbit within loop_tolerance; where that is the other
//                        direction's last end, the chains met and both end so. A branch that closes
//                        on itself (BranchEnd::kClosedLoop) is a loop too
//   resonance            the amplitude, max |x1| and |x2| over the orbit (exact: the measures of
//                        orbits/orbit_measures.hpp), passed max_amplitude; or the orbit, never
//                        sticking, approached a natural frequency of the undamped slip to within
//                        OrbitContinuationSetup::resonance_approach, its amplitude growing
//                        (orbits/slip_resonance.hpp)
//   not-confirmed        no adjacent type confirmed by simulation (SwitchAt's reasons, per margin)
//   no-adjacent-type     the margin has none (a tangential end)
//   family-end           u_s reached 0 (sliding-friction), the end of the physical family
//   continuation-failed  a branch's start did not converge, or its step fell below ds_min
//   max-points           a branch reached setup.options.max_points
//   max-branches         the direction holds max_branches branches
//   not-a-motion         (both directions, no branch) the start, solved at its parameter, is not a
//                        motion of the system (a margin below -setup.options.start_boundary_tolerance):
//                        refused as `stickslip solve` refuses it, unless allow_inadmissible
// With follow_past_unswitched, a change of type with no confirmed switch does not end the direction:
// the same type is followed on past it (its points are not a motion: admissible = 0), up to the next
// located sign change of a margin, where the next branch starts: a regular one where the orbit is
// admissible again, else the same type on. The §5.1 family over omega, whose changes of type switch
// nowhere, is traced so round its loop.
//
//   OrbitContinuationSetup setup = MakeSetup(ReadRunFile("continuation-scripts/paper-4.1-omega-down.toml"), "results");
//   const TraceResult trace = TraceOrbits(setup, {});
//   for (const TraceLink& link : trace.down.links) use(link.branch, link.signature);
// For any model (model/oscillator_model.hpp): the paper's model is compiled once (trace.cpp); a
// program or test tracing another model's orbits includes branches/model_trace.hpp.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/branches/type_switch.hpp"
#include "stickslip/progress.hpp"

namespace stickslip {

struct TraceOptions {
  int max_branches = 50;        // per direction, 1 to kMaxTraceBranches
  // A resonance: max |x1|, |x2| over an orbit above this (> 0) ends a branch; the max_amplitude of
  // every branch of the trace (OrbitContinuationSetup).
  double max_amplitude = kDefaultMaxAmplitude;
  // Two points are one (a loop) when their signatures agree and the parameter (relative to
  // 1 + |lambda|), the start state, the phase and the period (OrbitDistance) differ by at most this.
  double loop_tolerance = 1e-7;
  // Follow the same type on past a change of type that switches nowhere (see above), instead of
  // ending the direction there.
  bool follow_past_unswitched = false;
  // Trace from a start that is not a motion of the system (a margin < 0 there: admissible = 0),
  // instead of refusing it (TraceEnd::kNotAMotion). A start on a type boundary (a margin zero to
  // setup.options.start_boundary_tolerance, a restart from a change of type) is no refusal.
  bool allow_inadmissible = false;
  // How many of the branches met at BP, PD and SB are followed, in the order met (0 to
  // kMaxTraceBranches): each continued as one branch from its start, ending as a branch does (no
  // switching on it); the others are recorded only.
  int follow_bifurcations = 0;
  // Where several margins change sign at a branch's end (section 4.1's omega = 0.5999775: SK, T0
  // and GR at once), try every one and record the confirmed switches the chain does not take
  // (TraceLink::other_switches); the chain takes the first, as without it. The atlas follows them.
  bool record_other_switches = false;
  TypeSwitchOptions type_switch;  // at every change of type
  // Called after every accepted point of every branch: done = the points so far, total =
  // 2 max_branches max_points (an upper bound), unit "points", value = lambda. Empty: no reports.
  ProgressCallback progress = {};

  // Throws InvalidInput naming the first field out of its valid range.
  void Validate() const;
  // The trace's own fields only (not type_switch), for the run-file reader; in trace_options.cpp.
  void ValidateOwnFields() const;
};

// The most branches a direction may hold, however the bound is given.
inline constexpr int kMaxTraceBranches = 10000;

enum class TraceEnd {
  kSwitched,        // (a branch's end) a switch was confirmed: the next branch starts on the new type
  kSameTypeOn,      // (a branch's end) the next branch is of the same type: followed on past a change
                    // that switched nowhere, or on from where it is admissible again
  kParameterBound,
  kLoop,
  kResonance,
  kNotConfirmed,
  kNoAdjacentType,
  kFamilyEnd,
  kContinuationFailed,
  kMaxPoints,
  kMaxBranches,
  kNotAMotion,  // the start is not a motion (TraceOptions::allow_inadmissible); nothing was traced
};
const char* ToString(TraceEnd end);

// How a branch of the chain began.
enum class LinkStart {
  kTraceStart,     // the trace's start
  kSwitch,         // a confirmed switch at the previous branch's end
  kFollowedPast,   // the same type followed past a change that switched nowhere
  kAdmissibleAgain,  // the same type, where its orbit is admissible again after a stretch followed past
};
const char* ToString(LinkStart start);

// A branch met on the way, at a BP, PD or SB of a link's branch (branches/bifurcation_branches.hpp):
// its start is computed and recorded; the first TraceOptions::follow_bifurcations of them are
// followed, the others not (a run file that restarts from the stored label with switch_branch
// follows one).
template <OscillatorModel Model>
struct BasicBifurcationMet {
  int point = 0;           // the special point's point on the link's branch (SpecialPoint::point)
  std::string type;        // "BP", "PD" or "SB"
  double lambda = 0.0;
  std::string signature;   // the type of the branch that leaves it; "" where its start failed
  double singularity = 0.0;  // BifurcationBranchStart::singularity
  std::string message;     // why the start failed, if it did
  std::optional<BasicOrbitBranch<Model>> followed;  // the branch that leaves it, where TraceOptions asked for it
};
using BifurcationMet = BasicBifurcationMet<Pascal2014>;

template <OscillatorModel Model>
struct BasicTraceLink {
  BasicOrbitBranch<Model> branch;
  std::string signature;  // Signature::ToString of the branch's orbits
  int direction = 1;      // the parameter's way at the branch's start: +1 up, -1 down
  LinkStart start = LinkStart::kTraceStart;
  std::string margin;     // the previous branch's margin that the switch (or the following) was at
  // kSwitch: the confirmed switch (margin, adjacent kind, persists or a nonsmooth fold, start and
  // past orbits); kFollowedPast: the one that confirmed nothing.
  std::optional<BasicTypeSwitch<Model>> type_switch;
  TraceEnd end = TraceEnd::kContinuationFailed;  // how the branch ended, in the trace's terms
  std::string message;
  std::vector<BasicBifurcationMet<Model>> bifurcations;  // at its located BP, PD and SB, in branch order
  // With TraceOptions::record_other_switches: the confirmed switches at its end the chain did not take.
  std::vector<BasicTypeSwitch<Model>> other_switches;
};
using TraceLink = BasicTraceLink<Pascal2014>;

template <OscillatorModel Model>
struct BasicTraceDirection {
  int direction = 1;                          // -1 down, +1 up
  std::vector<BasicTraceLink<Model>> links;   // in chain order; empty only if the first start failed
  TraceEnd end = TraceEnd::kContinuationFailed;
  std::string message;
};
using TraceDirection = BasicTraceDirection<Pascal2014>;

// Both directions ended at a bound, the family's end, a loop, a resonance, max-points or max-branches.
bool TraceCompleted(TraceEnd down, TraceEnd up);

template <OscillatorModel Model>
struct BasicTraceResult {
  std::string parameter;
  BasicTraceDirection<Model> down{-1, {}, TraceEnd::kContinuationFailed, {}};
  BasicTraceDirection<Model> up{1, {}, TraceEnd::kContinuationFailed, {}};
  // Both directions ended at a bound, the family's end, a loop, a resonance, max-points or max-branches.
  bool Completed() const { return TraceCompleted(down.end, up.end); }
  // Some branch failed to converge (continuation-failed).
  bool Failed() const {
    return down.end == TraceEnd::kContinuationFailed || up.end == TraceEnd::kContinuationFailed;
  }
  // The start is not a motion and the trace was refused (TraceEnd::kNotAMotion): no branches.
  bool NotAMotion() const { return down.end == TraceEnd::kNotAMotion; }
  // Some branch started (else there is nothing to store: the reason is down.message).
  bool HasBranches() const { return !down.links.empty() || !up.links.empty(); }
};
using TraceResult = BasicTraceResult<Pascal2014>;

// The trace from `start` (its orbit, unknowns, parameter and shooting, and the options of every
// branch: setup.options, whose lambda_min and lambda_max bound the whole trace and whose direction
// is not used, since the trace goes both ways; its user values apply to the branches of the start's
// signature only, whose unknowns they address). Throws InvalidInput for invalid options (also
// continue_past_terminal set: the trace decides at every change of type), as ContinueOrbit does for
// an invalid setup.
template <OscillatorModel Model>
BasicTraceResult<Model> TraceOrbits(const BasicOrbitContinuationSetup<Model>& start, const TraceOptions& options = {});

// `setup` with its start at its least period: a start whose signature repeats a shorter one and
// whose orbit is that shorter one written several times (a period-1 orbit listed over three periods,
// where a stick of a period-3 orbit vanishes onto the period-1 family) is continued as the shorter
// one, with the unknowns at fixed parameters (UnknownsAtFixedParameters): one motion, one branch
// type. Any other start as it is. A trace's switches go through it, and so does the atlas's start
// from a switch a trace did not take.
template <OscillatorModel Model>
BasicOrbitContinuationSetup<Model> AtLeastPeriod(BasicOrbitContinuationSetup<Model> setup);

extern template TraceResult TraceOrbits(const OrbitContinuationSetup& start, const TraceOptions& options);
extern template OrbitContinuationSetup AtLeastPeriod(OrbitContinuationSetup setup);

}  // namespace stickslip
