#include "number_text.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip::cli {

double ParseNumber(std::string_view field, std::string_view text, std::string_view valid_range) {
  double value = 0.0;
  std::string_view digits = text;
  // from_chars rejects a leading '+', so one is dropped; a sign after it ("+-5") stays and is
  // refused below.
  if (digits.size() > 1 && digits.front() == '+' && digits[1] != '-' && digits[1] != '+') digits.remove_prefix(1);
  const char* end = digits.data() + digits.size();
  const auto [ptr, ec] = std::from_chars(digits.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) {
    throw InvalidInput::WithMessage(
        std::string(field), fmt::format("{} = '{}' is not a finite number: valid range {}", field, text, valid_range));
  }
  return value;
}

int ParseCount(std::string_view field, std::string_view text, int low, int high) {
  return WholeNumber(field, ParseNumber(field, text, WholeNumberRange(field, low, high)), low, high);
}

}  // namespace stickslip::cli
