// The one walk over an orbit's segments: from the start state at the time origin, each segment
// of the plan (segment_plan.hpp) follows its model's closed-form motion in its mode for its
// duration, and the next starts where it ended. The margins, the monodromy, the sampling and the
// verification visit the segments through it; the periodicity equations walk the same plan in
// variational form, carrying the derivatives alongside (periodicity.cpp).
//
// Templated on the scalar so that forward-mode AD through the walk gives exact gradients with
// respect to every orbit variable (margin_gradients.hpp).
#pragma once

#include <span>
#include <vector>

#include "stickslip/model/pascal_2014.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/segment_plan.hpp"

namespace stickslip {

// How the forcing phase at a segment's start is formed. Both are omega t0 + phi up to rounding;
// the periodicity equations advance it segment by segment, the margins take it from the time
// origin. Each consumer keeps its rule so that stored results stay reproducible to the last bit.
enum class PhaseRule { kAccumulated, kFromOrigin };

template <typename T, typename Model = Pascal2014>
struct SegmentVisit {
  using State = typename Model::template StateT<T>;
  const SegmentSpec& spec;
  int index = 0;      // position in the walk
  bool last = false;  // the walk's last segment
  T t0{};             // start time, from the orbit's origin
  T duration{};
  T phase{};          // forcing phase at the start, omega t0 + phi
  T end_phase{};
  State start;
  typename Model::template MotionT<T> motion;  // from `start`, as a function of the time elapsed in the segment
  State end;
};

// Visits every segment of `plan` in order, for any model (model/oscillator_model.hpp).
// `durations` are the listed segments' (a mirrored segment takes the duration of the one it
// mirrors).
template <typename T, typename Model, typename Visit>
void WalkSegments(const Model& model, std::span<const SegmentSpec> plan, const typename Model::template StateT<T>& x0,
                  const T& phi, std::span<const T> durations, const typename Model::template ParametersT<T>& p,
                  PhaseRule rule, Visit&& visit) {
  typename Model::template StateT<T> x = x0;
  const T omega = model.ForcingFrequency(p);
  T t0 = T(0.0);
  T phase = phi;
  for (std::size_t k = 0; k < plan.size(); ++k) {
    const SegmentSpec& spec = plan[k];
    const T& d = durations[static_cast<std::size_t>(spec.listed)];
    if (rule == PhaseRule::kFromOrigin) phase = phi + omega * t0;
    SegmentVisit<T, Model> s{spec, static_cast<int>(k), k + 1 == plan.size(), t0, d, phase, phase + omega * d,
                             x, model.MotionInMode(spec.mode, x, phase, p), {}};
    s.end = s.motion.StateAt(d);
    visit(static_cast<const SegmentVisit<T, Model>&>(s));
    x = s.end;
    t0 = t0 + d;
    phase = s.end_phase;
  }
}

// The paper's model (model/pascal_2014.hpp).
template <typename T, typename Visit>
void WalkSegments(std::span<const SegmentSpec> plan, const StateT<T>& x0, const T& phi, std::span<const T> durations,
                  const BasicParameters<T>& p, PhaseRule rule, Visit&& visit) {
  WalkSegments<T>(Pascal2014{}, plan, x0, phi, durations, p, rule, std::forward<Visit>(visit));
}

// The walk over an orbit's own values.
template <typename Model, typename Visit>
void WalkSegments(const Model& model, const BasicOrbit<Model>& orbit, Extent extent, PhaseRule rule, Visit&& visit) {
  const std::vector<SegmentSpec> plan = SegmentPlan(orbit.signature, extent);
  WalkSegments<double>(model, plan, orbit.start, orbit.phi, std::span<const double>(orbit.durations), orbit.parameters,
                       rule, std::forward<Visit>(visit));
}
template <typename Visit>
void WalkSegments(const Orbit& orbit, Extent extent, PhaseRule rule, Visit&& visit) {
  const std::vector<SegmentSpec> plan = SegmentPlan(orbit.signature, extent);
  WalkSegments<double>(plan, orbit.InitialState(), orbit.phi, orbit.durations, orbit.parameters, rule,
                       std::forward<Visit>(visit));
}

}  // namespace stickslip
