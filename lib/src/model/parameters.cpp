#include "stickslip/model/parameters.hpp"

#include <cmath>

#include <fmt/format.h>

#include "stickslip/model/modal.hpp"

namespace stickslip {

const char* ToString(ParameterId id) {
  switch (id) {
    case ParameterId::kChi: return "chi";
    case ParameterId::kEta: return "eta";
    case ParameterId::kOmega: return "omega";
    case ParameterId::kSlidingFriction: return "u_s";
    case ParameterId::kStaticFriction: break;
  }
  return "u_r";
}

std::optional<ParameterId> ParameterFromString(std::string_view key) {
  for (ParameterId id : kAllParameters) {
    if (key == ToString(id)) return id;
  }
  return std::nullopt;
}

std::optional<InvalidInput> ValidateClosedForm(const Parameters& p) {
  for (ParameterId id : kAllParameters) {
    if (!std::isfinite(p[id])) {
      return InvalidInput(ToString(id), p[id], "a finite number");
    }
  }
  if (!(p.chi > 0.0 && p.chi < 1.0)) return InvalidInput("chi", p.chi, "0 < chi < 1");
  if (!(p.eta > 0.0)) return InvalidInput("eta", p.eta, "eta > 0");
  if (!(p.omega > 0.0)) return InvalidInput("omega", p.omega, "omega > 0");
  // Q of eq. (7) has the factor 1/((omega^2 - omega1^2)(omega^2 - omega2^2)); a relative gap of
  // 1e-9 keeps it below ~1e9 times its typical size, beyond which no result is meaningful.
  const auto [omega1, omega2] = NaturalFrequencies(p.chi, p.eta);
  for (double natural : {omega1, omega2}) {
    if (std::abs(p.omega - natural) <= 1e-9 * natural) {
      return InvalidInput(
          "omega", p.omega,
          fmt::format("omega > 0 away from the natural frequencies omega1 = {} and omega2 = {} "
                      "(relative gap > 1e-9)",
                      omega1, omega2));
    }
  }
  return std::nullopt;
}

std::optional<InvalidInput> Validate(const Parameters& p) {
  if (auto invalid = ValidateClosedForm(p)) return invalid;
  if (!(p.u_s > 0.0)) return InvalidInput("u_s", p.u_s, "u_s > 0");
  if (!(p.u_r >= p.u_s)) {
    return InvalidInput("u_r", p.u_r, fmt::format("u_r >= u_s = {}", p.u_s));
  }
  return std::nullopt;
}

}  // namespace stickslip
