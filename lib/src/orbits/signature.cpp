#include "stickslip/orbits/signature.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {

const char* ToString(SegmentEndKind kind) {
  switch (kind) {
    case SegmentEndKind::kReversal: return "reversal";
    case SegmentEndKind::kStickEntry: return "stick-entry";
    case SegmentEndKind::kAbnormalStop: return "abnormal-stop";
    case SegmentEndKind::kExitToNegative: return "exit-to-slip-";
    case SegmentEndKind::kExitToPositive: break;
  }
  return "exit-to-slip+";
}

Mode Mirror(Mode mode) {
  switch (mode) {
    case Mode::kSlipNegative: return Mode::kSlipPositive;
    case Mode::kSlipPositive: return Mode::kSlipNegative;
    case Mode::kStick: break;
  }
  return Mode::kStick;
}

namespace {

// Empty if the cyclic sequence is valid, else why not.
std::string SequenceProblem(const std::vector<Mode>& segments, bool antisymmetric) {
  if (segments.empty()) return "it has no segment";
  const std::size_t n = segments.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Mode next = i + 1 < n ? segments[i + 1]
                                : (antisymmetric ? Mirror(segments.front()) : segments.front());
    if (segments[i] == Mode::kStick && next == Mode::kStick) {
      return fmt::format("segment {} is a stick followed by a stick{}", i + 1,
                         i + 1 < n ? "" : " (cyclically)");
    }
  }
  return {};
}

}  // namespace

Signature::Signature(std::vector<Mode> segments, bool antisymmetric, int period_multiple)
    : segments_(std::move(segments)), antisymmetric_(antisymmetric),
      period_multiple_(period_multiple) {
  auto fail = [&](const std::string& why) {
    return InvalidInput::WithMessage("signature", fmt::format("signature '{}': {}", ToString(), why));
  };
  if (const std::string problem = SequenceProblem(segments_, antisymmetric_); !problem.empty()) throw fail(problem);
  if (period_multiple_ < 1) throw fail(fmt::format("'period' must be at least 1, got {}", period_multiple_));
  // X(t + k pi/omega) = -X(t) needs the forcing to change sign over half the period: k odd.
  if (antisymmetric_ && period_multiple_ % 2 == 0) {
    throw fail(fmt::format("'antisymmetric' needs an odd 'period K' (the forcing must change sign over half the "
                           "period), got {}", period_multiple_));
  }
}

Signature Signature::Parse(std::string_view text) {
  auto fail = [&](const std::string& why) {
    return InvalidInput::WithMessage("signature", fmt::format("signature '{}': {}", text, why));
  };
  const std::size_t slash = text.find('/');
  std::istringstream modes(std::string(text.substr(0, slash)));
  std::vector<Mode> segments;
  std::string token;
  int index = 0;
  while (modes >> token) {
    ++index;
    const std::optional<Mode> mode = ModeFromString(token);
    if (!mode) {
      throw fail(fmt::format("token {} '{}' is not a mode: valid slip-, slip+, stick", index, token));
    }
    segments.push_back(*mode);
  }
  bool antisymmetric = false;
  int period_multiple = 1;
  if (slash != std::string_view::npos) {
    std::istringstream options(std::string(text.substr(slash + 1)));
    std::vector<std::string> seen;
    while (options >> token) {
      // "period 1 period 2" would silently keep the last: an option is given once.
      if (std::find(seen.begin(), seen.end(), token) != seen.end()) {
        throw fail(fmt::format("option '{}' is given twice", token));
      }
      seen.push_back(token);
      if (token == "antisymmetric") {
        antisymmetric = true;
      } else if (token == "period") {
        std::string value;
        if (!(options >> value) || value.find_first_not_of("0123456789") != std::string::npos ||
            value.size() > 3 || std::stoi(value) < 1) {
          throw fail("'period' needs a whole number 1 to 999 after it");
        }
        period_multiple = std::stoi(value);
      } else {
        throw fail(fmt::format("option '{}' after '/' is unknown: valid antisymmetric, period K", token));
      }
    }
  }
  return Signature(std::move(segments), antisymmetric, period_multiple);  // checks the sequence
}

std::string Signature::ToString() const {
  std::string text;
  for (Mode m : segments_) text += fmt::format("{}{}", text.empty() ? "" : " ", stickslip::ToString(m));
  std::string options;
  if (antisymmetric_) options += " antisymmetric";
  if (period_multiple_ != 1) options += fmt::format(" period {}", period_multiple_);
  return options.empty() ? text : text + " /" + options;
}

Mode Signature::NextMode(int i) const {
  if (i + 1 < size()) return segments_[i + 1];
  return antisymmetric_ ? Mirror(segments_.front()) : segments_.front();
}

SegmentEndKind Signature::EndKind(int i) const { return EndKindOf(segments_[i], NextMode(i)); }

SegmentEndKind EndKindOf(Mode mode, Mode next) {
  if (mode == Mode::kStick) {
    return next == Mode::kSlipNegative ? SegmentEndKind::kExitToNegative
                                       : SegmentEndKind::kExitToPositive;
  }
  if (next == Mode::kStick) return SegmentEndKind::kStickEntry;
  return next == mode ? SegmentEndKind::kAbnormalStop : SegmentEndKind::kReversal;
}

std::vector<Mode> Signature::FullPeriod() const {
  std::vector<Mode> full = segments_;
  if (antisymmetric_) {
    for (Mode m : segments_) full.push_back(Mirror(m));
  }
  return full;
}

}  // namespace stickslip
