#include "stickslip/branches/floquet_condition.hpp"

#include <cmath>
#include <complex>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/LU>
#include <Eigen/SVD>
#include <fmt/format.h>

#include "stickslip/branches/orbit_monitor.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/floquet_gradients.hpp"
#include "stickslip/orbits/stability.hpp"

namespace stickslip {

namespace {

enum class Kind { kFold, kFlip, kSymmetry, kTorus };

// B(X, Y) over the pairs i < j (rows) and k < l (columns), in lexicographic order: X_ik Y_jl -
// X_il Y_jk. The second compound of M is B(M, M), its derivative B(dM, M) + B(M, dM).
template <typename Matrix>
Eigen::MatrixXd PairProduct(const Matrix& x, const Matrix& y) {
  const int size = static_cast<int>(x.rows()), pairs = size * (size - 1) / 2;
  Eigen::MatrixXd b(pairs, pairs);
  int row = 0;
  for (int i = 0; i < size; ++i) {
    for (int j = i + 1; j < size; ++j, ++row) {
      int column = 0;
      for (int k = 0; k < size; ++k) {
        for (int l = k + 1; l < size; ++l, ++column) b(row, column) = x(i, k) * y(j, l) - x(i, l) * y(j, k);
      }
    }
  }
  return b;
}

// The matrix A whose singularity the condition is, and its derivatives by variable.
struct TestMatrix {
  Eigen::MatrixXd a;
  std::vector<Eigen::MatrixXd> d_a;
};

TestMatrix TestMatrixOf(Kind kind, const OrbitProblem& problem, const Eigen::VectorXd& u) {
  DynamicMonodromyGradient g = problem.MonodromyGradients(u);
  TestMatrix t;
  using Matrix = DynamicMonodromyGradient::Matrix;
  const Matrix identity = Matrix::Identity(g.period.rows(), g.period.cols());
  switch (kind) {
    case Kind::kFold:
      t.a = g.period - identity;
      t.d_a = std::move(g.d_period);
      break;
    case Kind::kFlip:
      t.a = g.period + identity;
      t.d_a = std::move(g.d_period);
      break;
    case Kind::kSymmetry:
      t.a = identity - g.listed;
      for (const Matrix& d : g.d_listed) t.d_a.push_back(-d);
      break;
    case Kind::kTorus:
      t.a = PairProduct(g.period, g.period);
      t.a -= Eigen::MatrixXd::Identity(t.a.rows(), t.a.cols());
      for (const Matrix& d : g.d_period) t.d_a.push_back(PairProduct(d, g.period) + PairProduct(g.period, d));
      break;
  }
  return t;
}

// p'(mu) at mu = +-1 for p(mu) = det(mu I - M): the trace of the adjugate of mu I - M, the sum of
// its principal minors of order size - 1. At the paper's model's size (4) the minors are fixed-size
// 3 x 3 (Eigen's closed-form determinant, as its results were computed); any other size by LU.
template <int S>
double PrincipalMinorSum(const Eigen::Matrix<double, S, S>& a) {
  const int size = static_cast<int>(a.rows());
  constexpr int kMinor = S == Eigen::Dynamic ? Eigen::Dynamic : S - 1;
  double sum = 0.0;
  for (int k = 0; k < size; ++k) {
    Eigen::Matrix<double, kMinor, kMinor> minor(size - 1, size - 1);
    for (int i = 0, r = 0; i < size; ++i) {
      if (i == k) continue;
      for (int j = 0, c = 0; j < size; ++j) {
        if (j != k) minor(r, c++) = a(i, j);
      }
      ++r;
    }
    sum += minor.determinant();
  }
  return sum;
}

double Slope(const OrbitStability& s, double mu) {
  const Eigen::Index size = s.monodromy.rows();
  const Eigen::MatrixXd a = mu * Eigen::MatrixXd::Identity(size, size) - s.monodromy;
  if (size == Pascal2014::kStateSize) return PrincipalMinorSum<Pascal2014::kStateSize>(a);
  return PrincipalMinorSum<Eigen::Dynamic>(a);
}

class Floquet final : public OrbitCondition {
 public:
  Floquet(Kind kind, std::string name, Eigen::VectorXd b, Eigen::VectorXd c)
      : kind_(kind), name_(std::move(name)), b_(std::move(b)), c_(std::move(c)) {}

  std::string Name() const override { return name_; }

  void Evaluate(const OrbitProblem& problem, const Eigen::VectorXd& u, const Eigen::VectorXd& extra,
                Eigen::VectorXd* residual, Eigen::MatrixXd* d_variables, Eigen::MatrixXd* d_extra) const override {
    (void)extra;
    const TestMatrix t = TestMatrixOf(kind_, problem, u);
    const int m = static_cast<int>(t.a.rows());
    Eigen::MatrixXd bordered(m + 1, m + 1);
    bordered << t.a, b_, c_.transpose(), 0.0;
    const Eigen::VectorXd last = Eigen::VectorXd::Unit(m + 1, m);
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(bordered);
    const Eigen::VectorXd v = lu.solve(last);  // (v, sigma)
    *residual = Eigen::VectorXd::Constant(1, v(m));
    if (d_extra) d_extra->resize(1, 0);
    if (!d_variables) return;
    const Eigen::VectorXd w = Eigen::FullPivLU<Eigen::MatrixXd>(bordered.transpose()).solve(last);
    d_variables->resize(1, static_cast<int>(t.d_a.size()));
    for (std::size_t k = 0; k < t.d_a.size(); ++k) {
      (*d_variables)(0, static_cast<int>(k)) = -w.head(m).dot(t.d_a[k] * v.head(m));
    }
  }

