#include "stickslip/model/linear_oscillator_data.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <set>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <unsupported/Eigen/MatrixFunctions>
#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {
namespace {

constexpr int kMaxCoordinates = kMaxLinearOscillatorCoordinates;
constexpr double kMaxForce = 1e15;
constexpr double kMaxSpeed = 1e6;

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

// The modes reproduce the matrix exponential e^{A t} (Pade, Eigen's MatrixFunctions) to 1e-9 at
// a fast and a slow time scale, or the data is refused: nearly dependent eigenvectors (as near
// critical damping) make the modal form lose accuracy while every eigenvalue looks distinct.
void CheckModalAccuracy(const FirstOrderBasis& basis, bool solved, const char* field, bool slip) {
  double worst = solved ? 0.0 : std::numeric_limits<double>::infinity();
  const Eigen::VectorXd magnitudes = basis.eigenvalues.cwiseAbs();
  for (double t : {1.0 / magnitudes.maxCoeff(), 2.0 * std::numbers::pi / magnitudes.minCoeff()}) {
    if (!(worst < 1e-9)) break;
    const Eigen::MatrixXd exact = (basis.system * t).exp();
    const Eigen::VectorXcd growth = (basis.eigenvalues * t).array().exp();
    const Eigen::MatrixXd modal = (basis.shapes * growth.asDiagonal() * basis.projector).real();
    // NaN (a scale so extreme that an eigenvalue or the exponential is not finite) is the worst.
    const double error = (modal - exact).norm() / exact.norm();
    if (!(error <= worst)) worst = error;
  }
  if (!(worst <= 1e-9)) {
    throw Invalid(field, fmt::format("gives {} modes that reproduce the motion only to {:.2g}: valid matrices with "
                                     "well separated modes (away from critical damping)",
                                     slip ? "slip" : "stick", worst));
  }
}

// The first-order system of M q'' + C q' + K q = input on the coordinates `free` (the others held):
// A = [[0, I], [-M^-1 K, -M^-1 C]] on (q_free, q_free'), with its eigenvectors.
// `damping_field` names what damps it (in refusals): the damping, or the friction slope that adds to a slip's.
FirstOrderBasis BasisOf(const LinearOscillatorData& data, const Eigen::MatrixXd& damping, Eigen::Index free,
                        const char* damping_field) {
  const Eigen::Index n = data.mass.rows(), d = 2 * free;
  FirstOrderBasis basis;
  for (Eigen::Index j = 0; j < free; ++j) basis.components.push_back(static_cast<int>(j));
  for (Eigen::Index j = 0; j < free; ++j) basis.components.push_back(static_cast<int>(n + j));
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(d);
  basis.forcing = basis.friction = basis.held_position = basis.held_velocity = zero;
  basis.system = Eigen::MatrixXd::Zero(d, d);
  if (free == 0) {
    basis.system_inverse = basis.system;
    basis.shapes = basis.projector = Eigen::MatrixXcd(0, 0);
    basis.eigenvalues = Eigen::VectorXcd(0);
    return basis;
  }
  const Eigen::LLT<Eigen::MatrixXd> mass(data.mass.topLeftCorner(free, free));
  basis.system.topRightCorner(free, free).setIdentity();
  basis.system.bottomLeftCorner(free, free) = -mass.solve(data.stiffness.topLeftCorner(free, free));
  basis.system.bottomRightCorner(free, free) = -mass.solve(damping.topLeftCorner(free, free));
  basis.system_inverse = basis.system.inverse();
  basis.forcing.tail(free) = mass.solve(data.forcing.head(free));
  if (free == n) {
    basis.friction.tail(free) = mass.solve(Eigen::VectorXd::Unit(n, n - 1));
  } else {
    basis.held_position.tail(free) = -mass.solve(data.stiffness.col(n - 1).head(free));
    basis.held_velocity.tail(free) = -mass.solve(damping.col(n - 1).head(free));
  }
  if (!basis.system.allFinite() || !basis.system_inverse.allFinite()) {
    throw Invalid("stiffness", fmt::format("over mass gives a {} system that is not finite: valid matrices whose "
                                           "scales stay within double range of each other", free == n ? "slip" : "stick"));
  }
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(basis.system);
  basis.eigenvalues = solver.eigenvalues();
  basis.shapes = solver.eigenvectors();
  basis.projector = basis.shapes.inverse();
  CheckModalAccuracy(basis, solver.info() == Eigen::Success, damping.isZero() ? "stiffness" : damping_field, free == n);
  return basis;
}

// By the coordinates' names, whatever their order: q_0 for each position; for each velocity the
// name with its leading x made v (x1: v1_0), or v_ before any other (left: v_left_0).
// The state's columns: each coordinate q, then its velocity v<k> for x<k>, v_q for any other name.
std::vector<std::string> StateColumnNames(const std::vector<std::string>& coordinates) {
  std::vector<std::string> names = coordinates;
  for (const std::string& q : coordinates) names.push_back(q.size() > 1 && q[0] == 'x' ? "v" + q.substr(1) : "v_" + q);
  return names;
}

// The state at t = 0: each column's name with "_0".
std::vector<std::string> StartStateNames(const std::vector<std::string>& coordinates) {
  std::vector<std::string> names = StateColumnNames(coordinates);
  for (std::string& name : names) name += "_0";
  return names;
}

}  // namespace

