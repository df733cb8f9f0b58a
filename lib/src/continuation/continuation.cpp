#include "stickslip/continuation/continuation.hpp"

#include <algorithm>
#include <functional>
#include <cmath>
#include <optional>
#include <stdexcept>

#include <boost/math/tools/roots.hpp>
#include <fmt/format.h>

namespace stickslip {

const char* ToString(BranchEnd end) {
  switch (end) {
    case BranchEnd::kRunning: return "running";
    case BranchEnd::kMaxPoints: return "max-points";
    case BranchEnd::kParameterBound: return "parameter-bound";
    case BranchEnd::kStepTooSmall: return "step-too-small";
    case BranchEnd::kTerminalEvent: return "terminal-event";
    case BranchEnd::kStartFailed: break;
  }
  return "start-failed";
}

void ContinuationOptions::Validate() const {
  if (parameter_index < 0) throw InvalidInput("parameter_index", parameter_index, "parameter_index >= 0");
  if (direction != 1 && direction != -1) throw InvalidInput("direction", direction, "+1 or -1");
  step.Validate();
  if (!(lambda_min < lambda_max)) {
    throw InvalidInput("lambda_min", lambda_min, fmt::format("lambda_min < lambda_max ({})", lambda_max));
  }
  if (max_points < 1) throw InvalidInput("max_points", max_points, "max_points >= 1");
  if (start_iterations < 1) throw InvalidInput("start_iterations", start_iterations, "start_iterations >= 1");
  if (!(bound_tolerance >= 0.0)) throw InvalidInput("bound_tolerance", bound_tolerance, "bound_tolerance >= 0");
  if (!(location.tolerance > 0.0)) throw InvalidInput("location.tolerance", location.tolerance, "> 0");
  if (location.corrector_iterations < 1) {
    throw InvalidInput("location.corrector_iterations", location.corrector_iterations, ">= 1");
  }
  if (location.max_iterations < 1) throw InvalidInput("location.max_iterations", location.max_iterations, ">= 1");
  if (!(location.same_point >= 0.0)) throw InvalidInput("location.same_point", location.same_point, ">= 0");
  if (!(location.fold_noise >= 0.0)) throw InvalidInput("location.fold_noise", location.fold_noise, ">= 0");
}

namespace {

JacobianMatrix AppendRow(const JacobianMatrix& j, const Eigen::VectorXd& row) {
  if (const auto* dense = std::get_if<Eigen::MatrixXd>(&j)) {
    Eigen::MatrixXd m(dense->rows() + 1, dense->cols());
    m << *dense, row.transpose();
    return m;
  }
  const SparseMatrix& s = std::get<SparseMatrix>(j);
  std::vector<Eigen::Triplet<double>> triplets;
  for (int k = 0; k < s.outerSize(); ++k) {
    for (SparseMatrix::InnerIterator it(s, k); it; ++it) triplets.emplace_back(it.row(), it.col(), it.value());
  }
  for (int c = 0; c < row.size(); ++c) {
    if (row(c) != 0.0) triplets.emplace_back(static_cast<int>(s.rows()), c, row(c));
  }
  SparseMatrix m(s.rows() + 1, s.cols());
  m.setFromTriplets(triplets.begin(), triplets.end());
  return m;
}

JacobianMatrix RemoveColumn(const JacobianMatrix& j, int column) {
  if (const auto* dense = std::get_if<Eigen::MatrixXd>(&j)) {
    Eigen::MatrixXd m(dense->rows(), dense->cols() - 1);
    m << dense->leftCols(column), dense->rightCols(dense->cols() - column - 1);
    return m;
  }
  const SparseMatrix& s = std::get<SparseMatrix>(j);
  std::vector<Eigen::Triplet<double>> triplets;
  for (int k = 0; k < s.outerSize(); ++k) {
    if (k == column) continue;
    for (SparseMatrix::InnerIterator it(s, k); it; ++it) {
      triplets.emplace_back(it.row(), k < column ? k : k - 1, it.value());
    }
  }
  SparseMatrix m(s.rows(), s.cols() - 1);
  m.setFromTriplets(triplets.begin(), triplets.end());
  return m;
}

// F with lambda held at its value in `full`: the square system that corrects the start point.
class FixedParameterSystem final : public NonlinearSystem {
 public:
  FixedParameterSystem(const NonlinearSystem& problem, Eigen::VectorXd full, int parameter)
      : problem_(problem), full_(std::move(full)), parameter_(parameter) {}
  int EquationCount() const override { return problem_.EquationCount(); }
  int UnknownCount() const override { return problem_.UnknownCount() - 1; }
  Eigen::VectorXd Expand(const Eigen::VectorXd& v) const {
    Eigen::VectorXd u = full_;
    u.head(parameter_) = v.head(parameter_);
    u.tail(u.size() - parameter_ - 1) = v.tail(v.size() - parameter_);
    return u;
  }
  Eigen::VectorXd Reduce(const Eigen::VectorXd& u) const {
    Eigen::VectorXd v(u.size() - 1);
    v << u.head(parameter_), u.tail(u.size() - parameter_ - 1);
    return v;
  }
  void Evaluate(const Eigen::VectorXd& v, Eigen::VectorXd* residual, JacobianMatrix* jacobian) const override {
    JacobianMatrix full_jacobian;
    problem_.Evaluate(Expand(v), residual, jacobian ? &full_jacobian : nullptr);
    if (jacobian) *jacobian = RemoveColumn(full_jacobian, parameter_);
  }
  std::optional<std::string> DomainError(const Eigen::VectorXd& v) const override {
    return problem_.DomainError(Expand(v));
  }

