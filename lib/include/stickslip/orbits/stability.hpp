// Stability of a periodic orbit of any model (model/oscillator_model.hpp): the monodromy matrix
// of the stroboscopic (period) map as the product of the closed-form flow Jacobians of the
// segments and the saltation (jump) matrices at each switching event (Leine & Nijmeijer,
// Dynamics and Bifurcations of Non-Smooth Mechanical Systems, 2004; the paper's in
// model/pascal_2014/saltation.hpp), and its Floquet multipliers.
#pragma once

#include <algorithm>
#include <array>
#include <complex>
#include <limits>
#include <span>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "stickslip/model/oscillator_model.hpp"
#include "stickslip/model/pascal_2014.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/segment_walk.hpp"

namespace stickslip {

template <int kStateSize>
struct BasicStability {
  using Matrix = Eigen::Matrix<double, kStateSize, kStateSize>;
  using Multipliers = std::conditional_t<kStateSize == Eigen::Dynamic, std::vector<std::complex<double>>,
                                         std::array<std::complex<double>, std::max(kStateSize, 0)>>;
  Matrix monodromy = FixedSizeDefault<Matrix, true>();  // from t = 0 to the period
  Multipliers multipliers{};                         // by decreasing modulus
  // Every |multiplier| < 1; an autonomous orbit's but the one nearest 1 (StabilityOf).
  bool stable = false;
  // Test functions of the smooth bifurcations, continuous along a branch:
  double fold_test = 0.0;   // det(M - I): a multiplier through +1 (LP)
  double flip_test = 0.0;   // det(M + I): a multiplier through -1 (PD)
  double torus_test = 0.0;  // prod_{i<j} (mu_i mu_j - 1): a complex pair on the unit circle (TR)
  // Antisymmetric orbits only (NaN for the others): det(I - M_half) = det(H + I), where H =
  // -M_half is the half-period map followed by the mirror X -> -X, and M = H^2. Zero where a
  // multiplier of H passes -1: a symmetry-breaking pitchfork (SB), where the orbit's
  // non-antisymmetric twins branch off. M then has a multiplier +1 without a fold of the branch,
  // and det(M + I) = |det(H - iI)|^2 cannot change sign, so no other test sees it.
  double symmetry_test = std::numeric_limits<double>::quiet_NaN();
  // An abnormal stop is a grazing of the contact's rest (x2' = 0): perturbations on one side cross zero and stick
  // for an instant, so the period map has only one-sided derivatives there. The multipliers are
  // those of the side that keeps it off rest (S = I at the abnormal stop).
  bool one_sided = false;
};
using Stability = BasicStability<4>;  // the paper's model

// The same of any model, its size known at run time: what the layers above the orbits
// (branches/orbit_monitor.hpp) see through the erased orbit problem (orbits/orbit_problem.hpp).
struct OrbitStability {
  Eigen::MatrixXd monodromy;
  std::vector<std::complex<double>> multipliers;  // by decreasing modulus
  bool stable = false;
  double fold_test = 0.0;
  double flip_test = 0.0;
  double torus_test = 0.0;
  double symmetry_test = std::numeric_limits<double>::quiet_NaN();
  bool one_sided = false;
};
template <int kStateSize>
OrbitStability ToOrbitStability(const BasicStability<kStateSize>& s) {
  return {s.monodromy, {s.multipliers.begin(), s.multipliers.end()}, s.stable, s.fold_test, s.flip_test,
          s.torus_test, s.symmetry_test, s.one_sided};
}

// The monodromy matrix of an orbit from its walk: the products of the segments' transition
// matrices and the saltation matrices at their ends. Templated on the scalar: forward-mode AD
// through it gives its exact derivatives (orbits/floquet_gradients.hpp).
template <typename T, typename Model = Pascal2014>
struct MonodromyT {
  using Matrix = Eigen::Matrix<T, Model::kStateSize, Model::kStateSize>;
  Matrix period;  // over the whole period (Monodromy starts both at the identity of the state's size)
  // Over the listed segments: the half-period map of an antisymmetric orbit (the period's for the others).
  Matrix listed;
  bool one_sided = false;  // an abnormal stop on the way (Stability::one_sided)
};
template <typename T, typename Model>
MonodromyT<T, Model> Monodromy(const Model& model, const Signature& signature,
                               const typename Model::template StateT<T>& x0, const T& phi, std::span<const T> durations,
                               const typename Model::template ParametersT<T>& p) {
  MonodromyT<T, Model> result;
  result.period = result.listed = MonodromyT<T, Model>::Matrix::Identity(x0.size(), x0.size());
  // The whole period: the listed segments, then their mirror images for an antisymmetric orbit,
  // flowed from the actual states (the symmetry is not assumed).
  const std::vector<SegmentSpec> plan = SegmentPlan(signature, Extent::kFullPeriod);
  WalkSegments<T>(model, plan, x0, phi, durations, p, PhaseRule::kAccumulated, [&](const SegmentVisit<T, Model>& s) {
    result.one_sided = result.one_sided || s.spec.end == SegmentEndKind::kAbnormalStop;
    result.period = model.SaltationMatrix(s.spec.mode, s.spec.next, s.end, s.end_phase, p) *
                    model.TransitionMatrix(s.spec.mode, s.duration, p) * result.period;
    if (s.index + 1 == signature.size()) result.listed = result.period;
  });
  return result;
}
template <typename T>
MonodromyT<T> Monodromy(const Signature& signature, const StateT<T>& x0, const T& phi, std::span<const T> durations,
                        const BasicParameters<T>& p) {
  return Monodromy<T>(Pascal2014{}, signature, x0, phi, durations, p);
}

// The multipliers and test functions of a monodromy (compiled for the state sizes of the models
// the library serves).
template <int kStateSize>
BasicStability<kStateSize> StabilityFromMonodromy(const Eigen::Matrix<double, kStateSize, kStateSize>& period,
                                                  const Eigen::Matrix<double, kStateSize, kStateSize>& listed,
                                                  bool antisymmetric, bool one_sided);

// Whether every multiplier but the one nearest 1 lies inside the unit circle: an autonomous orbit's
// stability, whose multiplier 1 (a shift along the orbit in time) decides nothing, and comes out of
// the eigensolver as 1 + rounding on either side.
template <typename Multipliers>
bool StableButTheTrivialMultiplier(const Multipliers& multipliers) {
  const auto trivial = std::min_element(multipliers.begin(), multipliers.end(),
                                        [](const auto& a, const auto& b) { return std::abs(a - 1.0) < std::abs(b - 1.0); });
  for (auto it = multipliers.begin(); it != multipliers.end(); ++it) {
    if (it != trivial && !(std::abs(*it) < 1.0)) return false;
  }
  return true;
}

template <typename Model>
BasicStability<Model::kStateSize> StabilityOf(const Model& model, const BasicOrbit<Model>& orbit) {
  const MonodromyT<double, Model> m = Monodromy<double>(model, orbit.signature, orbit.start, orbit.phi,
                                                        std::span<const double>(orbit.durations), orbit.parameters);
  BasicStability<Model::kStateSize> s =
      StabilityFromMonodromy<Model::kStateSize>(m.period, m.listed, orbit.signature.antisymmetric(), m.one_sided);
  if (model.Autonomous()) s.stable = StableButTheTrivialMultiplier(s.multipliers);
  return s;
}
Stability StabilityOf(const Orbit& orbit);

}  // namespace stickslip
