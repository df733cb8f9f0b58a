#include "cli_common.hpp"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "stickslip/orbits/start_problem.hpp"

namespace stickslip::cli {

double ParseNumber(std::string_view field, std::string_view text, std::string_view valid_range) {
  double value = 0.0;
  std::string_view digits = text;
  if (digits.size() > 1 && digits.front() == '+') digits.remove_prefix(1);  // from_chars rejects '+'
  const char* end = digits.data() + digits.size();
  const auto [ptr, ec] = std::from_chars(digits.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) {
    throw InvalidInput::WithMessage(
        std::string(field), fmt::format("{} = '{}' is not a finite number: valid range {}", field, text, valid_range));
  }
  return value;
}

int SolvedOrbitExitCode(const Margin& smallest, const Verification& verification, std::string* reason) {
  if (std::isnan(smallest.value)) {
    *reason = fmt::format("the solution's admissibility is not known: margin {} is not defined (its root search was cut short)",
                          smallest.Name());
    return kExitNotAMotion;
  }
  if (!(smallest.value > 0)) {
    *reason = fmt::format("the solution is not a motion of the system: margin {} = {:.6g} <= 0", smallest.Name(),
                          smallest.value);
    return kExitNotAMotion;
  }
  if (!verification.Passed()) {
    *reason = "the solution failed its verification by simulation";
    return kExitNotAMotion;
  }
  return kExitOk;
}

int ParseCount(std::string_view field, const std::string& text, int lo, int hi) {
  const std::string range = fmt::format("{} <= {} <= {}, a whole number", lo, field, hi);
  const double value = ParseNumber(field, text, range);
  if (!(value >= lo && value <= hi && value == std::floor(value))) throw InvalidInput(std::string(field), text, range);
  return static_cast<int>(value);
}

std::string SetKeysHelp() {
  std::string help = "KEY=VALUE, repeatable; overrides the preset. Keys:";
  for (const SetKey& k : SetKeys()) {
    help += fmt::format("\n  {:<6} {} ({})", k.key, k.meaning, k.valid_range);
  }
  return help;
}

std::string DescribeParameters(const Parameters& p) {
  std::string text;
  for (ParameterId id : kAllParameters) {
    text += fmt::format("{}{}={}", text.empty() ? "" : " ", ToString(id), p[id]);
  }
  return text;
}

}  // namespace stickslip::cli
