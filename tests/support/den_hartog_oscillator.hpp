// A second model behind the model interface (model/oscillator_model.hpp), for the tests only: one
// mass on a spring against a fixed ground with Coulomb friction, undamped, forced harmonically
// (Den Hartog, Trans. ASME APM 53 (1931) 107). With m = k = 1 and the forcing amplitude 1:
//   x'' + x = cos(omega t + phi) + F,  F = -beta sign(x') in a slip, |F| <= beta_static in a stick.
// The state is (x, x'); the contact velocity is x'. Written from the equation above, sharing no
// code with the paper's model, so that a simulator or solver that works through the interface
// for both shows the seam is real.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/model/mode.hpp"
#include "stickslip/model/model_description.hpp"
#include "stickslip/numerics/sinusoid_sum.hpp"

namespace stickslip {

struct DenHartogOscillator {
  using State = Eigen::Vector2d;
  struct Parameters {
    double omega = 0.0;        // forcing frequency over the natural frequency, r
    double beta = 0.0;         // kinetic friction over the forcing amplitude, F/P0
    double beta_static = 0.0;  // static friction over the forcing amplitude, >= beta
  };
  // x(s) = offset + drift s + sum of sinusoids, s the time elapsed in the mode.
  struct Motion {
    double offset = 0.0;
    double drift = 0.0;
    std::vector<Sinusoid> terms;

    SinusoidSum Position() const { return SinusoidSum(offset, drift, terms); }
    State StateAt(double s) const {
      const SinusoidSum::Jet jet = Position().JetAt(s);
      return State(jet.value, jet.slope);
    }
  };

  const ModelDescription& Description() const {
    static const ModelDescription description{
        "den-hartog-1930",
        {{"omega", "forcing frequency ratio r", "1", 0.01, 100.0, "0.01 <= omega <= 100, omega != 1"},
         {"beta", "kinetic friction ratio F/P0", "1", 1e-6, 1000.0, "1e-06 <= beta <= 1000"},
         {"beta_static", "static friction ratio", "1", 1e-6, 1000.0, "beta <= beta_static <= 1000"}},
        {"x"},
        {"x", "x'"}};
    return description;
  }
  std::optional<InvalidInput> Validate(const Parameters& p) const {
    if (!(p.omega >= 0.01 && p.omega <= 100.0) || std::abs(p.omega - 1.0) < 1e-9) {
      return InvalidInput("omega", p.omega, Description().parameters[0].range);
    }
    if (!(p.beta >= 1e-6 && p.beta <= 1000.0)) return InvalidInput("beta", p.beta, Description().parameters[1].range);
    if (!(p.beta_static >= p.beta && p.beta_static <= 1000.0)) {
      return InvalidInput("beta_static", p.beta_static, fmt::format("beta = {} <= beta_static <= 1000", p.beta));
    }
    return std::nullopt;
  }

  // In a slip: the particular solution -beta dir + Q cos(omega s + phase), Q = 1/(1 - omega^2),
  // plus the free oscillation at frequency 1 that meets the start. In a stick x stays put.
  Motion MotionInMode(Mode mode, const State& start, double phase, const Parameters& p) const {
    if (mode == Mode::kStick) return Motion{start(0), start(1), {}};
    const double offset = -p.beta * SlipDirection(mode);
    const double q = 1.0 / (1.0 - p.omega * p.omega);
    const Sinusoid forced{p.omega, q * std::cos(phase), -q * std::sin(phase)};
    const Sinusoid free{1.0, start(0) - offset - forced.cos_coefficient, start(1) - p.omega * forced.sin_coefficient};
    return Motion{offset, 0.0, {forced, free}};
  }
  double ForcingFrequency(const Parameters& p) const { return p.omega; }

  double ContactVelocity(const State& x) const { return x(1); }
  State AtRest(const State& x) const { return State(x(0), 0.0); }
  bool NearRest(const State& x) const { return std::abs(x(1)) <= 1e-12 * (1.0 + std::abs(x(0))); }

  // The friction force a stick needs, sign as the paper's s: x - cos(phase) > beta_static drives
  // the mass towards negative x.
  double StickForce(const State& x, double phase, const Parameters&) const { return x(0) - std::cos(phase); }
  double StaticThreshold(const Parameters& p) const { return p.beta_static; }
  bool AbnormalStopsPossible(const Parameters& p) const {
    return std::abs(p.beta_static - p.beta) <= 1e-12 * p.beta_static;
  }
  Mode ModeFromRest(const State& x, double phase, const Parameters& p) const {
    const double s = StickForce(x, phase, p);
    if (s > p.beta_static) return Mode::kSlipNegative;
    if (s < -p.beta_static) return Mode::kSlipPositive;
    return Mode::kStick;
  }

  SinusoidSum ContactVelocityAlong(const Motion& motion) const { return motion.Position().Derivative(); }
  SinusoidSum StickForceAlong(const Motion& motion, double phase, const Parameters& p) const {
    std::vector<Sinusoid> terms = motion.terms;
    terms.push_back({p.omega, -std::cos(phase), std::sin(phase)});  // -cos(omega s + phase)
    return SinusoidSum(motion.offset, motion.drift, std::move(terms));
  }
  // For an integrator (integrable_oscillator_model.hpp), from the equation above alone: in a
  // stick x'' = 0 and x' stays 0.
  State VectorField(Mode mode, const State& x, double phase, const Parameters& p) const {
    if (mode == Mode::kStick) return State(x(1), 0.0);
    return State(x(1), -x(0) + std::cos(phase) - p.beta * SlipDirection(mode));
  }
  // x'' = 0 at rest needs F = x - cos(phase), changing at omega sin(phase) while x' = 0.
  double HoldingForce(const State& x, double phase, const Parameters&) const { return x(0) - std::cos(phase); }
  double HoldingForceRate(const State&, double phase, const Parameters& p) const { return p.omega * std::sin(phase); }
  double HoldingForceScale(const State& x, const Parameters&) const { return std::max(std::abs(x(0)), 1.0); }
};

}  // namespace stickslip
