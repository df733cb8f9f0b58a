#include "stickslip/orbits/margin_gradients.hpp"

#include <cmath>
#include <stdexcept>
#include <string_view>

// <Eigen/Core> must precede the unsupported AutoDiff module.
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <fmt/format.h>

#include "stickslip/model/events.hpp"
#include "stickslip/orbits/segment_walk.hpp"

namespace stickslip {

namespace {

namespace ov = orbit_variables;

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

// The function an interior margin is the minimum of, at `tau` in segment `s`: sign(x2') x2' in a
// slip (velocity:i), G = s + eta u_r or G1 = -s + eta u_r in a stick (G:i, G1:i; eq. 35), with its
// time derivative.
FunctionAlong MarginFunction(const Margin& m, const SegmentVisit<Dual>& s, const BasicParameters<Dual>& p,
                             const Dual& tau) {
  const StateT<Dual> x = s.motion.StateAt(tau);
  const Dual phase = s.phase + p.omega * tau;
  if (m.kind == MarginKind::kSlipVelocity) {
    const double sigma = SlipDirection(s.spec.mode);
    return {sigma * x(3), sigma * Acceleration(s.spec.mode, x, phase, p)(1)};
  }
  const double side = std::string_view(m.base) == "G" ? 1.0 : -1.0;
  return {side * StickForce(x, phase, p) + p.eta * p.u_r, side * StickForceRate(x, phase, p)};
}

MarginGradient SegmentMarginGradient(const Margin& m, const SegmentVisit<Dual>& s, const BasicParameters<Dual>& p,
                                     const GradientBuilder& b) {
  const Mode mode = s.spec.mode;
  const Dual t_end = s.t0 + s.duration;
  switch (m.kind) {
    case MarginKind::kDuration: return b.AtBoundary(m, s.duration, s.t0);
    case MarginKind::kStopSlope: return b.AtBoundary(m, StopSlope(Pascal2014{}, mode, s.end, s.end_phase, p), t_end);
    case MarginKind::kExitSlope: return b.AtBoundary(m, ExitSlope(Pascal2014{}, s.spec.end, s.end, s.end_phase, p), t_end);
    case MarginKind::kStopForce:
      switch (s.spec.end) {
        case SegmentEndKind::kReversal:
          return b.AtBoundary(m, ReversalForce(Pascal2014{}, s.spec.next, s.end, s.end_phase, p), t_end);
        case SegmentEndKind::kStickEntry: return b.AtBoundary(m, StickEntryForce(Pascal2014{}, s.end, s.end_phase, p), t_end);
        default: return b.AtBoundary(m, AbnormalStopJerk(Pascal2014{}, mode, s.end, s.end_phase, p), t_end);
      }
    case MarginKind::kSlipVelocity: {
      if (!std::isfinite(m.value)) return b.Empty(m);
      const Dual tau = b.Tau(m.t - s.t0.value());
      return b.AtInteriorMinimum(m, MarginFunction(m, s, p, tau), s.t0, tau);
    }
    case MarginKind::kStickConstraint: {
      // The minimum is interior, or at the stick's start or end.
      const double tau_star = m.t - s.t0.value();
      const bool at_start = tau_star == 0.0;
      const bool at_end = m.t == t_end.value();
      const Dual tau = at_start ? b.Constant(0.0) : at_end ? s.duration : b.Tau(tau_star);
      const FunctionAlong f = MarginFunction(m, s, p, tau);
      if (at_start || at_end) return b.AtBoundary(m, f.f, s.t0 + tau);
      return b.AtInteriorMinimum(m, f, s.t0, tau);
    }
    case MarginKind::kFrictionLevel: break;  // the orbit's, not a segment's
  }
  return b.Empty(m);
}

// The walk over `orbit`'s listed segments with every variable seeded in its direction of b:
// visit(segment, parameters) for each segment in order; returns the seeded parameters.
template <typename Visit>
BasicParameters<Dual> WalkSeeded(const Orbit& orbit, const GradientBuilder& b, Visit&& visit) {
  const int n = orbit.signature.size();
  const StateT<Dual> x0(b.Seed(orbit.x10, ov::kX10), b.Seed(orbit.x20, ov::kX20), b.Seed(orbit.v10, ov::kV10),
                        b.Constant(0.0));
  std::vector<Dual> durations;
  for (int i = 0; i < n; ++i) durations.push_back(b.Seed(orbit.durations[i], ov::Duration(i)));
  BasicParameters<Dual> p;
  for (ParameterId id : kAllParameters) p[id] = b.Seed(orbit.parameters[id], ov::Parameter(n, id));
  const std::vector<SegmentSpec> plan = SegmentPlan(orbit.signature, Extent::kListed);
  WalkSegments<Dual>(plan, x0, b.Seed(orbit.phi, ov::kPhi), durations, p, PhaseRule::kFromOrigin,
                     [&](const SegmentVisit<Dual>& s) { visit(s, p); });
  return p;
}

}  // namespace

std::vector<MarginGradient> MarginGradients(const Orbit& orbit) {
  const std::vector<Margin> margins = AdmissibilityMargins(orbit);
  const GradientBuilder b(ov::Count(orbit.signature.size()));
  std::vector<MarginGradient> gradients;
  gradients.reserve(margins.size());
  // The margins come segment by segment, in the walk's order (margins.cpp), as the same walk
  // visits them here.
  const BasicParameters<Dual> p =
      WalkSeeded(orbit, b, [&](const SegmentVisit<Dual>& s, const BasicParameters<Dual>& seeded) {
        for (const Margin& m : margins) {
          if (m.segment == s.spec.listed) gradients.push_back(SegmentMarginGradient(m, s, seeded, b));
        }
      });
  for (const Margin& m : margins) {
    if (m.kind == MarginKind::kFrictionLevel) gradients.push_back(b.AtBoundary(m, p.u_s, b.Constant(0.0)));
  }
  return gradients;
}

MarginGradient MarginGradientAt(const Orbit& orbit, const Margin& margin, double tau) {
  const int n = orbit.signature.size();
  const bool velocity = margin.kind == MarginKind::kSlipVelocity;
  if ((!velocity && margin.kind != MarginKind::kStickConstraint) || margin.segment < 0 || margin.segment >= n ||
      velocity == (orbit.signature.segments()[margin.segment] == Mode::kStick)) {
    throw std::invalid_argument(fmt::format("MarginGradientAt: {} is no interior margin of {}", margin.Name(),
                                            orbit.signature.ToString()));
  }
  const GradientBuilder b(ov::Count(n));
  MarginGradient g;
  WalkSeeded(orbit, b, [&](const SegmentVisit<Dual>& s, const BasicParameters<Dual>& p) {
    if (s.spec.listed != margin.segment) return;
    const Dual t = b.Tau(tau);
    g = b.AtTime(margin, MarginFunction(margin, s, p, t), s.t0, t);
  });
  return g;
}

}  // namespace stickslip
