// The type of a periodic orbit: the cyclic sequence of slip and stick segments, what ends each
// segment, the period and an optional half-period antisymmetry.
//
// Text form: modes separated by spaces, then options after a slash:
//   "slip- slip+ stick slip+"              (section 5.1)
//   "slip- stick slip- / antisymmetric"    (section 6: the listed half, then its mirror image)
//   "slip- slip+ / period 2"               (a subharmonic orbit of period 2 * 2 pi/omega)
// What ends a segment follows from the next mode: a slip followed by the opposite slip ends at
// a stop with reversal, by a stick at a stop into a stick, by the same slip at an abnormal stop
// (x2' = x2'' = 0, section 4.2); a stick followed by slip- ends where s = +eta u_r (G1 = 0), by
// slip+ where s = -eta u_r (G = 0) (eq. 11, 35). A stick cannot follow a stick.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stickslip/invalid_input.hpp"
#include "stickslip/model/mode.hpp"

namespace stickslip {

enum class SegmentEndKind {
  kReversal,        // stop, x2' changes sign (a normal stop)
  kStickEntry,      // stop into a stick
  kAbnormalStop,    // stop without reversal: x2' = x2'' = 0
  kExitToNegative,  // stick exit at s = +eta u_r into slip-
  kExitToPositive,  // stick exit at s = -eta u_r into slip+
};
const char* ToString(SegmentEndKind kind);

// How a segment in `mode` ends when `next` follows it (the rules above).
SegmentEndKind EndKindOf(Mode mode, Mode next);

// The mode with x2' of the opposite sign (the image under X -> -X); a stick is its own mirror.
Mode Mirror(Mode mode);

class Signature {
 public:
  // Throws InvalidInput if the sequence is empty, has a stick after a stick (cyclically), or
  // period_multiple < 1, or is even with antisymmetric.
  Signature(std::vector<Mode> segments, bool antisymmetric = false, int period_multiple = 1);

  // Parses the text form. Throws InvalidInput naming "signature", with a message saying where
  // and why ("signature 'slip- stik': token 2 'stik' is not a mode: valid slip-, slip+, stick").
  static Signature Parse(std::string_view text);
  std::string ToString() const;

  // The segments the periodicity equations cover: the whole period, or the first half when
  // antisymmetric.
  const std::vector<Mode>& segments() const { return segments_; }
  int size() const { return static_cast<int>(segments_.size()); }
  bool antisymmetric() const { return antisymmetric_; }
  int period_multiple() const { return period_multiple_; }

  // The mode after segment i (cyclic; after the last listed segment of an antisymmetric orbit
  // comes the mirror of the first) and how segment i ends.
  Mode NextMode(int i) const;
  SegmentEndKind EndKind(int i) const;
  // The listed segments over a whole period (the half and its mirror when antisymmetric).
  std::vector<Mode> FullPeriod() const;
  // Fraction of the orbit period the listed segments span: 1, or 1/2 when antisymmetric.
  double CoveredFraction() const { return antisymmetric_ ? 0.5 : 1.0; }

  bool operator==(const Signature&) const = default;

 private:
  std::vector<Mode> segments_;
  bool antisymmetric_ = false;
  int period_multiple_ = 1;
};

}  // namespace stickslip
