#include "stickslip/model/pascal_2014/parameters.hpp"

#include <cmath>

#include <fmt/format.h>

#include "stickslip/model/pascal_2014/modal.hpp"
#include "stickslip/model/pascal_2014.hpp"

namespace stickslip {

const char* ToString(ParameterId id) {
  return Pascal2014{}.Description().parameters[static_cast<int>(id)].name.c_str();
}

std::optional<ParameterId> ParameterFromString(std::string_view key) {
  const std::optional<int> index = Pascal2014{}.Description().ParameterIndex(key);
  if (!index) return std::nullopt;
  return kAllParameters[*index];
}

std::optional<InvalidInput> ValidateClosedForm(const Parameters& p) {
  for (ParameterId id : kAllParameters) {
    if (!std::isfinite(p[id])) {
      return InvalidInput(ToString(id), p[id], "a finite number");
    }
  }
  if (!(p.chi >= kMinChi && p.chi <= kMaxChi)) return InvalidInput("chi", p.chi, std::string(kChiRange));
  if (!(p.eta >= kMinEta && p.eta <= kMaxEta)) return InvalidInput("eta", p.eta, std::string(kEtaRange));
  if (!(p.omega >= kMinOmega && p.omega <= kMaxOmega)) {
    return InvalidInput("omega", p.omega, std::string(kOmegaRange));
  }
  // Q of eq. (7) has the factor 1/((omega^2 - omega1^2)(omega^2 - omega2^2)); a relative gap of
  // 1e-9 keeps it below ~1e9 times its typical size, beyond which no result is meaningful.
  const auto [omega1, omega2] = NaturalFrequencies(p.chi, p.eta);
  for (double natural : {omega1, omega2}) {
    if (std::abs(p.omega - natural) <= 1e-9 * natural) {
      return InvalidInput(
          "omega", p.omega,
          fmt::format("0.01 <= omega <= 100 away from the natural frequencies omega1 = {} and omega2 = {} "
                      "(relative gap > 1e-9)",
                      omega1, omega2));
    }
  }
  return std::nullopt;
}

std::optional<InvalidInput> Validate(const Parameters& p) {
  if (auto invalid = ValidateClosedForm(p)) return invalid;
  if (!(p.u_s >= kMinSlidingFriction && p.u_s <= kMaxFriction)) {
    return InvalidInput("u_s", p.u_s, std::string(kSlidingFrictionRange));
  }
  if (!(p.u_r >= p.u_s && p.u_r <= kMaxFriction)) {
    return InvalidInput("u_r", p.u_r, fmt::format("u_s = {} <= u_r <= 1000", p.u_s));
  }
  return std::nullopt;
}

std::optional<InvalidInput> Validate(const Parameters& p, ParameterId varied) {
  std::optional<InvalidInput> invalid = Validate(p);
  const bool u_r_in_range = p.u_r >= kMinSlidingFriction && p.u_r <= kMaxFriction;
  if (invalid && invalid->field() == "u_r" && u_r_in_range && varied == ParameterId::kSlidingFriction) {
    return InvalidInput("u_s", p.u_s, fmt::format("1e-06 <= u_s <= u_r = {}", p.u_r));
  }
  return invalid;
}

std::optional<InvalidInput> ValidateStateValue(std::string_view name, double value) {
  if (!(std::abs(value) <= kMaxStateMagnitude)) return InvalidInput(std::string(name), value, std::string(kStateRange));
  return std::nullopt;
}

}  // namespace stickslip
