#include "stickslip/invalid_input.hpp"

#include <cmath>
#include <string_view>
#include <unordered_map>

#include <fmt/format.h>

namespace stickslip {

namespace {

// The message is one line whatever the input held: control characters are written as escapes
// (a run name with a newline in it is shown as 'two\nlines').
std::string OneLine(std::string_view text) {
  std::string line;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n') {
      line += "\\n";
    } else if (c == '\t') {
      line += "\\t";
    } else if (u < 0x20 || u == 0x7f) {
      line += fmt::format("\\x{:02x}", u);
    } else {
      line += c;
    }
  }
  return line;
}

}  // namespace

InvalidInput::InvalidInput(std::string field, std::string value, std::string valid_range,
                           std::string message)
    : std::invalid_argument(OneLine(message)), field_(std::move(field)), value_(std::move(value)),
      valid_range_(std::move(valid_range)) {}

InvalidInput::InvalidInput(std::string field, std::string value, std::string valid_range)
    : InvalidInput(field, value, valid_range,
                   fmt::format("{} = {} is invalid: valid range {}", field, value, valid_range)) {}

InvalidInput::InvalidInput(std::string field, double value, std::string valid_range)
    : InvalidInput(std::move(field), fmt::format("{}", value), std::move(valid_range)) {}

InvalidInput InvalidInput::WithMessage(std::string field, std::string message) {
  return InvalidInput(std::move(field), "", "", std::move(message));
}

std::string InvalidInput::Predicate() const {
  const std::string_view message = what();
  if (!field_.empty() && message.starts_with(field_ + " ")) return std::string(message.substr(field_.size() + 1));
  return std::string(message);
}

InvalidInput InvalidInput::Renamed(std::string field) const {
  // A violation in the standard form names its field in the valid range too ("0 < loop_tolerance
  // <= 1e-2"): renamed there as well.
  if (!valid_range_.empty() && !field_.empty() &&
      std::string_view(what()) == fmt::format("{} = {} is invalid: valid range {}", field_, value_, valid_range_)) {
    std::string range = valid_range_;
    for (auto at = range.find(field_); at != std::string::npos; at = range.find(field_, at + field.size())) {
      range.replace(at, field_.size(), field);
    }
    return InvalidInput(std::move(field), value_, std::move(range));
  }
  const bool leading = Predicate().size() != std::string_view(what()).size();
  std::string message = leading ? fmt::format("{} {}", field, Predicate()) : std::string(what());
  return InvalidInput(std::move(field), value_, valid_range_, std::move(message));
}

int WholeNumber(std::string_view field, double value, int low, int high) {
  if (!(value >= low && value <= high) || value != std::trunc(value)) {
    throw InvalidInput(std::string(field), value, WholeNumberRange(field, low, high));
  }
  return static_cast<int>(value);
}

std::string WholeNumberRange(std::string_view field, int low, int high) {
  return fmt::format("whole numbers {} <= {} <= {}", low, field, high);
}

}  // namespace stickslip

namespace stickslip {

// One pass with the names seen so far: a caller may pass any number of names (100,000 took 25 s
// when every pair was compared).
void RefuseRepeatedNames(std::string_view field, const std::vector<std::pair<std::string, double>>& values,
                         std::string_view where) {
  std::unordered_map<std::string_view, std::size_t> first;
  for (std::size_t k = 0; k < values.size(); ++k) {
    const auto [seen, added] = first.emplace(values[k].first, k);
    if (!added) {
      throw InvalidInput::WithMessage(std::string(field), fmt::format("{} gives '{}' twice ({} and {}): give it once{}",
                                                                      field, values[k].first, values[seen->second].second,
                                                                      values[k].second, where));
    }
  }
}

}  // namespace stickslip