 private:
  const NonlinearSystem& problem_;
  Eigen::VectorXd full_;
  int parameter_;
};

// [F(u); t.(u - u_ref) - s]: the pseudo-arclength corrector (Keller).
class BorderedSystem final : public NonlinearSystem {
 public:
  BorderedSystem(const NonlinearSystem& problem, Eigen::VectorXd tangent, Eigen::VectorXd reference, double s)
      : problem_(problem), tangent_(std::move(tangent)), reference_(std::move(reference)), s_(s) {}
  int EquationCount() const override { return problem_.EquationCount() + 1; }
  int UnknownCount() const override { return problem_.UnknownCount(); }
  void Evaluate(const Eigen::VectorXd& u, Eigen::VectorXd* residual, JacobianMatrix* jacobian) const override {
    Eigen::VectorXd f;
    JacobianMatrix j;
    problem_.Evaluate(u, &f, jacobian ? &j : nullptr);
    residual->resize(f.size() + 1);
    *residual << f, tangent_.dot(u - reference_) - s_;
    if (jacobian) *jacobian = AppendRow(j, tangent_);
  }
  std::optional<std::string> DomainError(const Eigen::VectorXd& u) const override {
    return problem_.DomainError(u);
  }

 private:
  const NonlinearSystem& problem_;
  Eigen::VectorXd tangent_;
  Eigen::VectorXd reference_;
  double s_;
};

// Thrown inside event location when the corrector fails at a trial arclength.
struct CorrectorFailure {};

}  // namespace

// Per-step mutable state, apart from the immutable setup (problem, monitor, options).
struct Continuation::State {
  const NonlinearSystem& problem;
  const Monitor* monitor;
  ContinuationOptions options;
  std::unique_ptr<StepSizeController> steps;
  std::unique_ptr<LinearSolver> solver;
  Eigen::VectorXd start;
  Eigen::VectorXd u;        // last accepted point
  Eigen::VectorXd tangent;  // unit tangent there, oriented along the branch
  int det_sign = 0;         // sign of det [J; t^T] there
  Eigen::VectorXd tests;    // the monitor's values there
  double ds = 0.0;
  std::string last_failure;  // why the corrector last failed, for the end message
  bool started = false;
  bool ended = false;

  // Everything a test function may need at a point.
  struct Sample {
    Eigen::VectorXd u;
    Eigen::VectorXd tangent;
    int det_sign = 0;
    Eigen::VectorXd tests;
    int iterations = 0;
  };

