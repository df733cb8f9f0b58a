// The physical data of the oscillator (Pascal 2014, eqs. 2-4) and their validation.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "stickslip/invalid_input.hpp"

namespace stickslip {

// The five parameters users may continue in. The order is the column order of every
// parameter derivative in stickslip (FlowDerivatives::d_parameters, ...).
enum class ParameterId { kChi, kEta, kOmega, kSlidingFriction, kStaticFriction };
inline constexpr int kParameterCount = 5;
inline constexpr std::array<ParameterId, kParameterCount> kAllParameters = {
    ParameterId::kChi, ParameterId::kEta, ParameterId::kOmega, ParameterId::kSlidingFriction,
    ParameterId::kStaticFriction};

// "chi", "eta", "omega", "u_s", "u_r": the keys used on the command line and in files.
const char* ToString(ParameterId id);
std::optional<ParameterId> ParameterFromString(std::string_view key);

// Dimensionless data of eq. (3). Templated on the scalar so that forward-mode automatic
// differentiation can carry derivatives with respect to each parameter.
template <typename T>
struct BasicParameters {
  T chi{};    // k2/(k1+k2), stiffness ratio, valid in (0, 1)
  T eta{};    // m1/m2, mass ratio, > 0
  T omega{};  // forcing frequency scaled by sqrt((k1+k2)/m1), > 0, not a natural frequency
  T u_s{};    // sliding friction level (force / (eta p)), > 0
  T u_r{};    // static friction level, >= u_s (eq. 4; u_r = u_s admits abnormal stops, eq. 25)

  T& operator[](ParameterId id) { return *Address(this, id); }
  const T& operator[](ParameterId id) const { return *Address(this, id); }

 private:
  template <typename Self>
  static auto Address(Self* self, ParameterId id) {
    switch (id) {
      case ParameterId::kChi: return &self->chi;
      case ParameterId::kEta: return &self->eta;
      case ParameterId::kOmega: return &self->omega;
      case ParameterId::kSlidingFriction: return &self->u_s;
      case ParameterId::kStaticFriction: break;
    }
    return &self->u_r;
  }
};
using Parameters = BasicParameters<double>;

// Checks every condition of eq. (4) and of the closed form: chi in (0,1), eta > 0, omega > 0,
// u_s > 0, u_r >= u_s, all finite, and omega away from the natural frequencies omega1, omega2
// (eq. 56) where the forced amplitude Q of eq. (7) is singular. Returns the first violation
// (not thrown: the solvers ask it of every iterate).
std::optional<InvalidInput> Validate(const Parameters& p);

// Only what the closed-form flows need: finite values, chi in (0,1), eta > 0, omega > 0 away
// from omega1, omega2. The friction levels enter the equations linearly and stay meaningful
// to the solvers beyond their physical range, where the admissibility margins take over.
std::optional<InvalidInput> ValidateClosedForm(const Parameters& p);

}  // namespace stickslip
