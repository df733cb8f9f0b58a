#include "stickslip/branches/margin_condition.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "stickslip/branches/orbit_monitor.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/margin_gradients.hpp"
#include "stickslip/orbits/orbit_layout.hpp"
#include "stickslip/orbits/segment_plan.hpp"

namespace stickslip {

namespace {

constexpr const char* kRegular = "a margin whose zero is a regular curve";

std::string Column(const std::string& name) { return std::string(orbit_columns::kMarginPrefix) + name; }

const Margin* Named(const std::vector<Margin>& margins, std::string_view name) {
  const auto it = std::find_if(margins.begin(), margins.end(), [&](const Margin& m) { return m.Name() == name; });
  return it == margins.end() ? nullptr : &*it;
}

// The margin of the end before segment `segment` (cyclically): the force condition of a slip's
// stop, or a stick's exit slope.
const Margin* EndBefore(const std::vector<Margin>& margins, int segment, int count) {
  const int before = (segment + count - 1) % count;
  const auto it = std::find_if(margins.begin(), margins.end(), [&](const Margin& m) {
    return m.segment == before && (m.kind == MarginKind::kStopForce || m.kind == MarginKind::kExitSlope);
  });
  return it == margins.end() ? nullptr : &*it;
}

}  // namespace

MarginCondition::MarginCondition(const OrbitProblem& problem, const Eigen::VectorXd& u, std::string_view margin) {
  const std::string value = Column(std::string(margin));
  const Signature& signature = problem.signature();
  const std::vector<Margin> margins = problem.Margins(u);
  const Margin* found = Named(margins, margin);
  if (!found) {
    std::vector<std::string> names;
    for (const Margin& m : margins) names.push_back(Column(m.Name()));
    throw InvalidInput("condition", value,
                       fmt::format("a margin of {}: {}", signature.ToString(), fmt::join(names, ", ")));
  }
  margin_ = *found;
  index_ = static_cast<int>(found - margins.data());
  const int n = signature.size();
  const int i = margin_.segment;
  const bool stick = i >= 0 && signature.segments()[i] == Mode::kStick;
  // A stick ends into slip- (its G1 reaches zero) or into slip+ (its G does).
  const bool into_negative = stick && SegmentPlan(signature, Extent::kListed)[i].end == SegmentEndKind::kExitToNegative;
  if (margin_.kind == MarginKind::kFrictionLevel) {
    throw InvalidInput("condition", value,
                       fmt::format("{}: not sliding-friction ({} ends the physical family; it is no boundary "
                                   "between orbit types)",
                                   kRegular, problem.description().contact.no_friction));
  }
  if (margin_.kind == MarginKind::kDuration && !stick) {
    const Margin* before = EndBefore(margins, i, n);
    throw InvalidInput("condition", value,
                       fmt::format("{}: not a slip's duration (at zero length its end condition {} = 0 holds "
                                   "identically); a slip shrinks to nothing only where the acceleration at its start "
                                   "does, at the zero of the margin of the end before it: use {}",
                                   kRegular, problem.description().contact.velocity,
                                   before ? Column(before->Name()) : "none (no end before it)"));
  }
  // A stick's start time, where its constraint's minimum may lie.
  const double t0 = margin_.kind == MarginKind::kStickConstraint ? problem.SegmentStart(u, i) : 0.0;
  if (margin_.kind == MarginKind::kSlipVelocity) {
    interior_ = true;
  } else if (margin_.kind == MarginKind::kStickConstraint) {
    const Eigen::VectorXd variables = problem.Variables(u.head(problem.UnknownCount()));
    interior_ = margin_.t != t0 && margin_.t != t0 + variables(OrbitLayout(problem.description(), n).Duration(i));
  }
  if (interior_ && !std::isfinite(margin_.value)) {
    throw InvalidInput("condition", value,
                       fmt::format("an interior margin with a minimum at the start orbit (it is {} there: {})",
                                   margin_.value, std::isnan(margin_.value) ? "not defined" : "no interior minimum"));
  }
  if (interior_ && margin_.kind == MarginKind::kStickConstraint) {
    // The constraint that ends the stick (G into slip+, G1 into slip-) is zero at the exit by the
    // end condition. Its interior minimum is a zero of its own only if a maximum separates the two,
    // that is if the constraint falls into the exit (exit-slope:i > 0). Otherwise the minimum and
    // the exit are one double root, the tangential exit: with tau = d_i the rows f(tau) = 0 and
    // the end condition coincide, the Jacobian loses a rank all along the curve, and Newton stops
    // at tau - d_i of the square root of its tolerance with either sign, a sign the bordered
    // determinant follows (measured on the §5.1 map: tau - d3 = +-1e-8, smallest singular value
    // 0.57 |tau - d3|, a "BP" at every sign change: 24 on the four curves, 1 to 14 each).
    const Margin* exit_slope = Named(margins, fmt::format("exit-slope:{}", i + 1));
    if ((std::string_view(margin_.base) == "G1") == into_negative && exit_slope && !(exit_slope->value > 0.0)) {
      throw InvalidInput("condition", value,
                         fmt::format("{}: not an interior minimum of the constraint that ends the stick where no "
                                     "maximum separates it from the exit ({} = {} <= 0 there: the two zeros are one, "
                                     "the tangential exit): use {}",
                                     kRegular, Column(exit_slope->Name()), exit_slope->value, Column(exit_slope->Name())));
    }
  }

  defining_.push_back(value);
  auto also = [&](const Margin* m) {
    if (m) defining_.push_back(Column(m->Name()));
  };
  const std::string next = std::to_string((i + 1) % n + 1);
  if (margin_.kind == MarginKind::kDuration) {
    also(EndBefore(margins, i, n));  // the stick entry
    also(Named(margins, fmt::format("{}:{}", into_negative ? "G1" : "G", i + 1)));
  } else if (std::string_view(margin_.base) == "stick-entry") {
    const Margin* g = Named(margins, "G:" + next);
    const Margin* g1 = Named(margins, "G1:" + next);
    if (g && g1) also(g->value <= g1->value ? g : g1);
  } else if (margin_.kind == MarginKind::kStickConstraint && !interior_ && margin_.t == t0) {
    also(EndBefore(margins, i, n));
  } else if (margin_.kind == MarginKind::kStopSlope || margin_.kind == MarginKind::kExitSlope) {
    // A tangential stop or stick exit: the saltation matrix there divides by the slope, and the
    // multipliers' tests jump through poles all along the curve.
    for (const char* test : {orbit_columns::kFlipTest, orbit_columns::kTorusTest, orbit_columns::kSymmetryTest}) {
      defining_.emplace_back(test);
    }
  }
}

std::string MarginCondition::Name() const { return Column(margin_.Name()); }

Eigen::VectorXd MarginCondition::ExtraUnknowns(const OrbitProblem& problem, const Eigen::VectorXd& u) const {
  if (!interior_) return Eigen::VectorXd();
  const Margin m = problem.Margins(u)[static_cast<std::size_t>(index_)];
  return Eigen::VectorXd::Constant(1, m.t - problem.SegmentStart(u, margin_.segment));
}

void MarginCondition::Evaluate(const OrbitProblem& problem, const Eigen::VectorXd& u, const Eigen::VectorXd& extra,
                               Eigen::VectorXd* residual, Eigen::MatrixXd* d_variables, Eigen::MatrixXd* d_extra) const {
  if (!interior_) {
    const MarginGradient g = problem.MarginGradients(u)[static_cast<std::size_t>(index_)];
    *residual = Eigen::VectorXd::Constant(1, g.value);
    if (d_variables) *d_variables = g.d_value;
    if (d_extra) d_extra->resize(1, 0);
    return;
  }
  const MarginGradient g = problem.MarginGradientAt(u, margin_, extra(0));
  residual->resize(2);
  *residual << g.value, g.slope;
  if (d_variables) {
    d_variables->resize(2, g.d_value.size());
    *d_variables << g.d_value, g.d_slope;
  }
  if (d_extra) {
    d_extra->resize(2, 1);
    *d_extra << g.slope, g.curvature;
  }
}

}  // namespace stickslip