  State(const NonlinearSystem& p, const Monitor* m, ContinuationOptions o, Eigen::VectorXd s)
      : problem(p), monitor(m), options(std::move(o)), steps(StepSizeController::Create(options.step)),
        solver(LinearSolver::Create(options.corrector.linear_solver)), start(std::move(s)) {}

  double Lambda(const Eigen::VectorXd& x) const { return x(options.parameter_index); }

  // Unit tangent at x with the orientation of `reference` (t.reference > 0), and the sign of
  // det [J; t^T] for branch-point detection. False if the bordered matrix is singular.
  bool Tangent(const Eigen::VectorXd& x, const Eigen::VectorXd& reference, Eigen::VectorXd* t, int* sign) {
    Eigen::VectorXd f;
    JacobianMatrix j;
    problem.Evaluate(x, &f, &j);
    if (!solver->Factorize(AppendRow(j, reference))) return false;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(x.size());
    rhs(x.size() - 1) = 1.0;
    *t = solver->Solve(rhs);
    // With A = [J; r^T] and A t~ = e (so r.t~ = 1: t keeps the orientation of r), the rank-one
    // update to B = [J; t^T], t = t~/|t~|, gives det B = det A (1 + (t - r).t~) = det A |t~|: one
    // factorisation serves.
    *sign = solver->DeterminantSign();
    *t /= t->norm();
    return true;
  }

  Eigen::VectorXd Tests(const Eigen::VectorXd& x) const {
    return monitor ? monitor->Evaluate(x) : Eigen::VectorXd();
  }

  bool Admissible(const Eigen::VectorXd& values, const std::vector<TestFunctionInfo>& info) const {
    for (int k = 0; k < values.size(); ++k) {
      if (info[k].terminal && std::isfinite(values(k)) && values(k) <= 0.0) return false;
    }
    return true;
  }

  // The point at arclength s from the last accepted point along its tangent. Locating an event
  // may need points near a singular one (a branch point), where Newton converges slowly: it
  // is allowed more iterations than a step, which could shrink instead.
  std::optional<Sample> Corrected(double s, bool locating = false) {
    const BorderedSystem bordered(problem, tangent, u, s);
    NewtonOptions newton = options.corrector;
    if (locating) newton.max_iterations = std::max(newton.max_iterations, options.location.corrector_iterations);
    NewtonResult r = SolveNewton(bordered, u + s * tangent, newton);
    if (!r.summary.Converged()) {
      last_failure = r.summary.BriefReport();
      return std::nullopt;
    }
    Sample sample;
    sample.u = std::move(r.solution);
    sample.iterations = r.summary.iterations;
    if (!Tangent(sample.u, tangent, &sample.tangent, &sample.det_sign)) return std::nullopt;
    sample.tests = Tests(sample.u);
    return sample;
  }

