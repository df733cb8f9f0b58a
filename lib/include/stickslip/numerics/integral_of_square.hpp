// The integral of f(t)^2 over [0, d] for f an exponential sum (exponential_sum.hpp), in closed form:
// the energy a viscous-like force dissipates along one segment of a linear oscillator (a friction
// slope alpha dissipates alpha int s^2 dt over a slip, s the slip speed).
//
// With each term the real part of c_k t^{m_k} e^{lambda_k t} (c = a - i b, lambda = sigma + i nu),
//   int_0^d f^2 dt = 1/2 sum_{j,k} Re[c_j c_k J(m_j + m_k, lambda_j + lambda_k)
//                                     + c_j conj(c_k) J(m_j + m_k, lambda_j + conj(lambda_k))],
//   J(M, lambda) = int_0^d t^M e^{lambda t} dt = d^{M+1} K_M(lambda d),  K_M(z) = int_0^1 u^M e^{z u} du,
// K_M by its power series sum_j z^j / (j! (M + j + 1)) where |z| <= M + 1 (no cancellation of
// e^z - 1 near z = 0), else upwards from K_0 = (e^z - 1)/z by K_M = (e^z - M K_{M-1})/z, which
// damps errors there (M/|z| < 1). Rounding is relative to the terms' own sizes: where they cancel
// to a much smaller f, the integral's error is about eps (sum |c_k|)^2 d.
//
//   const double dissipated = alpha * IntegralOfSquare(model.ContactVelocityAlong(motion), duration);
#pragma once

#include "stickslip/numerics/exponential_sum.hpp"
#include "stickslip/numerics/sinusoid_sum.hpp"

namespace stickslip {

// int_0^d f(t)^2 dt for d >= 0; inf or NaN where an exponential overflows (never a wrong finite
// number).
double IntegralOfSquare(const ExponentialSum& f, double d);
double IntegralOfSquare(const SinusoidSum& f, double d);

}  // namespace stickslip
