// The integral of f(t)^2 over [0, d] for f an exponential sum (exponential_sum.hpp), in closed form:
// the energy a viscous-like force dissipates along one segment of a linear oscillator (a friction
// slope alpha dissipates alpha int s^2 dt over a slip, s the slip speed).
//
// With each term the real part of c_k t^{m_k} e^{lambda_k t} (c = a - i b, lambda = sigma + i nu),
//   int_0^d f^2 dt = 1/2 sum_{j,k} Re[c_j c_k J(m_j + m_k, lambda_j + lambda_k)
//                                     + c_j conj(c_k) J(m_j + m_k, lambda_j + conj(lambda_k))],
//   J(M, lambda) = int_0^d t^M e^{lambda t} dt = d^{M+1} K_M(lambda d),  K_M(z) = int_0^1 u^M e^{z u} du,
// for the powers a linear oscillator's sums have (m_k 0 or 1: a drift; so M <= 2): K_M by a power
// series where |z| <= M + 1 (no cancellation of e^z - 1 near z = 0): sum_j z^j / (j! (M + j + 1))
// for Re z >= 0, e^z sum_j (-z)^j M! / (M + 1 + j)! for Re z < 0 (each without alternating real
// parts); else upwards from K_0 = (e^z - 1)/z by K_M = (e^z - M K_{M-1})/z, which damps errors
// there (M/|z| < 1). Its rounding is relative to the terms' own sizes, eps int_0^d (sum_k |c_k|
// t^{m_k} e^{sigma_k t})^2 dt: where they cancel to a much smaller f (a slip near critical damping),
// more than 1e3 times the result, f^2 is integrated from f's values instead (Gauss-Legendre on
// panels where each term turns by at most a radian: exact to f's rounding; NaN beyond 1e5 panels).
//
//   const double dissipated = alpha * IntegralOfSquare(model.ContactVelocityAlong(motion), duration);
#pragma once

#include "stickslip/numerics/exponential_sum.hpp"
#include "stickslip/numerics/sinusoid_sum.hpp"

namespace stickslip {

// int_0^d f(t)^2 dt (>= 0); inf or NaN where an exponential overflows (never a wrong finite
// number). Throws InvalidInput naming "duration" unless 0 <= d is finite, and "power" for a term
// with a polynomial factor above t.
double IntegralOfSquare(const ExponentialSum& f, double d);
double IntegralOfSquare(const SinusoidSum& f, double d);

}  // namespace stickslip
