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

// Valid magnitudes. Eq. (3) scales time so that the stick's natural frequency is 1 and forces
// so that the forcing amplitude is 1; every other magnitude is judged against these units.
// Doubles carry 16 digits, events are located to 1e-13 in time and a zero is judged at 1e-11
// of its function's size (sinusoid_sum.hpp). Within the ranges below,
//   - every frequency (omega, 1, omega1 >= 1e-3, omega2 <= 10) lies within 1e3 of the unit, so
//     a segment or a forcing period holds a bounded number of oscillations and costs a bounded
//     number of root-finding steps;
//   - every force (eta u_r <= 1e5, chi eta (x2 - x1) <= 2e8) stays far from overflow, and the
//     unit forcing stays above the zero level of the constraints it enters;
//   - the friction force eta u_s >= 1e-8 stays above that zero level too, so that Coulomb's law
//     at a stop is decided by the physics and not by rounding (below u_s ~ 1e-15 the exact
//     simulator turned a stick of the 5.1 orbit into a slip);
//   - a phase omega t + phi keeps 10 digits after the point.
inline constexpr double kMinChi = 0.01, kMaxChi = 0.99;
inline constexpr double kMinEta = 0.01, kMaxEta = 100.0;
inline constexpr double kMinOmega = 0.01, kMaxOmega = 100.0;
inline constexpr double kMinSlidingFriction = 1e-6, kMaxFriction = 1000.0;
inline constexpr double kMaxStateMagnitude = 1e6;  // |x1|, |x2|, |x1'|, |x2'| and |phi| of a start
// The same ranges as the messages and --help print them.
inline constexpr std::string_view kChiRange = "0.01 <= chi <= 0.99";
inline constexpr std::string_view kEtaRange = "0.01 <= eta <= 100";
inline constexpr std::string_view kOmegaRange = "0.01 <= omega <= 100, not a natural frequency";
inline constexpr std::string_view kSlidingFrictionRange = "1e-06 <= u_s <= 1000";
inline constexpr std::string_view kStaticFrictionRange = "u_s <= u_r <= 1000";
inline constexpr std::string_view kStateRange = "|value| <= 1e+06";

// Checks every condition of eq. (4) and of the closed form: the ranges above, u_r >= u_s, all
// finite, and omega away from the natural frequencies omega1, omega2 (eq. 56) where the forced
// amplitude Q of eq. (7) is singular. Returns the first violation (not thrown: the solvers ask
// it of every iterate).
std::optional<InvalidInput> Validate(const Parameters& p);

// As Validate, for data in which `varied` is the value given (a map's second parameter): where
// u_r >= u_s fails with u_s the one given, the violation is u_s's, with its valid range given u_r
// ("1e-06 <= u_s <= u_r = 0.3"), not u_r's (whose range would then hold u_r).
std::optional<InvalidInput> Validate(const Parameters& p, ParameterId varied);

// Only what the closed-form flows need: finite values, chi, eta and omega in range and omega
// away from omega1, omega2. The friction levels enter the equations linearly and stay
// meaningful to the solvers beyond their physical range, where the admissibility margins take
// over.
std::optional<InvalidInput> ValidateClosedForm(const Parameters& p);

// A start state's component or phase within kStateRange; `name` is the field reported.
std::optional<InvalidInput> ValidateStateValue(std::string_view name, double value);

}  // namespace stickslip
