// The segment plan of an orbit type: for each segment, its mode, what ends it and the mode that
// follows (COCO's hybrid segments define each segment once as a mode, an event and a reset), and
// the end conditions the periodicity equations impose there. Decided once from the signature;
// the equations, the margins, the monodromy, the sampling and the verification all read it.
#pragma once

#include <span>
#include <vector>

#include "stickslip/model/pascal_2014/events.hpp"
#include "stickslip/model/pascal_2014/flows.hpp"
#include "stickslip/orbits/signature.hpp"

namespace stickslip {

// Which segments: the listed ones (what the periodicity equations cover), or one whole period
// (the listed ones and, for an antisymmetric orbit, their mirror images).
enum class Extent { kListed, kFullPeriod };

struct SegmentSpec {
  int listed = 0;  // the listed segment it is, or mirrors
  bool mirrored = false;
  Mode mode = Mode::kSlipNegative;
  Mode next = Mode::kSlipNegative;
  SegmentEndKind end = SegmentEndKind::kReversal;
};

std::vector<SegmentSpec> SegmentPlan(const Signature& signature, Extent extent);

// The scalar equations that end a segment, zero on the orbit:
enum class EndCondition {
  kStop,                  // x2' = 0 (eq. 14, 16, 30)
  kSlipAccelerationZero,  // x2'' = 0 as well at an abnormal stop (eq. 18, 23)
  kExitIntoSlipNegative,  // s - eta u_r = 0: G1 = 0 (eq. 11, 32, 48)
  kExitIntoSlipPositive,  // s + eta u_r = 0: G = 0 (eq. 11, 35, 37, 50)
};

// The end conditions of a segment end, in the order the periodicity equations list them.
std::span<const EndCondition> EndConditionsOf(SegmentEndKind end);

// The value of an end condition at the end state x and forcing phase of a segment in `mode`, for
// any model (model/oscillator_model.hpp). Templated on the scalar so that forward-mode AD gives
// its exact gradient.
template <typename Model, typename T>
T EndConditionValue(const Model& model, EndCondition condition, Mode mode,
                    const typename Model::template StateT<T>& x, const T& phase,
                    const typename Model::template ParametersT<T>& p) {
  switch (condition) {
    case EndCondition::kStop: return model.ContactVelocity(x, p);
    case EndCondition::kSlipAccelerationZero: return model.ContactAcceleration(mode, x, phase, p);
    case EndCondition::kExitIntoSlipNegative: return model.StickForce(x, phase, p) - model.StaticThreshold(p);
    case EndCondition::kExitIntoSlipPositive: break;
  }
  return model.StickForce(x, phase, p) + model.StaticThreshold(p);
}

}  // namespace stickslip
