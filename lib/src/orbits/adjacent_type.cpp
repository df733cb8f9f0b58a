#include "stickslip/orbits/adjacent_type.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "stickslip/invalid_input.hpp"

namespace stickslip {

namespace {

bool IsSlip(Mode mode) { return mode != Mode::kStick; }

// Whether margin `base` belongs to segment i of `signature` (margins.cpp adds them so).
bool BelongsTo(std::string_view base, int i, const Signature& signature) {
  const Mode mode = signature.segments()[i];
  const SegmentEndKind end = signature.EndKind(i);
  if (base == "duration" || base == "sliding-friction") return true;
  if (base == "velocity") return IsSlip(mode);
  if (base == "stop-slope") return end == SegmentEndKind::kReversal || end == SegmentEndKind::kStickEntry;
  if (base == "reversal") return end == SegmentEndKind::kReversal;
  if (base == "stick-entry") return end == SegmentEndKind::kStickEntry;
  if (base == "abnormal-stop") return end == SegmentEndKind::kAbnormalStop;
  if (base == "G" || base == "G1" || base == "exit-slope") return mode == Mode::kStick;
  return false;
}

constexpr std::array<std::string_view, 10> kMarginBases = {"duration",    "velocity",        "stop-slope", "reversal",
                                                           "stick-entry", "abnormal-stop",   "G",          "G1",
                                                           "exit-slope",  "sliding-friction"};

AdjacentType Inserted(const Signature& signature, int i, Mode mode, const char* bifurcation, std::string motion) {
  return {InsertSegment(signature, i + 1, mode), TypeEdit::kInsert, i, i + 1, bifurcation, std::move(motion)};
}

AdjacentType Split(const Signature& signature, int i, Mode mode, const char* bifurcation, std::string motion) {
  return {SplitSegment(signature, i, mode), TypeEdit::kSplit, i, i + 1, bifurcation, std::move(motion)};
}

// Slip i cut in two slips of its mode that meet at an abnormal stop: the first keeps i's start,
// neither keeps its duration.
AdjacentType SplitAtAbnormalStop(const Signature& signature, int i, const ContactWords& w) {
  SignatureEdit edit = InsertSegment(signature, i + 1, signature.segments()[i]);
  edit.duration_kept[i] = false;
  return {std::move(edit),
          TypeEdit::kSplitAtAbnormalStop,
          i,
          -1,
          w.abnormal_grazing,
          fmt::format("{} touches zero inside the slip with {} = 0 and goes on in the same direction: an abnormal stop",
                      w.velocity, w.acceleration)};
}

void AddRemovals(const Signature& signature, int i, bool equal_friction, std::vector<AdjacentType>* out) {
  const std::vector<Mode>& modes = signature.segments();
  const int n = signature.size();
  const bool stick = modes[i] == Mode::kStick;
  const Mode before = i > 0 ? modes[i - 1] : signature.antisymmetric() ? Mirror(modes[n - 1]) : modes[n - 1];
  const bool equal_neighbours = before == signature.NextMode(i);
  const char* bifurcation = stick ? "crossing-sliding (inverse)" : "vanishing slip";
  const std::string what = stick ? "the stick shrinks to nothing" : "the slip shrinks to nothing";
  // Equal slips may also stay apart at an abnormal stop, which needs u_r = u_s (ERRATA).
  const bool keep_apart = equal_neighbours && equal_friction && before != Mode::kStick;
  for (const bool join : {true, false}) {
    if (!join && !keep_apart) continue;
    try {
      out->push_back({RemoveSegment(signature, i, join), join ? TypeEdit::kRemove : TypeEdit::kRemoveKeepApart, i, -1,
                      bifurcation,
                      !equal_neighbours ? what + "; its neighbours meet at a stop"
                      : join            ? what + "; its neighbours, in the same mode, join into one segment"
                                        : what + "; its equal neighbours meet at an abnormal stop"});
    } catch (const InvalidInput&) {
      // The only segment, a join across the orbit's origin, or a stick beside a stick: no such type.
    }
  }
}

}  // namespace

const char* ToString(TypeEdit edit) {
  switch (edit) {
    case TypeEdit::kInsert: return "insert";
    case TypeEdit::kSplit: return "split";
    case TypeEdit::kSplitAtAbnormalStop: return "split-at-abnormal-stop";
    case TypeEdit::kRemove: return "remove";
    case TypeEdit::kRemoveKeepApart: return "remove-keep-apart";
  }
  return "?";
}

std::string NoAdjacentTypeReason(std::string_view base, const ContactWords& w) {
  if (base == "stop-slope") {
    return fmt::format("stop-slope: the stop becomes tangential ({} = 0 there); two roots of {} = 0 merge, the "
                       "branch of the same type folds, no segment appears or vanishes",
                       w.acceleration, w.velocity);
  }
  if (base == "exit-slope") {
    return fmt::format("exit-slope: {} reaches the exit level tangentially; two roots of the exit condition merge, "
                       "the branch of the same type exchanges roots, no segment appears or vanishes",
                       w.force);
  }
  if (base == "sliding-friction") return fmt::format("sliding-friction: {} ends the physical family", w.no_friction);
  return "";
}

std::vector<AdjacentType> AdjacentTypes(std::string_view base, int segment, const Signature& signature,
                                        bool equal_friction, const ContactWords& w) {
  if (std::find(kMarginBases.begin(), kMarginBases.end(), base) == kMarginBases.end()) {
    throw InvalidInput("margin", std::string(base),
                       "duration, velocity, stop-slope, reversal, stick-entry, "
                       "abnormal-stop, G, G1, exit-slope, sliding-friction");
  }
  if (base == "sliding-friction") return {};
  if (segment < 0 || segment >= signature.size()) {
    throw InvalidInput("segment", segment, fmt::format("0 <= segment < {}", signature.size()));
  }
  if (!BelongsTo(base, segment, signature)) {
    throw InvalidInput::WithMessage(
        "margin", fmt::format("margin = '{}:{}' is invalid: segment {} of '{}' ({}, ending at a {}) has no such margin",
                              base, segment + 1, segment + 1, signature.ToString(),
                              ToString(signature.segments()[segment]), ToString(signature.EndKind(segment))));
  }
  const int i = segment;
  const Mode mode = signature.segments()[i];
  std::vector<AdjacentType> out;
  if (base == "reversal") {
    out.push_back(Inserted(signature, i, Mode::kStick, "crossing-sliding",
                           fmt::format("the force at the stop stays inside the static band: the mass sticks there "
                                       "until {} reaches the exit level of the next slip",
                                       w.force)));
  } else if (base == "stick-entry") {
    out.push_back(Inserted(signature, i, Mirror(mode), "crossing-sliding (at the entry)",
                           "the force at the stop leaves the static band: the mass reverses and slips back before "
                           "it sticks"));
    // Where the stick has shrunk to nothing at the same point, the stop becomes a reversal (T0).
    AddRemovals(signature, (i + 1) % signature.size(), equal_friction, &out);
  } else if (base == "abnormal-stop") {
    out.push_back(Inserted(signature, i, Mode::kStick, "grazing-sliding (at the abnormal stop)",
                           fmt::format("{} reaches zero with {} of the wrong sign: the mass stops and sticks for an "
                                       "instant between the two slips",
                                       w.velocity, w.jerk)));
  } else if (base == "velocity") {
    out.push_back(Split(signature, i, Mode::kStick, "grazing-sliding",
                        fmt::format("{} touches zero inside the slip where |{}| = {} < {}: the mass stops and "
                                    "sticks, then slips on",
                                    w.velocity, w.force, w.kinetic_level, w.static_level)));
    if (equal_friction) out.push_back(SplitAtAbnormalStop(signature, i, w));
  } else if (base == "G" || base == "G1") {
    const bool g = base == "G";
    out.push_back(Split(signature, i, g ? Mode::kSlipPositive : Mode::kSlipNegative, "adding-sliding",
                        fmt::format("{} grazes {}{} inside the stick: the mass leaves it in a short {} and sticks again",
                                    w.force, g ? "-" : "+", w.static_level, g ? "slip+" : "slip-")));
  } else if (base == "duration") {
    AddRemovals(signature, i, equal_friction, &out);
  }
  return out;
}

}  // namespace stickslip