void CheckCoordinateNames(const std::vector<std::string>& names, Eigen::Index n, const std::string& field) {
  if (names.empty()) return;
  if (static_cast<Eigen::Index>(names.size()) != n) {
    throw Invalid(field, fmt::format("has {} names: valid one per coordinate, {}", names.size(), n));
  }
  const auto identifier = [](const std::string& name) {
    return !name.empty() && name.size() <= 64 && std::isalpha(static_cast<unsigned char>(name[0])) &&
           std::all_of(name.begin(), name.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
  };
  for (const std::string& name : names) {
    if (!identifier(name)) {
      throw Invalid(field, fmt::format("has the name '{}': valid a letter, then letters, digits or '_' (at most 64)",
                                       name.substr(0, 64)));
    }
  }
  if (std::set<std::string>(names.begin(), names.end()).size() != names.size()) {
    throw Invalid(field, "repeats a name: valid distinct names");
  }
  const std::vector<std::string> start = StartStateNames(names);
  if (std::set<std::string>(start.begin(), start.end()).size() != start.size()) {
    throw Invalid(field, "give a position and a velocity the same start-state name (x1 and v1 both make v1_0): valid "
                         "names whose start-state names q_0, v<k>_0 for x<k> and v_q_0 differ");
  }
  // The state's columns sit beside the parameters and the fixed columns of result files (a sweep's
  // CSV). (A coordinate 'b' gives a velocity column v_b, the belt's speed's name: a sweep in v_b refuses it.)
  static const std::set<std::string> kReserved = {
      "omega", "F_k", "F_s", "phi", "period", "k", "chain", "direction", "step", "section_phase",
      "stops_per_period", "sticks_per_period", "pt", "label", "stable", "admissible", "newton_iterations", "step_size",
      // a brute-force map's (io/map_file.hpp)
      "i", "j", "ni", "nj", "run", "attractors", "attractor", "status", "starts"};
  for (const std::string& column : StateColumnNames(names)) {
    const bool duration = column.size() > 1 && column[0] == 'd' &&
                          std::all_of(column.begin() + 1, column.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
    if (kReserved.count(column) != 0 || duration) {
      throw Invalid(field, fmt::format("gives the state a column '{}', a name files use for another quantity (a "
                                       "parameter, a duration d<k> or a fixed column): valid other names",
                                       column));
    }
  }
}

LinearOscillatorModes ModesOf(const LinearOscillatorData& data) {
  const Eigen::Index n = data.mass.rows();
  if (n < 1 || n > kMaxCoordinates) {
    throw InvalidInput("mass", fmt::format("a {}x{} matrix", data.mass.rows(), data.mass.cols()),
                       fmt::format("1 to {} coordinates", kMaxCoordinates));
  }
  CheckSymmetricPositiveDefinite("mass", data.mass, n);
  CheckSymmetricPositiveDefinite("stiffness", data.stiffness, n);
  const Eigen::MatrixXd damping = data.damping.size() == 0 ? Eigen::MatrixXd::Zero(n, n) : data.damping;
  if (damping.rows() != n || damping.cols() != n) {
    throw Invalid("damping", fmt::format("is {}x{}: valid a {}x{} matrix or none", damping.rows(), damping.cols(), n, n));
  }
  if (!damping.allFinite()) throw Invalid("damping", "has an entry that is not finite: valid finite entries");
  if (data.forcing.size() != n) {
    throw Invalid("forcing", fmt::format("has {} entries: valid one per coordinate, {}", data.forcing.size(), n));
  }
  if (!(data.forcing.cwiseAbs().maxCoeff() <= kMaxForce)) {
    throw Invalid("forcing", fmt::format("has an entry of magnitude {:g}: valid finite entries of magnitude <= {:g}",
                                         data.forcing.cwiseAbs().maxCoeff(), kMaxForce));
  }
  if (!(std::abs(data.friction_slope) <= kMaxForce)) {
    throw InvalidInput("friction_slope", data.friction_slope,
                       fmt::format("-{0:g} <= friction_slope <= {0:g} (force per unit slip speed)", kMaxForce));
  }
  CheckCoordinateNames(data.coordinates, n, "coordinates");
  CheckUnits(data.units);
  // In a slip F = -F_k sign(s) - alpha s: alpha damps the contact's coordinate; a stick holds it.
  Eigen::MatrixXd slip_damping = damping;
  slip_damping(n - 1, n - 1) += data.friction_slope;
  // A slip's damping is the friction slope's where C adds nothing to the contact's coordinate.
  const char* slip_field = data.friction_slope != 0.0 && damping.col(n - 1).isZero() ? "friction_slope" : "damping";
  LinearOscillatorModes modes{BasisOf(data, slip_damping, n, slip_field), BasisOf(data, damping, n - 1, "damping"), {}, 0.0};
  const Eigen::MatrixXd mass_inverse = data.mass.llt().solve(Eigen::MatrixXd::Identity(n, n));
  const double contact_compliance = mass_inverse(n - 1, n - 1);
  modes.holding.resize(2 * n);
  modes.holding << (mass_inverse * data.stiffness).row(n - 1), (mass_inverse * damping).row(n - 1);
  modes.holding /= contact_compliance;
  modes.holding_forcing = mass_inverse.row(n - 1).dot(data.forcing) / contact_compliance;
  return modes;
}

ModelDescription DescribeLinearOscillator(const LinearOscillatorData& data, const LinearOscillatorModes& modes) {
  const Eigen::Index n = data.mass.rows();
  ModelDescription d;
  d.name = data.name;
  double lowest = std::numeric_limits<double>::infinity(), highest = 0.0;
  for (const FirstOrderBasis* basis : {&modes.slip, &modes.stick}) {
    for (const std::complex<double>& lambda : basis->eigenvalues) {
      lowest = std::min(lowest, std::abs(lambda));
      highest = std::max(highest, std::abs(lambda));
    }
  }
  lowest *= 1e-3;
  highest *= 1e3;
  d.units = data.units;
  d.parameters = {
      {"omega", "forcing frequency", d.units.Frequency(), lowest, highest,
       fmt::format("{:.6g} <= omega <= {:.6g}, away from the natural frequencies", lowest, highest)},
      {"F_k", "kinetic friction force", d.units.force, std::numeric_limits<double>::min(), kMaxForce,
       fmt::format("0 < F_k <= {:g}", kMaxForce)},
      {"F_s", "static friction force", d.units.force, std::numeric_limits<double>::min(), kMaxForce,
       fmt::format("F_k <= F_s <= {:g}", kMaxForce)},
      {"v_b", "the surface's (belt's) speed", d.units.Speed(), -kMaxSpeed, kMaxSpeed,
       fmt::format("-{0:g} <= v_b <= {0:g}", kMaxSpeed)}};
  d.coordinates = data.coordinates;
  for (Eigen::Index j = static_cast<Eigen::Index>(d.coordinates.size()); j < n; ++j) d.coordinates.push_back(fmt::format("x{}", j + 1));
  for (const std::string& q : d.coordinates) d.state_components.push_back(q);
  for (const std::string& q : d.coordinates) d.state_components.push_back(q + "'");
  d.state_columns = StateColumnNames(d.coordinates);
  d.initial_state = StartStateNames(d.coordinates);
  d.contact = {"s", "s'", "s''", "F", "F_k", "F_s", "F_k = 0", "grazing-sliding (F_s = F_k)"};
  return d;
}

void LinearOscillatorData::AddTo(Fingerprint& hash) const {
  for (const Eigen::MatrixXd* m : {&mass, &damping, &stiffness}) {
    hash.Add(static_cast<std::uint64_t>(m->rows()));
    hash.Add(static_cast<std::uint64_t>(m->cols()));
    for (Eigen::Index k = 0; k < m->size(); ++k) hash.AddNumber(m->data()[k]);
  }
  hash.Add(static_cast<std::uint64_t>(forcing.size()));
  for (Eigen::Index k = 0; k < forcing.size(); ++k) hash.AddNumber(forcing(k));
  hash.AddNumber(friction_slope);
  hash.Add(coordinates.size());
  for (const std::string& coordinate : coordinates) hash.AddText(coordinate);
  hash.AddText(name);
  // Units other than SI only: the fingerprints of runs made before units could be declared stand.
  if (units != SiUnits()) {
    for (const auto& [quantity, unit] : ModelUnits::kNamed) hash.AddText(units.*unit);
  }
}

}  // namespace stickslip
