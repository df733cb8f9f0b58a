#include "stickslip/model/linear_oscillator_data.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {
namespace {

constexpr int kMaxCoordinates = 50;
constexpr double kMaxForce = 1e15;

// "<field> <predicate>": the library's one-line form for input that is not one value.
InvalidInput Invalid(const std::string& field, const std::string& predicate) {
  return InvalidInput::WithMessage(field, field + " " + predicate);
}

void CheckSymmetricPositiveDefinite(const char* field, const Eigen::MatrixXd& a, Eigen::Index n) {
  if (a.rows() != n || a.cols() != n) {
    throw Invalid(field, fmt::format("is {}x{}: valid a {}x{} matrix", a.rows(), a.cols(), n, n));
  }
  if (!a.allFinite()) throw Invalid(field, "has an entry that is not finite: valid finite entries");
  const double scale = a.cwiseAbs().maxCoeff();
  if (((a - a.transpose()).cwiseAbs().array() > 1e-12 * scale).any()) {
    throw Invalid(field, "is not symmetric: valid a symmetric positive definite matrix");
  }
  // Positive definite with a margin above rounding: the smallest eigenvalue against the largest.
  const Eigen::VectorXd eigenvalues = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a, Eigen::EigenvaluesOnly).eigenvalues();
  if (!(eigenvalues(0) > 1e-12 * eigenvalues(n - 1))) {
    throw Invalid(
        field, fmt::format("has the eigenvalue {:.6g} (largest {:.6g}): valid a symmetric positive definite matrix",
                           eigenvalues(0), eigenvalues(n - 1)));
  }
}

ModalBasis ModesOfPair(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& stiffness) {
  ModalBasis basis;
  if (mass.rows() == 0) return {Eigen::MatrixXd(0, 0), Eigen::MatrixXd(0, 0), Eigen::VectorXd(0)};
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(stiffness, mass);
  basis.shapes = solver.eigenvectors();  // mass-normalised by the solver
  basis.projector = basis.shapes.transpose() * mass;
  basis.eigenvalues = solver.eigenvalues();
  return basis;
}

// The stick's basis on the n - 1 free coordinates, padded with the held contact's zero row/column.
ModalBasis StickModes(const Eigen::MatrixXd& mass, const Eigen::MatrixXd& stiffness) {
  const Eigen::Index r = mass.rows() - 1;
  const ModalBasis free = ModesOfPair(mass.topLeftCorner(r, r), stiffness.topLeftCorner(r, r));
  ModalBasis basis{Eigen::MatrixXd::Zero(r + 1, r), Eigen::MatrixXd::Zero(r, r + 1), free.eigenvalues};
  basis.shapes.topRows(r) = free.shapes;
  basis.projector.leftCols(r) = free.projector;
  return basis;
}

void CheckNames(const std::vector<std::string>& names, Eigen::Index n) {
  if (names.empty()) return;
  if (static_cast<Eigen::Index>(names.size()) != n) {
    throw Invalid("coordinates", fmt::format("has {} names: valid one per coordinate, {}", names.size(), n));
  }
  const std::set<std::string> distinct(names.begin(), names.end());
  if (distinct.size() != names.size() || distinct.count("") != 0) {
    throw Invalid("coordinates", "repeats a name or has an empty one: valid distinct names");
  }
}

}  // namespace

LinearOscillatorModes ModesOf(const LinearOscillatorData& data) {
  const Eigen::Index n = data.mass.rows();
  if (n < 1 || n > kMaxCoordinates) {
    throw InvalidInput("mass", fmt::format("a {}x{} matrix", data.mass.rows(), data.mass.cols()),
                       fmt::format("1 to {} coordinates", kMaxCoordinates));
  }
  CheckSymmetricPositiveDefinite("mass", data.mass, n);
  CheckSymmetricPositiveDefinite("stiffness", data.stiffness, n);
  if (data.forcing.size() != n) {
    throw Invalid("forcing", fmt::format("has {} entries: valid one per coordinate, {}", data.forcing.size(), n));
  }
  if (!data.forcing.allFinite()) throw Invalid("forcing", "has an entry that is not finite: valid finite entries");
  CheckNames(data.coordinates, n);
  LinearOscillatorModes modes{ModesOfPair(data.mass, data.stiffness), StickModes(data.mass, data.stiffness), {}, 0.0};
  const Eigen::MatrixXd mass_inverse = data.mass.llt().solve(Eigen::MatrixXd::Identity(n, n));
  const double contact_compliance = mass_inverse(n - 1, n - 1);
  modes.holding_stiffness = (mass_inverse * data.stiffness).row(n - 1) / contact_compliance;
  modes.holding_forcing = mass_inverse.row(n - 1).dot(data.forcing) / contact_compliance;
  return modes;
}

ModelDescription DescribeLinearOscillator(const LinearOscillatorData& data, const LinearOscillatorModes& modes) {
  const Eigen::Index n = data.mass.rows();
  ModelDescription d;
  d.name = data.name;
  double highest = modes.slip.eigenvalues.maxCoeff();
  if (n > 1) highest = std::max(highest, modes.stick.eigenvalues.maxCoeff());
  const double lowest = 1e-3 * std::sqrt(modes.slip.eigenvalues.minCoeff());
  highest = 1e3 * std::sqrt(highest);
  d.parameters = {
      {"omega", "forcing frequency", "rad/s", lowest, highest,
       fmt::format("{:.6g} <= omega <= {:.6g}, away from the natural frequencies", lowest, highest)},
      {"F_k", "kinetic friction force", "N", std::numeric_limits<double>::min(), kMaxForce,
       fmt::format("0 < F_k <= {:g}", kMaxForce)},
      {"F_s", "static friction force", "N", std::numeric_limits<double>::min(), kMaxForce,
       fmt::format("F_k <= F_s <= {:g}", kMaxForce)}};
  d.coordinates = data.coordinates;
  for (Eigen::Index j = static_cast<Eigen::Index>(d.coordinates.size()); j < n; ++j) d.coordinates.push_back(fmt::format("x{}", j + 1));
  for (const std::string& q : d.coordinates) d.state_components.push_back(q);
  for (const std::string& q : d.coordinates) d.state_components.push_back(q + "'");
  for (Eigen::Index j = 0; j < n; ++j) d.initial_state.push_back(fmt::format("x{}_0", j + 1));
  for (Eigen::Index j = 0; j < n; ++j) d.initial_state.push_back(fmt::format("v{}_0", j + 1));
  return d;
}

}  // namespace stickslip
