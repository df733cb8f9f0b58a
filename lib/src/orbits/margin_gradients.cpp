#include "stickslip/orbits/margin_gradients.hpp"

#include <cmath>
#include <string_view>

// <Eigen/Core> must precede the unsupported AutoDiff module.
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "stickslip/model/events.hpp"
#include "stickslip/orbits/segment_walk.hpp"

namespace stickslip {

namespace {

namespace ov = orbit_variables;

// One direction per orbit variable, and a last one for the time tau elapsed in a segment.
using Dual = Eigen::AutoDiffScalar<Eigen::VectorXd>;

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

  // A margin at an interior minimum in time of f, with f_tau its time derivative, both evaluated
  // at tau* seeded by Tau(): f's derivative along tau is f_tau, and f_tau's is f_tau_tau.
  MarginGradient AtInteriorMinimum(const Margin& m, const Dual& f, const Dual& f_tau, const Dual& t0) const {
    MarginGradient g = Empty(m);
    g.interior = true;
    g.value = f.value();
    g.d_value = Head(f);  // the envelope theorem: the partial derivative at fixed tau*
    g.slope = f_tau.value();
    g.d_slope = Head(f_tau);
    g.curvature = f_tau.derivatives()(variables_);
    g.d_t = Head(t0) - g.d_slope / g.curvature;
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

MarginGradient SegmentMarginGradient(const Margin& m, const SegmentVisit<Dual>& s, const BasicParameters<Dual>& p,
                                     const GradientBuilder& b) {
  const Mode mode = s.spec.mode;
  const Dual t_end = s.t0 + s.duration;
  switch (m.kind) {
    case MarginKind::kDuration: return b.AtBoundary(m, s.duration, s.t0);
    case MarginKind::kStopSlope: return b.AtBoundary(m, StopSlope(mode, s.end, s.end_phase, p), t_end);
    case MarginKind::kExitSlope: return b.AtBoundary(m, ExitSlope(s.spec.end, s.end, s.end_phase, p), t_end);
    case MarginKind::kStopForce:
      switch (s.spec.end) {
        case SegmentEndKind::kReversal:
          return b.AtBoundary(m, ReversalForce(s.spec.next, s.end, s.end_phase, p), t_end);
        case SegmentEndKind::kStickEntry: return b.AtBoundary(m, StickEntryForce(s.end, s.end_phase, p), t_end);
        default: return b.AtBoundary(m, AbnormalStopJerk(mode, s.end, s.end_phase, p), t_end);
      }
    case MarginKind::kSlipVelocity: {
      if (!std::isfinite(m.value)) return b.Empty(m);
      const double sigma = SlipDirection(mode);
      const Dual tau = b.Tau(m.t - s.t0.value());
      const StateT<Dual> x = s.motion.StateAt(tau);
      const Dual phase = s.phase + p.omega * tau;
      return b.AtInteriorMinimum(m, sigma * x(3), sigma * Acceleration(mode, x, phase, p)(1), s.t0);
    }
    case MarginKind::kStickConstraint: {
      // G = s + eta u_r, G1 = -s + eta u_r along the stick (eq. 35); the minimum is interior, or
      // at the stick's start or end.
      const double side = std::string_view(m.base) == "G" ? 1.0 : -1.0;
      const double tau_star = m.t - s.t0.value();
      const bool at_start = tau_star == 0.0;
      const bool at_end = m.t == t_end.value();
      const Dual tau = at_start ? b.Constant(0.0) : at_end ? s.duration : b.Tau(tau_star);
      const StateT<Dual> x = s.motion.StateAt(tau);
      const Dual phase = s.phase + p.omega * tau;
      const Dual f = side * StickForce(x, phase, p) + p.eta * p.u_r;
      if (at_start || at_end) return b.AtBoundary(m, f, s.t0 + tau);
      return b.AtInteriorMinimum(m, f, side * StickForceRate(x, phase, p), s.t0);
    }
    case MarginKind::kFrictionLevel: break;  // the orbit's, not a segment's
  }
  return b.Empty(m);
}

}  // namespace

std::vector<MarginGradient> MarginGradients(const Orbit& orbit) {
  const std::vector<Margin> margins = AdmissibilityMargins(orbit);
  const int n = orbit.signature.size();
  const GradientBuilder b(ov::Count(n));
  const StateT<Dual> x0(b.Seed(orbit.x10, ov::kX10), b.Seed(orbit.x20, ov::kX20), b.Seed(orbit.v10, ov::kV10),
                        b.Constant(0.0));
  std::vector<Dual> durations;
  for (int i = 0; i < n; ++i) durations.push_back(b.Seed(orbit.durations[i], ov::Duration(i)));
  BasicParameters<Dual> p;
  for (ParameterId id : kAllParameters) p[id] = b.Seed(orbit.parameters[id], ov::Parameter(n, id));

  std::vector<MarginGradient> gradients;
  gradients.reserve(margins.size());
  const std::vector<SegmentSpec> plan = SegmentPlan(orbit.signature, Extent::kListed);
  // The margins come segment by segment, in the walk's order (margins.cpp), as the same walk
  // visits them here.
  WalkSegments<Dual>(plan, x0, b.Seed(orbit.phi, ov::kPhi), durations, p, PhaseRule::kFromOrigin,
                     [&](const SegmentVisit<Dual>& s) {
                       for (const Margin& m : margins) {
                         if (m.segment == s.spec.listed) gradients.push_back(SegmentMarginGradient(m, s, p, b));
                       }
                     });
  for (const Margin& m : margins) {
    if (m.kind == MarginKind::kFrictionLevel) gradients.push_back(b.AtBoundary(m, p.u_s, b.Constant(0.0)));
  }
  return gradients;
}

}  // namespace stickslip
