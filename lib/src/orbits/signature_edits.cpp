#include "stickslip/orbits/signature_edits.hpp"

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {

namespace {

void CheckSegment(const char* field, int i, int count) {
  if (i < 0 || i >= count) throw InvalidInput(field, i, fmt::format("0 <= {} < {}", field, count));
}

// The edited signature with every listed segment in place, ready for the edit to move them.
SignatureEdit Unchanged(const Signature& signature, std::vector<Mode> segments) {
  const int n = signature.size();
  SignatureEdit edit{Signature(std::move(segments), signature.antisymmetric(), signature.period_multiple()), {}, {}};
  for (int i = 0; i < n; ++i) edit.new_index.push_back(i);
  edit.duration_kept.assign(static_cast<std::size_t>(n), true);
  return edit;
}

}  // namespace

// The durations are "d1".."dn" for every model (orbit_layout.hpp); no other name changes.
std::string SignatureEdit::Renamed(std::string_view variable) const {
  const int n = static_cast<int>(new_index.size());
  int i = 0;
  while (i < n && variable != fmt::format("d{}", i + 1)) ++i;
  if (i == n) return std::string(variable);
  if (new_index[i] < 0 || !duration_kept[i]) {
    throw InvalidInput::WithMessage(
        std::string(variable), fmt::format("{} names the duration of segment {}, which the edit to '{}' split, joined "
                                           "or removed: it has no name in the edited type",
                                           variable, i + 1, signature.ToString()));
  }
  return fmt::format("d{}", new_index[i] + 1);
}

SignatureEdit InsertSegment(const Signature& signature, int position, Mode mode) {
  if (position < 0 || position > signature.size()) {
    throw InvalidInput("position", position, fmt::format("0 <= position <= {}", signature.size()));
  }
  std::vector<Mode> segments = signature.segments();
  segments.insert(segments.begin() + position, mode);
  SignatureEdit edit = Unchanged(signature, std::move(segments));
  for (int& index : edit.new_index) index += index >= position ? 1 : 0;
  return edit;
}

SignatureEdit RemoveSegment(const Signature& signature, int i, bool join_equal_neighbours) {
  const int n = signature.size();
  CheckSegment("segment", i, n);
  if (n == 1) throw InvalidInput("segment", i, "a segment of a signature with more than one");
  const std::vector<Mode>& modes = signature.segments();
  // The neighbours in the cyclic sequence: before the first listed segment of an antisymmetric
  // orbit comes the mirror of the last, after the last the mirror of the first.
  const Mode before = i > 0 ? modes[i - 1] : signature.antisymmetric() ? Mirror(modes[n - 1]) : modes[n - 1];
  const Mode after = signature.NextMode(i);
  const bool join = join_equal_neighbours && before == after;
  if (join && (i == 0 || i == n - 1)) {
    throw InvalidInput("segment", i,
                       "a segment whose neighbours do not join across the orbit's origin (the time origin is a "
                       "stop between them: rotate the orbit first)");
  }
  std::vector<Mode> segments = modes;
  segments.erase(segments.begin() + i, segments.begin() + i + (join ? 2 : 1));
  SignatureEdit edit = Unchanged(signature, std::move(segments));
  const int removed = join ? 2 : 1;
  for (int k = 0; k < n; ++k) edit.new_index[k] = k < i ? k : k < i + removed ? -1 : k - removed;
  if (join) edit.duration_kept[i - 1] = false;
  return edit;
}

SignatureEdit SplitSegment(const Signature& signature, int i, Mode inserted) {
  CheckSegment("segment", i, signature.size());
  std::vector<Mode> segments = signature.segments();
  segments.insert(segments.begin() + i + 1, {inserted, segments[i]});
  SignatureEdit edit = Unchanged(signature, std::move(segments));
  for (int& index : edit.new_index) index += index > i ? 2 : 0;
  edit.duration_kept[i] = false;
  return edit;
}

Signature Unfolded(const Signature& signature, int copies) {
  if (!(copies >= 1 && copies <= 64)) throw InvalidInput("copies", copies, "1 <= copies <= 64");
  const std::vector<Mode> period = signature.FullPeriod();
  std::vector<Mode> segments;
  for (int k = 0; k < copies; ++k) segments.insert(segments.end(), period.begin(), period.end());
  return Signature(std::move(segments), false, signature.period_multiple() * copies);
}

}  // namespace stickslip
