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
  const Eigen::Index size = m.rows();
  const Matrix identity = Matrix::Identity(size, size);
  if (antisymmetric) result.symmetry_test = (identity - listed).determinant();
  result.monodromy = m;
  const Eigen::EigenSolver<Matrix> eigen(m, /*computeEigenvectors=*/false);
  if constexpr (kStateSize == Eigen::Dynamic) result.multipliers.resize(static_cast<std::size_t>(size));
  for (Eigen::Index k = 0; k < size; ++k) result.multipliers[static_cast<std::size_t>(k)] = eigen.eigenvalues()(k);
  std::sort(result.multipliers.begin(), result.multipliers.end(), [](const auto& a, const auto& b) {
    if (std::abs(a) != std::abs(b)) return std::abs(a) > std::abs(b);
    return a.imag() > b.imag();
  });
  result.stable = std::abs(result.multipliers[0]) < 1.0;
  result.fold_test = (m - identity).determinant();
  result.flip_test = (m + identity).determinant();
  std::complex<double> torus = 1.0;
  for (std::size_t i = 0; i < result.multipliers.size(); ++i) {
    for (std::size_t j = i + 1; j < result.multipliers.size(); ++j) torus *= result.multipliers[i] * result.multipliers[j] - 1.0;
  }
  result.torus_test = torus.real();
  return result;
}

// The paper's model, one mass, and any model whose size comes from a file.
template <int kStateSize>
using MonodromyMatrix = typename BasicStability<kStateSize>::Matrix;
template BasicStability<Pascal2014::kStateSize> StabilityFromMonodromy<Pascal2014::kStateSize>(
    const MonodromyMatrix<Pascal2014::kStateSize>&, const MonodromyMatrix<Pascal2014::kStateSize>&, bool, bool);
template BasicStability<2> StabilityFromMonodromy<2>(const MonodromyMatrix<2>&, const MonodromyMatrix<2>&, bool, bool);
template BasicStability<Eigen::Dynamic> StabilityFromMonodromy<Eigen::Dynamic>(const MonodromyMatrix<Eigen::Dynamic>&,
                                                                               const MonodromyMatrix<Eigen::Dynamic>&,
                                                                               bool, bool);

Stability StabilityOf(const Orbit& orbit) {
  const MonodromyT<double> m = Monodromy<double>(orbit.signature, orbit.InitialState(), orbit.phi,
                                                 orbit.durations, orbit.parameters);
  return StabilityFromMonodromy<Pascal2014::kStateSize>(m.period, m.listed, orbit.signature.antisymmetric(), m.one_sided);
}

}  // namespace stickslip
