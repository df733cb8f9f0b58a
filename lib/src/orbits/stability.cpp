#include "stickslip/orbits/stability.hpp"

#include <algorithm>

#include <Eigen/Eigenvalues>

namespace stickslip {

template <int kStateSize>
BasicStability<kStateSize> StabilityFromMonodromy(const Eigen::Matrix<double, kStateSize, kStateSize>& period,
                                                  const Eigen::Matrix<double, kStateSize, kStateSize>& listed,
                                                  bool antisymmetric, bool one_sided) {
  using Matrix = typename BasicStability<kStateSize>::Matrix;
  BasicStability<kStateSize> result;
  const Matrix& m = period;
  result.one_sided = one_sided;
  if (antisymmetric) result.symmetry_test = (Matrix::Identity() - listed).determinant();
  result.monodromy = m;
  const Eigen::EigenSolver<Matrix> eigen(m, /*computeEigenvectors=*/false);
  for (int k = 0; k < kStateSize; ++k) result.multipliers[k] = eigen.eigenvalues()(k);
  std::sort(result.multipliers.begin(), result.multipliers.end(), [](const auto& a, const auto& b) {
    if (std::abs(a) != std::abs(b)) return std::abs(a) > std::abs(b);
    return a.imag() > b.imag();
  });
  result.stable = std::abs(result.multipliers[0]) < 1.0;
  result.fold_test = (m - Matrix::Identity()).determinant();
  result.flip_test = (m + Matrix::Identity()).determinant();
  std::complex<double> torus = 1.0;
  for (int i = 0; i < kStateSize; ++i) {
    for (int j = i + 1; j < kStateSize; ++j) torus *= result.multipliers[i] * result.multipliers[j] - 1.0;
  }
  result.torus_test = torus.real();
  return result;
}

// The paper's model, and one mass (the tests' second model; the one-mass models to come).
template <int kStateSize>
using MonodromyMatrix = typename BasicStability<kStateSize>::Matrix;
template BasicStability<Pascal2014::kStateSize> StabilityFromMonodromy<Pascal2014::kStateSize>(
    const MonodromyMatrix<Pascal2014::kStateSize>&, const MonodromyMatrix<Pascal2014::kStateSize>&, bool, bool);
template BasicStability<2> StabilityFromMonodromy<2>(const MonodromyMatrix<2>&, const MonodromyMatrix<2>&, bool, bool);

Stability StabilityOf(const Orbit& orbit) {
  const MonodromyT<double> m = Monodromy<double>(orbit.signature, orbit.InitialState(), orbit.phi,
                                                 orbit.durations, orbit.parameters);
  return StabilityFromMonodromy<Pascal2014::kStateSize>(m.period, m.listed, orbit.signature.antisymmetric(), m.one_sided);
}

}  // namespace stickslip