  // AUTO's names: LPPD a fold-flip (multipliers +1 and -1), R1 and R2 the 1:1 and 1:2
  // resonances (a double multiplier +1 or -1, where p'(+-1) = 0, p(mu) = det(mu I - M): the sum of
  // the principal 3 x 3 minors of +-I - M). The torus test is not watched on these curves: it
  // vanishes at the resonances too. On an SB curve M = H^2 has a multiplier +1 throughout and
  // det(M + I) keeps its sign (stability.hpp). A TR curve reports its ends, folds and type
  // boundaries only (a multiplier +1 or -1 on it may be the torus pair's own: a resonance).
  std::vector<WatchedColumn> CodimensionTwoTests() const override {
    switch (kind_) {
      case Kind::kFold:
        return {{orbit_columns::kFlipTest, "LPPD", {}}, {"floquet:p'(1)", "R1", [](const OrbitStability& s) { return Slope(s, 1.0); }}};
      case Kind::kFlip:
        return {{orbit_columns::kFoldTest, "LPPD", {}}, {"floquet:p'(-1)", "R2", [](const OrbitStability& s) { return Slope(s, -1.0); }}};
      case Kind::kSymmetry:
      case Kind::kTorus: break;
    }
    return {};
  }

  std::vector<std::string> Defining() const override {
    switch (kind_) {
      case Kind::kFold: return {orbit_columns::kTorusTest};  // det(M - I) is recorded, not watched
      case Kind::kFlip: return {orbit_columns::kFlipTest, orbit_columns::kTorusTest};
      case Kind::kSymmetry: return {orbit_columns::kSymmetryTest};
      case Kind::kTorus: return {orbit_columns::kTorusTest};
    }
    return {};
  }

 private:
  Kind kind_;
  std::string name_;
  Eigen::VectorXd b_;
  Eigen::VectorXd c_;
};

// The product mu_i mu_j (i < j) nearest 1 is that of a complex pair.
bool TorusPairNearUnitCircle(const OrbitStability& s) {
  const int size = static_cast<int>(s.multipliers.size());
  double nearest = INFINITY;
  bool complex_pair = false;
  for (int i = 0; i < size; ++i) {
    for (int j = i + 1; j < size; ++j) {
      const double distance = std::abs(s.multipliers[i] * s.multipliers[j] - 1.0);
      if (distance < nearest) {
        nearest = distance;
        complex_pair = s.multipliers[i].imag() != 0.0 && 
                        std::abs(s.multipliers[i] - std::conj(s.multipliers[j])) <= 1e-12 * std::abs(s.multipliers[i]);
      }
    }
  }
  return complex_pair;
}

}  // namespace

std::shared_ptr<const OrbitCondition> FloquetCondition(std::string_view type, const OrbitProblem& problem,
                                                       const Eigen::VectorXd& u, double max_singularity) {
  const bool antisymmetric = problem.signature().antisymmetric();
  Kind kind = Kind::kFold;
  if (type == "LP") {
    kind = Kind::kFold;
  } else if (type == "PD" && !antisymmetric) {
    kind = Kind::kFlip;
  } else if (type == "SB" && antisymmetric) {
    kind = Kind::kSymmetry;
  } else if (type == "TR") {
    kind = Kind::kTorus;
  } else {
    throw InvalidInput("condition", std::string(type),
                       antisymmetric ? "LP, SB or TR for an antisymmetric orbit (its PD is no codimension-one point: SB is), "
                                       "or a margin's column"
                                     : "LP, PD or TR for an orbit that is not antisymmetric, or a margin's column");
  }
  const TestMatrix t = TestMatrixOf(kind, problem, u);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(t.a, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  const double singularity = sigma(sigma.size() - 1) / sigma(0);
  if (!(singularity <= max_singularity)) {
    throw InvalidInput("condition", fmt::format("{} at a point where its matrix has relative smallest singular value {:.3g}", type, singularity),
                       fmt::format("a point where it is <= {:g}: a located {}{}", max_singularity, type,
                                   kind == Kind::kFold ? " (a fold where a margin is zero is nonsmooth, the margin's curve)" : ""));
  }
  if (kind == Kind::kTorus && !TorusPairNearUnitCircle(problem.Stability(u))) {
    throw InvalidInput("condition", "TR at a point whose product mu_i mu_j nearest 1 is of real multipliers (a neutral saddle)",
                       "a point with a complex pair on the unit circle");
  }
  const int m = static_cast<int>(t.a.rows());
  return std::make_shared<Floquet>(kind, std::string(type), svd.matrixU().col(m - 1), svd.matrixV().col(m - 1));
}

}  // namespace stickslip
