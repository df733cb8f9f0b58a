#include "stickslip/orbits/floquet_gradients.hpp"

// <Eigen/Core> must precede the unsupported AutoDiff module.
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "stickslip/orbits/stability.hpp"

namespace stickslip {

namespace {

namespace ov = orbit_variables;

// Derivatives held on the stack up to this many directions (15 listed segments): the heap
// allocations of dynamic ones were half the cost of a curve's point.
constexpr int kStackDirections = 24;

template <typename Dual>
void Split(const Matrix4<Dual>& m, int variables, Eigen::Matrix4d* value, std::vector<Eigen::Matrix4d>* derivatives) {
  derivatives->assign(static_cast<std::size_t>(variables), Eigen::Matrix4d::Zero());
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      (*value)(i, j) = m(i, j).value();
      const auto& d = m(i, j).derivatives();
      for (int k = 0; k < d.size(); ++k) (*derivatives)[static_cast<std::size_t>(k)](i, j) = d(k);
    }
  }
}

template <typename Dual>
MonodromyGradient Gradients(const Orbit& orbit) {
  using Derivatives = typename Dual::DerType;
  const int n = orbit.signature.size();
  const int variables = ov::Count(n);
  auto seed = [&](double value, int direction) { return Dual(value, variables, direction); };
  // x2' = 0 at the origin, a segment end: not a variable (orbit.hpp).
  const StateT<Dual> x0(seed(orbit.x10, ov::kX10), seed(orbit.x20, ov::kX20), seed(orbit.v10, ov::kV10),
                        Dual(0.0, Derivatives::Zero(variables)));
  std::vector<Dual> durations;
  for (int i = 0; i < n; ++i) durations.push_back(seed(orbit.durations[i], ov::Duration(i)));
  BasicParameters<Dual> p;
  for (ParameterId id : kAllParameters) p[id] = seed(orbit.parameters[id], ov::Parameter(n, id));
  const MonodromyT<Dual> m = Monodromy<Dual>(orbit.signature, x0, seed(orbit.phi, ov::kPhi), durations, p);
  MonodromyGradient result;
  Split(m.period, variables, &result.period, &result.d_period);
  Split(m.listed, variables, &result.listed, &result.d_listed);
  return result;
}

}  // namespace

MonodromyGradient MonodromyGradients(const Orbit& orbit) {
  if (ov::Count(orbit.signature.size()) <= kStackDirections) {
    return Gradients<Eigen::AutoDiffScalar<Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kStackDirections, 1>>>(orbit);
  }
  return Gradients<Eigen::AutoDiffScalar<Eigen::VectorXd>>(orbit);
}

}  // namespace stickslip
