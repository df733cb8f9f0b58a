// Exact gradients of the admissibility margins (margins.hpp) with respect to every orbit variable,
// for any model: the full variable vector of periodicity_equations.hpp (for the paper's model
// orbit.hpp's x10, x20, v10, phi, d1..dn, chi, eta, omega, u_s, u_r):
// forward-mode AD through the segment walk (segment_walk.hpp) and the margin templates. What a
// two-parameter continuation of a type boundary adds to the periodicity system: margin = 0.
//
// A margin at a segment end depends on the variables through the end state and phase. A margin
// at an interior minimum of a function f(tau) of the time tau elapsed in its segment (velocity:i,
// G:i, G1:i) has, by the envelope theorem, the gradient of f at the fixed tau* (f_tau = 0 there),
// and tau* moves with d tau*/dv = -(d f_tau/dv) / f_tau_tau. A continuation that keeps tau* as an
// unknown adds f_tau = 0: `slope`, its gradient at fixed tau and `curvature` are that equation, at
// any tau (MarginGradientAt; branches/margin_condition.hpp).
#pragma once

#include <cmath>
#include <span>
#include <stdexcept>
#include <string_view>
#include <vector>

// <Eigen/Core> must precede the unsupported AutoDiff module.
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <fmt/format.h>

#include "stickslip/model/oscillator_model.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/segment_walk.hpp"

namespace stickslip {

struct MarginGradient {
  double value = 0.0;          // the margin, evaluated along the AD walk (AdmissibilityMargins' to rounding)
  Eigen::RowVectorXd d_value;  // d value / d variables
  double t = 0.0;              // where it is attained, from the orbit's origin (Margin::t)
  Eigen::RowVectorXd d_t;      // d t / d variables
  bool interior = false;       // an interior minimum in time: the fields below apply
  double slope = 0.0;          // f_tau at tau*: zero up to rounding
  Eigen::RowVectorXd d_slope;  // d f_tau / d variables at fixed tau
  double curvature = 0.0;      // f_tau_tau at tau*, > 0 at a minimum
};

namespace margin_gradients {

// One direction per orbit variable, and a last one for the time tau elapsed in a segment.
using Dual = Eigen::AutoDiffScalar<Eigen::VectorXd>;

// An interior margin's function and its time derivative at the time tau elapsed in the segment.
struct FunctionAlong {
  Dual f;
  Dual f_tau;
};

class GradientBuilder {
 public:
  explicit GradientBuilder(int variables) : variables_(variables) {}

  Dual Seed(double value, int direction) const { return Dual(value, variables_ + 1, direction); }
  Dual Constant(double value) const { return Dual(value, Eigen::VectorXd::Zero(variables_ + 1)); }
  Dual Tau(double tau) const { return Seed(tau, variables_); }

  // A margin attained at a time that is a function of the variables (a segment end or start).
  MarginGradient AtBoundary(const Margin& m, const Dual& f, const Dual& t) const {
    MarginGradient g = Empty(m);
    g.value = f.value();
    g.d_value = Head(f);
    g.d_t = Head(t);
    return g;
  }

  // An interior margin's function f at the time t0 + tau, tau seeded by Tau(): f's derivative along
  // tau is f_tau, and f_tau's is f_tau_tau. The gradients are at fixed tau; so is d_t.
  MarginGradient AtTime(const Margin& m, const FunctionAlong& f, const Dual& t0, const Dual& tau) const {
    MarginGradient g = Empty(m);
    g.interior = true;
    g.value = f.f.value();
    g.d_value = Head(f.f);
    g.t = t0.value() + tau.value();
    g.d_t = Head(t0);
    g.slope = f.f_tau.value();
    g.d_slope = Head(f.f_tau);
    g.curvature = f.f_tau.derivatives()(variables_);
    return g;
  }

  // A margin at an interior minimum in time of f, at tau* seeded by Tau(): by the envelope
  // theorem its gradient is f's at fixed tau*, and tau* moves with -(d f_tau) / f_tau_tau.
  MarginGradient AtInteriorMinimum(const Margin& m, const FunctionAlong& f, const Dual& t0, const Dual& tau) const {
    MarginGradient g = AtTime(m, f, t0, tau);
    g.t = m.t;
    g.d_t = g.d_t - g.d_slope / g.curvature;
    return g;
  }

  MarginGradient Empty(const Margin& m) const {
    MarginGradient g;
    g.value = m.value;
    g.t = m.t;
    g.d_value = g.d_t = g.d_slope = Eigen::RowVectorXd::Zero(variables_);
    return g;
  }

