// Exact derivatives of the monodromy matrix (orbits/stability.hpp) with respect to every orbit
// variable (orbit.hpp's order: x10, x20, v10, phi, d1..dn, chi, eta, omega, u_s, u_r): forward-mode
// AD through the templated walk, transition and saltation matrices. What the curves of folds,
// period doublings, symmetry breakings and torus points (branches/floquet_condition.hpp) add to the
// periodicity equations.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

struct MonodromyGradient {
  Eigen::Matrix4d period;                // M over the whole period (Stability::monodromy)
  std::vector<Eigen::Matrix4d> d_period;  // dM/dv, one per variable
  Eigen::Matrix4d listed;                // over the listed segments: the half period of an antisymmetric orbit
  std::vector<Eigen::Matrix4d> d_listed;
};

MonodromyGradient MonodromyGradients(const Orbit& orbit);

}  // namespace stickslip
