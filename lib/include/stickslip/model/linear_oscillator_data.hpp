// A linear oscillator with one Coulomb contact, as data:
//   M q'' + C q' + K q = g cos(omega t + phi) + e_n F,   q in R^n,
// the contact on the last coordinate q_n (order the coordinates so), with kinetic level F_k and
// static level F_s >= F_k. This file checks the data and computes, once per model, the modal bases
// the closed forms of linear_oscillator.hpp are written in: the eigenvectors of the first-order
// system z' = A z (z = (q, q')) of the whole oscillator (a slip: F = -F_k sign(q_n') is constant)
// and of the oscillator with q_n held (a stick). With damping the eigenvalues are complex and every
// coordinate in a mode is a sum of exponentially weighted sinusoids (numerics/exponential_sum.hpp);
// without, the rates are 0. C may be any matrix (non-symmetric in brake models); M symmetric
// positive definite; K symmetric positive definite (a singular K, a rigid-body mode, needs
// polynomial terms).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "stickslip/model/model_description.hpp"
#include "stickslip/numerics/fingerprint.hpp"

namespace stickslip {

// The most coordinates a linear oscillator may have (ModesOf).
inline constexpr int kMaxLinearOscillatorCoordinates = 50;

struct LinearOscillatorData {
  Eigen::MatrixXd mass;       // M, symmetric positive definite
  Eigen::MatrixXd damping;    // C, any; empty: none
  Eigen::MatrixXd stiffness;  // K, symmetric positive definite
  Eigen::VectorXd forcing;    // g: the force amplitude on each coordinate
  // alpha: in a slip the kinetic level is F_k + alpha |s|, s the contact's relative velocity (force
  // per unit speed; alpha < 0, friction falling with the slip speed, destabilises steady sliding on
  // a belt). F = -(F_k + alpha |s|) sign(s) = -F_k sign(s) - alpha s keeps every mode linear: alpha
  // adds to the contact's damping in a slip.
  double friction_slope = 0.0;
  std::vector<std::string> coordinates;  // their names; empty: x1 ... xn
  std::string name = "linear-oscillator";
  ModelUnits units = SiUnits();  // what its numbers are in: labels, the numbers are not converted

  // Every field into a run's fingerprint (the shards of one brute-force map share it).
  void AddTo(Fingerprint& hash) const;
};

// One mode's first-order system y' = A y + inputs, on the D components of the state (q, q') it
// moves (all 2n in a slip; in a stick all but q_n and q_n'), and its eigenvectors: y = V eta,
// eta = W y with W = V^-1, eta_k' = lambda_k eta_k + (W input)_k.
struct FirstOrderBasis {
  std::vector<int> components;   // the state index of each of the D components
  Eigen::MatrixXd system;         // A
  Eigen::MatrixXd system_inverse;  // A^-1 (K is invertible)
  Eigen::MatrixXcd shapes;        // V
  Eigen::MatrixXcd projector;     // W
  Eigen::VectorXcd eigenvalues;   // lambda
  Eigen::VectorXd forcing;        // the input per unit cos(psi)
  Eigen::VectorXd friction;       // per unit friction force (a slip)
  Eigen::VectorXd held_position;  // per unit held position q_n (a stick)
  Eigen::VectorXd held_velocity;  // per unit held velocity q_n' (a stick)
};

struct LinearOscillatorModes {
  FirstOrderBasis slip;
  FirstOrderBasis stick;
  // The friction force a stick needs, F = holding . (q, q') - holding_forcing cos(psi): from
  // q_n'' = 0 in M q'' = -K q - C q' + g cos(psi) + e_n F,
  // F = [(M^-1 (K q + C q'))_n - (M^-1 g)_n cos psi] / (M^-1)_nn.
  Eigen::RowVectorXd holding;
  double holding_forcing = 0.0;
};

// Throws InvalidInput naming `field` unless there are no names or n distinct ones, each a letter
// followed by letters, digits or '_' (so that x1, x1' and the file columns stay distinct), whose
// start-state names (DescribeLinearOscillator) differ too.
void CheckCoordinateNames(const std::vector<std::string>& names, Eigen::Index n, const std::string& field);

// Throws InvalidInput naming the field (mass, damping, stiffness, forcing, friction_slope,
// coordinates) when alpha or an entry of the forcing is not finite or beyond 1e15 in magnitude, M or K
// is not square, symmetric and positive definite with finite entries, C is not n x n and finite,
// the sizes disagree, n is not 1 ... 50, a mode's system is not finite (scales too far apart) or
// its eigenvectors reproduce the matrix exponential worse than 1e-9 (nearly dependent ones, as
// near critical damping), the names are not as CheckCoordinateNames asks, or the units not as
// CheckUnits asks.
LinearOscillatorModes ModesOf(const LinearOscillatorData& data);

// The parameters (omega in rad per time unit, F_k and F_s in force units, v_b in length per time unit,
// by the data's units) with their ranges, the
// coordinates and the initial-state names by the coordinates' names: q_0 for each position; for each
// velocity the name with its leading x made v (x1: v1_0), or v_ before any other (left: v_left_0).
ModelDescription DescribeLinearOscillator(const LinearOscillatorData& data, const LinearOscillatorModes& modes);

}  // namespace stickslip