 private:
  Eigen::RowVectorXd Head(const Dual& x) const {
    return x.derivatives().size() == 0 ? Eigen::RowVectorXd::Zero(variables_)
                                       : Eigen::RowVectorXd(x.derivatives().head(variables_).transpose());
  }

  int variables_;
};

// The function an interior margin is the minimum of, at `tau` in segment `s`: sign(s) s of the
// contact velocity in a slip (velocity:i; the paper's x2'), G = F + F_s or G1 = -F + F_s of the
// stick force F in a stick (G:i, G1:i; eq. 35), with its time derivative.
template <typename Model>
FunctionAlong MarginFunction(const Model& model, const Margin& m, const SegmentVisit<Dual, Model>& s,
                             const typename Model::template ParametersT<Dual>& p, const Dual& tau) {
  const typename Model::template StateT<Dual> x = s.motion.StateAt(tau);
  const Dual phase = s.phase + model.ForcingFrequency(p) * tau;
  if (m.kind == MarginKind::kSlipVelocity) {
    const double sigma = SlipDirection(s.spec.mode);
    return {sigma * model.ContactVelocity(x, p), sigma * model.ContactAcceleration(s.spec.mode, x, phase, p)};
  }
  const double side = std::string_view(m.base) == "G" ? 1.0 : -1.0;
  return {side * model.StickForce(x, phase, p) + model.StaticThreshold(p), side * model.StickForceRate(x, phase, p)};
}

template <typename Model>
MarginGradient SegmentMarginGradient(const Model& model, const Margin& m, const SegmentVisit<Dual, Model>& s,
                                     const typename Model::template ParametersT<Dual>& p, const GradientBuilder& b) {
  const Mode mode = s.spec.mode;
  const Dual t_end = s.t0 + s.duration;
  switch (m.kind) {
    case MarginKind::kDuration: return b.AtBoundary(m, s.duration, s.t0);
    case MarginKind::kStopSlope: return b.AtBoundary(m, StopSlope(model, mode, s.end, s.end_phase, p), t_end);
    case MarginKind::kExitSlope: return b.AtBoundary(m, ExitSlope(model, s.spec.end, s.end, s.end_phase, p), t_end);
    case MarginKind::kStopForce:
      switch (s.spec.end) {
        case SegmentEndKind::kReversal:
          return b.AtBoundary(m, ReversalForce(model, s.spec.next, s.end, s.end_phase, p), t_end);
        case SegmentEndKind::kStickEntry: return b.AtBoundary(m, StickEntryForce(model, s.end, s.end_phase, p), t_end);
        default: return b.AtBoundary(m, AbnormalStopJerk(model, mode, s.end, s.end_phase, p), t_end);
      }
    case MarginKind::kSlipVelocity: {
      if (!std::isfinite(m.value)) return b.Empty(m);
      const Dual tau = b.Tau(m.t - s.t0.value());
      return b.AtInteriorMinimum(m, MarginFunction(model, m, s, p, tau), s.t0, tau);
    }
    case MarginKind::kStickConstraint: {
      // The minimum is interior, or at the stick's start or end.
      const double tau_star = m.t - s.t0.value();
      const bool at_start = tau_star == 0.0;
      const bool at_end = m.t == t_end.value();
      const Dual tau = at_start ? b.Constant(0.0) : at_end ? s.duration : b.Tau(tau_star);
      const FunctionAlong f = MarginFunction(model, m, s, p, tau);
      if (at_start || at_end) return b.AtBoundary(m, f.f, s.t0 + tau);
      return b.AtInteriorMinimum(m, f, s.t0, tau);
    }
    case MarginKind::kFrictionLevel: break;  // the orbit's, not a segment's
  }
  return b.Empty(m);
}

// The variables' layout (periodicity_equations.hpp): the start state but its last component
// (the contact's velocity, zero at the origin), phi, the durations, the parameters.
template <typename Model>
int VariableCount(const BasicOrbit<Model>& orbit) {
  return static_cast<int>(orbit.start.size()) + orbit.signature.size() + Model::kParameterCount;
}

// The walk over `orbit`'s listed segments with every variable seeded in its direction of b:
// visit(segment, parameters) for each segment in order; returns the seeded parameters.
template <typename Model, typename Visit>
typename Model::template ParametersT<Dual> WalkSeeded(const Model& model, const BasicOrbit<Model>& orbit,
                                                      const GradientBuilder& b, Visit&& visit) {
  const int S = model.StateSize(), n = orbit.signature.size();
  typename Model::template StateT<Dual> x0(S);
  for (int j = 0; j + 1 < S; ++j) x0(j) = b.Seed(orbit.start(j), j);
  std::vector<Dual> durations;
  for (int i = 0; i < n; ++i) durations.push_back(b.Seed(orbit.durations[i], S + i));
  typename Model::template ParametersT<Dual> p;
  for (int k = 0; k < Model::kParameterCount; ++k) {
    Model::ParameterAt(p, k) = b.Seed(Model::ParameterAt(orbit.parameters, k), S + n + k);
  }
  x0(S - 1) = RestVelocity<Model>(p, b.Constant(0.0));  // the contact at rest at the origin
  const std::vector<SegmentSpec> plan = SegmentPlan(orbit.signature, Extent::kListed);
  WalkSegments<Dual>(model, plan, x0, b.Seed(orbit.phi, S - 1), std::span<const Dual>(durations), p,
                     PhaseRule::kFromOrigin, [&](const SegmentVisit<Dual, Model>& s) { visit(s, p); });
  return p;
}

}  // namespace margin_gradients

// MarginGradients below, for any model (model/oscillator_model.hpp).
template <typename Model>
std::vector<MarginGradient> MarginGradients(const Model& model, const BasicOrbit<Model>& orbit) {
  using margin_gradients::Dual;
  const std::vector<Margin> margins = AdmissibilityMargins(model, orbit);
  const margin_gradients::GradientBuilder b(margin_gradients::VariableCount(orbit));
  std::vector<MarginGradient> gradients;
  gradients.reserve(margins.size());
  // The margins come segment by segment, in the walk's order (margins.hpp), as the same walk
  // visits them here.
  const auto p = margin_gradients::WalkSeeded(
      model, orbit, b, [&](const SegmentVisit<Dual, Model>& s, const typename Model::template ParametersT<Dual>& seeded) {
        for (const Margin& m : margins) {
          if (m.segment == s.spec.listed) gradients.push_back(margin_gradients::SegmentMarginGradient(model, m, s, seeded, b));
        }
      });
  for (const Margin& m : margins) {
    if (m.kind == MarginKind::kFrictionLevel) {
      gradients.push_back(b.AtBoundary(m, Model::ParameterAt(p, Model::kKineticLevelParameter), b.Constant(0.0)));
    }
  }
  return gradients;
}

// MarginGradientAt below, for any model.
template <typename Model>
MarginGradient MarginGradientAt(const Model& model, const BasicOrbit<Model>& orbit, const Margin& margin, double tau) {
  using margin_gradients::Dual;
  const int n = orbit.signature.size();
  const bool velocity = margin.kind == MarginKind::kSlipVelocity;
  if ((!velocity && margin.kind != MarginKind::kStickConstraint) || margin.segment < 0 || margin.segment >= n ||
      velocity == (orbit.signature.segments()[margin.segment] == Mode::kStick)) {
    throw std::invalid_argument(fmt::format("MarginGradientAt: {} is no interior margin of {}", margin.Name(),
                                            orbit.signature.ToString()));
  }
  const margin_gradients::GradientBuilder b(margin_gradients::VariableCount(orbit));
  MarginGradient g;
  margin_gradients::WalkSeeded(
      model, orbit, b, [&](const SegmentVisit<Dual, Model>& s, const typename Model::template ParametersT<Dual>& p) {
        if (s.spec.listed != margin.segment) return;
        const Dual t = b.Tau(tau);
        g = b.AtTime(margin, margin_gradients::MarginFunction(model, margin, s, p, t), s.t0, t);
      });
  return g;
}

// One per margin of AdmissibilityMargins(orbit), in its order. Where a margin is +inf (a slip
// with no interior minimum of its velocity) its gradients are zero.
std::vector<MarginGradient> MarginGradients(const Orbit& orbit);

// An interior margin's function at the time `tau` elapsed in its segment, any tau, not only its
// minimum: velocity:i's sign(x2') x2' in slip i, G:i's G = s + eta u_r and G1:i's G1 = -s + eta u_r
// in stick i (eq. 35). value = f(tau), slope = f_tau(tau), curvature = f_tau_tau(tau), d_value and
// d_slope their gradients at fixed tau, t = the segment's start + tau and d_t the start's gradient;
// interior = true. MarginGradients evaluates the same function at the root finder's tau* (and
// corrects d_t for tau*'s motion). `margin` is one of AdmissibilityMargins(o) for an orbit o of
// orbit's signature, of kind kSlipVelocity or kStickConstraint; else std::invalid_argument.
MarginGradient MarginGradientAt(const Orbit& orbit, const Margin& margin, double tau);

}  // namespace stickslip
