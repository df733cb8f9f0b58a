// Modal analysis of the two-mass oscillator (Pascal 2014, Appendix 1 and eq. 7): natural
// frequencies, modal matrices, the transition matrices H(t) of a slip and Gamma(t) of a stick,
// the forced amplitude Q and the static offset d0. Templated on the scalar for forward-mode AD.
#pragma once

#include <cmath>
#include <utility>

#include <Eigen/Core>

namespace stickslip {

template <typename T>
using Vector2 = Eigen::Matrix<T, 2, 1>;
template <typename T>
using Matrix2 = Eigen::Matrix<T, 2, 2>;
template <typename T>
using Matrix4 = Eigen::Matrix<T, 4, 4>;

// Roots omega1 < omega2 of D(s^2) = det(K - s^2 I) = 0 with K = [1 -chi; -chi*eta chi*eta]
// (eq. 56): s^4 - (1 + chi*eta) s^2 + chi*eta*(1 - chi) = 0. The discriminant
// (1 - chi*eta)^2 + 4 chi^2 eta is positive, so both roots are real, distinct and positive.
template <typename T>
std::pair<T, T> NaturalFrequencies(const T& chi, const T& eta) {
  using std::sqrt;
  const T trace = 1.0 + chi * eta;
  const T root = sqrt((1.0 - chi * eta) * (1.0 - chi * eta) + 4.0 * chi * chi * eta);
  // omega1^2 = (trace - root)/2 written as det/omega2^2 to avoid cancellation.
  const T omega2_sq = 0.5 * (trace + root);
  const T omega1_sq = chi * eta * (1.0 - chi) / omega2_sq;
  return {sqrt(omega1_sq), sqrt(omega2_sq)};
}

// Lambda = [psi_1 psi_2] with psi_j = (1, lambda_j), (K - omega_j^2 I) psi_j = 0, so
// lambda_j = (1 - omega_j^2)/chi (Appendix 1, after eq. 56).
template <typename T>
Matrix2<T> ModalMatrix(const T& chi, const T& omega1, const T& omega2) {
  Matrix2<T> lambda;
  lambda << T(1.0), T(1.0), (1.0 - omega1 * omega1) / chi, (1.0 - omega2 * omega2) / chi;
  return lambda;
}

// Lambda^{-1} = [lambda_2 -1; -lambda_1 1]/(lambda_2 - lambda_1), written out so that it works
// for any scalar type (the modes are distinct: lambda_1 != lambda_2).
template <typename T>
Matrix2<T> ModalMatrixInverse(const Matrix2<T>& lambda) {
  const T l1 = lambda(1, 0);
  const T l2 = lambda(1, 1);
  Matrix2<T> inverse;
  inverse << l2, T(-1.0), -l1, T(1.0);
  return inverse / (l2 - l1);
}

// H(t) = [H1 H2; H3 H1], H_i = Lambda B_i Lambda^{-1}, B_2 = diag(sin(omega_j t)/omega_j),
// B_1 = B_2', B_3 = B_2'' (eq. 55): the transition matrix of a slip in the coordinates
// Z - F of eq. (5).
template <typename T>
Matrix4<T> SlipTransition(const T& chi, const T& eta, const T& t) {
  using std::cos;
  using std::sin;
  const auto [w1, w2] = NaturalFrequencies(chi, eta);
  const Matrix2<T> lambda = ModalMatrix(chi, w1, w2);
  const Matrix2<T> lambda_inv = ModalMatrixInverse(lambda);
  auto similar = [&](const T& d1, const T& d2) {
    return Matrix2<T>(lambda * Vector2<T>(d1, d2).asDiagonal() * lambda_inv);
  };
  Matrix4<T> h;
  h.template topLeftCorner<2, 2>() = similar(cos(w1 * t), cos(w2 * t));
  h.template topRightCorner<2, 2>() = similar(sin(w1 * t) / w1, sin(w2 * t) / w2);
  h.template bottomLeftCorner<2, 2>() = similar(-w1 * sin(w1 * t), -w2 * sin(w2 * t));
  h.template bottomRightCorner<2, 2>() = h.template topLeftCorner<2, 2>();
  return h;
}

// Gamma(t) = [G1 G2; G3 G1], G_i = Sigma gamma_i Sigma^{-1}, gamma_2 = diag(sin t, t),
// Sigma = [1 chi; 0 1], gamma_1 = gamma_2', gamma_3 = gamma_2'' (eq. 58): the transition matrix
// of a stick (eq. 9-10), x1'' + x1 - chi x2 = 0, x2'' = 0.
template <typename T>
Matrix4<T> StickTransition(const T& chi, const T& t) {
  using std::cos;
  using std::sin;
  Matrix2<T> sigma;
  sigma << T(1.0), chi, T(0.0), T(1.0);
  Matrix2<T> sigma_inv;
  sigma_inv << T(1.0), -chi, T(0.0), T(1.0);
  auto similar = [&](const T& d1, const T& d2) {
    return Matrix2<T>(sigma * Vector2<T>(d1, d2).asDiagonal() * sigma_inv);
  };
  Matrix4<T> g;
  g.template topLeftCorner<2, 2>() = similar(cos(t), T(1.0));
  g.template topRightCorner<2, 2>() = similar(sin(t), t);
  g.template bottomLeftCorner<2, 2>() = similar(-sin(t), T(0.0));
  g.template bottomRightCorner<2, 2>() = g.template topLeftCorner<2, 2>();
  return g;
}

// Q = (q1, q2), q1 = chi/((omega^2 - omega1^2)(omega^2 - omega2^2)), q2 = q1 (1 - omega^2)/chi
// (eq. 7): the amplitude of the forced response R(t) = Q cos(omega t + phi). The product of the
// two factors equals det(K - omega^2 I), evaluated directly.
template <typename T>
Vector2<T> ForcedAmplitude(const T& chi, const T& eta, const T& omega) {
  const T w2 = omega * omega;
  const T det = (1.0 - w2) * (chi * eta - w2) - chi * chi * eta;
  const T q1 = chi / det;
  return Vector2<T>(q1, q1 * (1.0 - w2) / chi);
}

// d0 = (u_s/(1 - chi), u_s/(chi (1 - chi))) (eq. 7): the static equilibrium of a slip with
// x2' < 0 (friction +u_s); a slip with x2' > 0 has its equilibrium at -d0 (eq. 8).
template <typename T>
Vector2<T> StaticOffset(const T& chi, const T& u_s) {
  const T d01 = u_s / (1.0 - chi);
  return Vector2<T>(d01, d01 / chi);
}

}  // namespace stickslip
