// Stage 3 of an atlas, the paper's (atlas.hpp) and any model's (model_atlas.hpp) alike: in grid
// order, each attractor's exact orbit placed on a branch traced before it, or else on the trace
// started from it; its mirror image traced where the model has that symmetry; and from every trace,
// each confirmed switch to an adjacent type that it did not take, where no branch holds it. What
// differs between models comes in as hooks: how a trace starts from an orbit, whether an orbit lies
// on the branches so far, whether its mirror image is a motion.
//
//   AtlasPlacer<Pascal2014, Atlas> placer(atlas, hooks, trace_options, max_traces);
//   for (int k : solved) placer.Place(k, unknowns_of(k));
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "stickslip/analysis/atlas_fate.hpp"
#include "stickslip/branches/branch_membership.hpp"
#include "stickslip/branches/trace.hpp"

namespace stickslip {

template <OscillatorModel Model>
struct AtlasPlacementHooks {
  using AnyOrbit = OrbitOfModel<Model>;
  using Branches = std::vector<const BasicOrbitBranch<Model>*>;
  // The trace's start from an orbit and the unknowns that make it square at a fixed parameter.
  std::function<BasicOrbitContinuationSetup<Model>(const AnyOrbit&, const UnknownChoice&)> setup;
  // Whether (and where) an orbit lies on the branches.
  std::function<BranchMembership(const AnyOrbit&, const Branches&)> membership;
  // The orbit's mirror image, where it is a motion of the model too (an asymmetric orbit of a
  // symmetric model); nullopt otherwise.
  std::function<std::optional<AnyOrbit>(const AnyOrbit&)> mirror;
};

// `AnyAtlas` holds `attractors` (each with fate, branch, point, reason, started_trace) and `traces`
// (each with attractor, mirror, from_branch, adjacent, result, first_branch, count), and Branches().
template <OscillatorModel Model, typename AnyAtlas>
class AtlasPlacer {
 public:
  using AnyOrbit = OrbitOfModel<Model>;
  using AnyTrace = typename decltype(AnyAtlas::traces)::value_type;

  AtlasPlacer(AnyAtlas& atlas, AtlasPlacementHooks<Model> hooks, TraceOptions trace, int max_traces)
      : atlas_(atlas), hooks_(std::move(hooks)), trace_(std::move(trace)), max_traces_(max_traces) {
    trace_.record_other_switches = true;
  }

  // The attractor `k`, whose exact orbit is `orbit` (its unknowns square at fixed parameters).
  void Place(int k, const AnyOrbit& orbit, const UnknownChoice& unknowns) {
    auto& a = atlas_.attractors[k];
    if (!PlaceOn(a, orbit)) {
      const std::size_t own = atlas_.traces.size();  // the index its own trace takes (its switches' come after)
      a.started_trace = TraceIfNew({.attractor = k}, orbit, unknowns);
      if (!PlaceOn(a, orbit)) {
        const auto& trace = atlas_.traces[a.started_trace ? own : 0];
        a.reason = a.started_trace ? fmt::format("its own trace does not pass through it ({}; down: {}; up: {})",
                                                 a.reason, trace.result.down.message, trace.result.up.message)
                                   : fmt::format("{}; max_traces = {} reached", a.reason, max_traces_);
      }
    }
    if (const std::optional<AnyOrbit> mirrored = hooks_.mirror(orbit)) {
      TraceIfNew({.attractor = k, .mirror = true}, *mirrored, unknowns);
    }
  }

 private:
  // The attractor `a` on a branch where its exact orbit lies on one (its reason either way).
  template <typename AnyAttractor>
  bool PlaceOn(AnyAttractor& a, const AnyOrbit& orbit) {
    const BranchMembership m = hooks_.membership(orbit, atlas_.Branches());
    a.reason = m.message;
    if (!m.on_branch) return false;
    a.fate = AttractorFate::kOnBranch;
    a.branch = m.branch;
    a.point = m.point;
    return true;
  }

  // Traces from `start` unless a branch holds it already or max_traces is reached; then from every
  // switch the new trace confirmed but did not take, in turn. True if `start` was traced.
  bool TraceIfNew(AnyTrace from, const AnyOrbit& start, const UnknownChoice& unknowns) {
    if (hooks_.membership(start, atlas_.Branches()).on_branch) return false;
    if (static_cast<int>(atlas_.traces.size()) >= max_traces_) return false;
    from.result = TraceOrbits(hooks_.setup(start, unknowns), trace_);
    from.first_branch = static_cast<int>(atlas_.Branches().size());
    for (const auto* chain : {&from.result.down, &from.result.up}) from.count += static_cast<int>(chain->links.size());
    atlas_.traces.push_back(std::move(from));
    // Copied out first: the traces below grow atlas_.traces.
    const AnyTrace& added = atlas_.traces.back();
    std::vector<std::pair<int, BasicTypeSwitch<Model>>> others;
    int branch = added.first_branch;
    for (const auto* chain : {&added.result.down, &added.result.up}) {
      for (const auto& link : chain->links) {
        for (const auto& sw : link.other_switches) others.emplace_back(branch, sw);
        ++branch;
      }
    }
    const int attractor = added.attractor;
    for (const auto& [at, sw] : others) {
      TraceIfNew({.attractor = attractor, .from_branch = at, .adjacent = sw.adjacent->edit.signature.ToString()},
                 sw.BranchStart(), sw.unknowns);
    }
    return true;
  }

  AnyAtlas& atlas_;
  AtlasPlacementHooks<Model> hooks_;
  TraceOptions trace_;
  int max_traces_ = 1;
};

}  // namespace stickslip
