#include "column_kinds.hpp"

#include <cmath>

#include <fmt/format.h>

#include "stickslip/model/pascal_2014.hpp"
#include "stickslip/orbits/start_problem.hpp"

namespace stickslip::detail {

namespace {

ValidValues Range(double min, double max, std::string text) {
  return {.min = min, .max = max, .text = std::move(text)};
}

// The model's description of parameter `id`: its name and valid range.
const ParameterDescription& Described(ParameterId id) {
  return Pascal2014{}.Description().parameters[static_cast<int>(id)];
}

}  // namespace

bool ValidValues::Holds(double value) const {
  if (std::isnan(value)) return nan;
  if (std::isinf(value)) return value > 0.0 ? inf : minus_inf;
  return finite && value >= min && value <= max;
}

ValidValues ModelParameter(ParameterId id) {
  const ParameterDescription& d = Described(id);
  return Range(d.minimum, d.maximum, fmt::format("{} <= {} <= {}", d.minimum, d.name, d.maximum));
}

ValidValues BranchParameter(ParameterId id) {
  const int k = static_cast<int>(id);
  if (k != Pascal2014::kKineticLevelParameter && k != Pascal2014::kStaticLevelParameter) return ModelParameter(id);
  const ParameterDescription& d = Described(id);
  return Range(-d.maximum, d.maximum,
               fmt::format("|{}| <= {} (a branch ends where a released {} reaches 0)", d.name, d.maximum,
                           Described(kAllParameters[Pascal2014::kKineticLevelParameter]).name));
}

ValidValues Finite() { return {.text = "a finite number"}; }

ValidValues Duration(std::string_view name, double period, bool admissible) {
  if (!admissible) return {.text = fmt::format("a finite number (a row past a change of orbit type)")};
  return Range(-kDurationRounding * period, period * (1.0 + kDurationRounding),
               fmt::format("0 <= {} <= {}, the orbit's period, to rounding ({} of it), on an admissible row", name,
                           period, kDurationRounding));
}

ValidValues Fraction(bool admissible) {
  if (!admissible) return {.text = "a finite number (a row past a change of orbit type)"};
  return Range(-kDurationRounding, 1.0 + kDurationRounding,
               fmt::format("0 to 1, to rounding ({}), on an admissible row", kDurationRounding));
}

ValidValues NonNegative() { return Range(0.0, std::numeric_limits<double>::infinity(), "a finite number >= 0"); }

ValidValues SettledAmplitude() {
  ValidValues valid = NonNegative();
  valid.nan = true;
  valid.text = "a finite number >= 0 or nan (not computed)";
  return valid;
}

ValidValues FrictionMeasure() {
  ValidValues valid = Finite();
  valid.nan = true;
  valid.text = "a finite number or nan (not computed)";
  return valid;
}

ValidValues Margin() {
  return {.inf = true, .nan = true, .text = "a finite number, inf (a margin that does not apply) or nan (not computed)"};
}

ValidValues FloquetValue() { return {.nan = true, .text = "a finite number, or nan (not computed)"}; }

ValidValues FloquetProduct() {
  return {.inf = true, .minus_inf = true, .nan = true,
          .text = "a finite number, inf or -inf (a product that overflows) or nan (not computed)"};
}

ValidValues SymmetryTest(bool antisymmetric) {
  if (antisymmetric) return FloquetProduct();
  return {.finite = false, .nan = true, .text = "nan (the orbit is not antisymmetric)"};
}

}  // namespace stickslip::detail