  // A corrected point within rounding of a parameter bound, moved onto it exactly (Newton with
  // the parameter held at the bound), so that the bound is reached as a located event.
  std::optional<Sample> OnBound(const Sample& near, double bound) {
    Eigen::VectorXd target = near.u;
    target(options.parameter_index) = bound;
    const FixedParameterSystem fixed(problem, target, options.parameter_index);
    NewtonResult r = SolveNewton(fixed, fixed.Reduce(target), options.corrector);
    if (!r.summary.Converged()) return std::nullopt;
    Sample sample;
    sample.u = fixed.Expand(r.solution);
    sample.iterations = near.iterations + r.summary.iterations;
    if (!Tangent(sample.u, tangent, &sample.tangent, &sample.det_sign)) return std::nullopt;
    sample.tests = Tests(sample.u);
    return sample;
  }
};

Continuation::Continuation(const NonlinearSystem& problem, const Monitor* monitor,
                           ContinuationOptions options, Eigen::VectorXd start) {
  options.Validate();
  if (problem.UnknownCount() != problem.EquationCount() + 1) {
    throw std::invalid_argument(fmt::format(
        "continuation needs one unknown more than equations: {} equations, {} unknowns",
        problem.EquationCount(), problem.UnknownCount()));
  }
  if (start.size() != problem.UnknownCount()) {
    throw std::invalid_argument(fmt::format("the start point has {} unknowns, the problem {}", start.size(),
                                            problem.UnknownCount()));
  }
  if (options.parameter_index >= start.size()) {
    throw InvalidInput("parameter_index", options.parameter_index,
                       fmt::format("0 <= parameter_index < {} (the unknowns)", start.size()));
  }
  if (monitor) branch_.test_functions = monitor->TestFunctions();
  state_ = std::make_unique<State>(problem, monitor, std::move(options), std::move(start));
}

Continuation::~Continuation() = default;

bool Continuation::Step() {
  State& st = *state_;
  if (st.ended) return false;
  const ContinuationOptions& o = st.options;
  const int n1 = static_cast<int>(st.start.size());
  auto end = [&](BranchEnd why, std::string message) {
    st.ended = true;
    branch_.end = why;
    branch_.end_message = std::move(message);
    if (!branch_.points.empty()) {
      const int last = static_cast<int>(branch_.points.size()) - 1;
      BranchPoint& p = branch_.points[last];
      if (p.label.empty()) p.label = "EP";
      branch_.special_points.push_back({"EP", ToString(why), last, p.lambda, p.u, p.tests, 0.0, true, 0.0});
    }
    return false;
  };
  auto push = [&](const State::Sample& s, double ds, std::string label) {
    BranchPoint p{s.u, st.Lambda(s.u), ds, s.iterations, s.tests, std::move(label),
                  st.Admissible(s.tests, branch_.test_functions)};
    branch_.points.push_back(std::move(p));
  };

  if (!st.started) {
    st.started = true;
    const FixedParameterSystem fixed(st.problem, st.start, o.parameter_index);
    NewtonOptions newton = o.corrector;
    newton.max_iterations = std::max(newton.max_iterations, o.start_iterations);
    const NewtonResult r = SolveNewton(fixed, fixed.Reduce(st.start), newton);
    if (!r.summary.Converged()) {
      return end(BranchEnd::kStartFailed, "the start point does not converge: " + r.summary.BriefReport());
    }
    st.u = fixed.Expand(r.solution);
    Eigen::VectorXd axis = Eigen::VectorXd::Zero(n1);
    axis(o.parameter_index) = o.direction;
    if (!st.Tangent(st.u, axis, &st.tangent, &st.det_sign)) {
      return end(BranchEnd::kStartFailed, "the bordered Jacobian is singular at the start point");
    }
    st.ds = st.steps->Initial();
    st.tests = st.Tests(st.u);
    State::Sample s{st.u, st.tangent, st.det_sign, st.tests, r.summary.iterations};
    push(s, 0.0, "EP");
    branch_.special_points.push_back({"EP", "start", 0, st.Lambda(st.u), st.u, s.tests, 0.0, true, 0.0});
    if (st.Lambda(st.u) < o.lambda_min || st.Lambda(st.u) > o.lambda_max) {
      return end(BranchEnd::kParameterBound, "the start lies outside the parameter range");
    }
    if (o.max_points <= 1) return end(BranchEnd::kMaxPoints, "max_points reached");
    return true;
  }

  // Predictor-corrector with step-size control. A step that would cross a parameter bound is
  // shortened to end on it, so that a bound at the edge of the problem's domain can be reached.
  std::optional<State::Sample> next;
  double ds = st.ds;
  bool on_bound = false;
  while (true) {
    if (ds < o.step.ds_min) {
      return end(BranchEnd::kStepTooSmall,
                 fmt::format("the corrector failed down to ds = {:.3e} < ds_min = {:.3e} at {} = {:.12g}; last "
                             "failure: {}",
                             ds, o.step.ds_min, "lambda", st.Lambda(st.u), st.last_failure));
    }
    const double rate = st.tangent(o.parameter_index);
    const double bound = rate > 0.0 ? o.lambda_max : o.lambda_min;
    const double to_bound = rate != 0.0 ? (bound - st.Lambda(st.u)) / rate : ds;
    // Standing on the bound and heading out of the range (a start on a range end): done.
    if (rate != 0.0 && to_bound <= 0.0) {
      return end(BranchEnd::kParameterBound, fmt::format("at the bound lambda = {}", st.Lambda(st.u)));
    }
    on_bound = to_bound <= ds;
    next = st.Corrected(on_bound ? to_bound : ds);
    if (next) {
      if (on_bound) {
        ds = to_bound;
        // The corrector keeps lambda on the bound only to second order in the step; where it
        // lands within rounding of it, the point is put on it, and the bound event below
        // records it. If that fails, the branch still ends on the corrected point.
        on_bound = std::abs(st.Lambda(next->u) - bound) <= o.bound_tolerance * (1.0 + std::abs(bound));
        if (on_bound) {
          if (std::optional<State::Sample> exact = st.OnBound(*next, bound)) next = std::move(exact);
        }
      }
      break;
    }
    ds = st.steps->OnRejected(ds);
    st.ds = ds;
  }
  const State::Sample a{st.u, st.tangent, st.det_sign, st.tests, 0};
  const State::Sample& b = *next;

  // Every test function whose sign differs between a and b.
  struct Event {
    std::string type, name;
    std::function<double(const State::Sample&)> g;  // continuous, or a sign for BP
    bool sign_only = false;
    bool terminal = false;  // ends the branch when crossing out of admissibility
    bool bound = false;     // a parameter bound
    double noise = 0.0;     // a sign change between values both below this is noise
    int priority = 0;       // order of events located at the same point
  };
  std::vector<Event> events;
  const int lambda_index = o.parameter_index;
  if (o.detect_folds) {
    // Where the branch runs at constant lambda, the fold function is rounding noise around zero.
    events.push_back({"LP", "tangent:lambda", [lambda_index](const State::Sample& s) { return s.tangent(lambda_index); },
                      false, false, false, o.location.fold_noise, 1});
  }
  if (o.detect_branch_points) {
    events.push_back({"BP", "det-bordered", [](const State::Sample& s) { return double(s.det_sign); }, true, false,
                      false, 0.0, 2});
  }
  for (const UserValue& uz : o.user_values) {
    events.push_back({"UZ", uz.name, [uz](const State::Sample& s) { return s.u(uz.index) - uz.value; }, false, false,
                      false, 0.0, 3});
  }
  for (int k = 0; k < static_cast<int>(branch_.test_functions.size()); ++k) {
    const TestFunctionInfo& info = branch_.test_functions[k];
    if (!info.detect) continue;
    events.push_back({info.type, info.name, [k](const State::Sample& s) { return s.tests(k); }, false,
                      info.terminal && !o.continue_past_terminal});
  }
  events.push_back({"EP", "lambda_max", [&o, lambda_index](const State::Sample& s) { return o.lambda_max - s.u(lambda_index); },
                    false, false, true, 0.0, 4});
  events.push_back({"EP", "lambda_min", [&o, lambda_index](const State::Sample& s) { return s.u(lambda_index) - o.lambda_min; },
                    false, false, true, 0.0, 4});

  struct Located {
    double s;
    const Event* event;
    State::Sample sample;
    double value;
    bool located;
    double bracket;
  };
  std::vector<Located> located;
  for (const Event& e : events) {
    const double ga = e.g(a);
    const double gb = e.g(b);
    if (!std::isfinite(ga) || !std::isfinite(gb) || ga * gb > 0.0 || (ga == 0.0 && gb == 0.0)) continue;
    if (ga == 0.0) continue;  // counted at the previous step
    if (std::max(std::abs(ga), std::abs(gb)) < e.noise) continue;
    auto g_at = [&](double s) {
      std::optional<State::Sample> p = st.Corrected(s, /*locating=*/true);
      if (!p) throw CorrectorFailure{};
      return e.g(*p);
    };
    double lo = 0.0, hi = ds, g_lo = ga;
    bool ok = true;
    try {
      if (e.sign_only) {
        while (hi - lo > o.location.tolerance) {
          const double mid = 0.5 * (lo + hi);
          const double g_mid = g_at(mid);
          if (g_mid * g_lo > 0.0) {
            lo = mid;
            g_lo = g_mid;
          } else {
            hi = mid;
          }
        }
      } else if (gb != 0.0) {
        std::uintmax_t iterations = static_cast<std::uintmax_t>(o.location.max_iterations);
        const double tol = o.location.tolerance;
        const auto bracket = boost::math::tools::toms748_solve(
            g_at, 0.0, ds, ga, gb, [tol](double x, double y) { return std::abs(y - x) <= tol; }, iterations);
        lo = bracket.first;
        hi = bracket.second;
      }
    } catch (const CorrectorFailure&) {
      ok = false;
    }
    if (gb == 0.0) lo = hi = ds;
    const double s_star = ok ? (e.sign_only ? hi : 0.5 * (lo + hi)) : ds * ga / (ga - gb);
    std::optional<State::Sample> p =
        ok ? (s_star == ds ? std::optional<State::Sample>(b) : st.Corrected(s_star, /*locating=*/true)) : std::nullopt;
    if (!p) {
      ok = false;
      p = b;
    }
    const double value = e.g(*p);
    // A sign change through a pole (a test function that blows up, as a saltation matrix does
    // where an event becomes tangent) is no zero: the located value is large, not small.
    if (ok && !e.sign_only && std::abs(value) > std::max(std::abs(ga), std::abs(gb))) continue;
    located.push_back({s_star, &e, *p, value, ok, hi - lo});
  }
  // In arclength order; events within a few location tolerances of each other are one point
  // (a fold where a stop degenerates, say) and come in a fixed order, whatever the step size.
  std::sort(located.begin(), located.end(), [](const Located& x, const Located& y) { return x.s < y.s; });
  const double same_point = o.location.same_point * o.location.tolerance;
  for (std::size_t first = 0; first < located.size();) {
    std::size_t last = first + 1;
    while (last < located.size() && located[last].s - located[last - 1].s <= same_point) ++last;
    std::stable_sort(located.begin() + static_cast<long>(first), located.begin() + static_cast<long>(last),
                     [](const Located& x, const Located& y) { return x.event->priority < y.event->priority; });
    std::optional<std::pair<BranchEnd, std::string>> ending;
    for (std::size_t k = first; k < last; ++k) {
      const Located& l = located[k];
      const Event& e = *l.event;
      push(l.sample, 0.0, e.type);
      const int index = static_cast<int>(branch_.points.size()) - 1;
      branch_.special_points.push_back({e.type, e.name, index, st.Lambda(l.sample.u), l.sample.u, l.sample.tests,
                                        l.value, l.located, l.bracket});
      if (ending) continue;
      if (e.bound) {
        ending.emplace(BranchEnd::kParameterBound, fmt::format("reached {} = {}", e.name, st.Lambda(l.sample.u)));
      } else if (e.terminal && e.g(a) > 0.0) {
        // A terminal function ends the branch only when it leaves the admissible (positive) side.
        ending.emplace(BranchEnd::kTerminalEvent,
                       fmt::format("{} ({}) left its admissible side", e.name, e.type));
      }
    }
    if (ending) {
      st.u = branch_.points.back().u;
      return end(ending->first, ending->second);
    }
    first = last;
  }

  push(b, ds, "");
  st.u = b.u;
  st.tests = b.tests;
  if (on_bound) return end(BranchEnd::kParameterBound, fmt::format("reached the bound lambda = {}", st.Lambda(b.u)));
  st.tangent = b.tangent;
  st.det_sign = b.det_sign;
  st.ds = st.steps->OnAccepted(ds, b.iterations);
  if (static_cast<int>(branch_.points.size()) >= o.max_points) return end(BranchEnd::kMaxPoints, "max_points reached");
  return true;
}

Branch Continuation::Run() {
  while (Step()) {
  }
  return branch_;
}

}  // namespace stickslip
