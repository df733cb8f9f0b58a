#include "stickslip/orbits/stability.hpp"

#include <algorithm>

#include <Eigen/Eigenvalues>

namespace stickslip {

Stability StabilityOf(const Orbit& orbit) {
  const Parameters& p = orbit.parameters;
  Stability result;
  const MonodromyT<double> monodromy = Monodromy<double>(orbit.signature, orbit.InitialState(), orbit.phi,
                                                         orbit.durations, p);
  const Eigen::Matrix4d& m = monodromy.period;
  result.one_sided = monodromy.one_sided;
  if (orbit.signature.antisymmetric()) {
    result.symmetry_test = (Eigen::Matrix4d::Identity() - monodromy.listed).determinant();
  }
  result.monodromy = m;
  const Eigen::EigenSolver<Eigen::Matrix4d> eigen(m, /*computeEigenvectors=*/false);
  for (int k = 0; k < 4; ++k) result.multipliers[k] = eigen.eigenvalues()(k);
  std::sort(result.multipliers.begin(), result.multipliers.end(), [](const auto& a, const auto& b) {
    if (std::abs(a) != std::abs(b)) return std::abs(a) > std::abs(b);
    return a.imag() > b.imag();
  });
  result.stable = std::abs(result.multipliers[0]) < 1.0;
  result.fold_test = (m - Eigen::Matrix4d::Identity()).determinant();
  result.flip_test = (m + Eigen::Matrix4d::Identity()).determinant();
  std::complex<double> torus = 1.0;
  for (int i = 0; i < 4; ++i) {
    for (int j = i + 1; j < 4; ++j) torus *= result.multipliers[i] * result.multipliers[j] - 1.0;
  }
  result.torus_test = torus.real();
  return result;
}

}  // namespace stickslip
