// A linear oscillator with one Coulomb contact, as data:
//   M q'' + K q = g cos(omega t + phi) + e_n F,   q in R^n,
// the contact on the last coordinate q_n (order the coordinates so), with kinetic level F_k and
// static level F_s >= F_k. This file checks the data and computes, once per model, the modal bases
// the closed forms of linear_oscillator.hpp are written in: the free modes of the whole system
// (a slip: F = -F_k sign(q_n') is constant) and those of the system with q_n held (a stick).
// Undamped and with K positive definite in this step: every coordinate in a mode is then a sum of
// sinusoids (numerics/sinusoid_sum.hpp). Viscous damping (complex modes, exponential_sum.hpp), a
// singular K (a rigid-body mode: polynomial terms), a belt and autonomous orbits come next
// (the general-oscillator issue).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "stickslip/model/model_description.hpp"

namespace stickslip {

struct LinearOscillatorData {
  Eigen::MatrixXd mass;       // M, symmetric positive definite
  Eigen::MatrixXd stiffness;  // K, symmetric positive definite
  Eigen::VectorXd forcing;    // g: the force amplitude on each coordinate
  std::vector<std::string> coordinates;  // their names; empty: x1 ... xn
  std::string name = "linear-oscillator";
};

// q = shapes eta, eta = projector q; eta_i'' + lambda_i eta_i = (shapes^T f)_i for a force f.
struct ModalBasis {
  Eigen::MatrixXd shapes;       // n x m, mass-normalised: shapes^T M shapes = I
  Eigen::MatrixXd projector;    // m x n
  Eigen::VectorXd eigenvalues;  // lambda_i = omega_i^2 > 0, increasing
};

struct LinearOscillatorModes {
  ModalBasis slip;   // the n modes of (M, K)
  ModalBasis stick;  // the n - 1 modes with q_n held: the contact's row of `shapes` and column of `projector` are 0
  // The friction force a stick needs, F = holding_stiffness . q - holding_forcing cos(psi): from
  // q_n'' = 0 in M q'' = -K q + g cos(psi) + e_n F, F = [(M^-1 K q)_n - (M^-1 g)_n cos psi] / (M^-1)_nn.
  Eigen::RowVectorXd holding_stiffness;
  double holding_forcing = 0.0;
};

// Throws InvalidInput naming the field (mass, stiffness, forcing, coordinates) when M or K is not
// square, symmetric and positive definite with finite entries, the sizes disagree, n is not 1 ... 50,
// or the names are not n distinct non-empty names.
LinearOscillatorModes ModesOf(const LinearOscillatorData& data);

// The parameters (omega in rad/s, F_k and F_s in N, SI by default) with their ranges, the
// coordinates and the initial-state names x1_0 ... xn_0, v1_0 ... vn_0.
ModelDescription DescribeLinearOscillator(const LinearOscillatorData& data, const LinearOscillatorModes& modes);

}  // namespace stickslip
