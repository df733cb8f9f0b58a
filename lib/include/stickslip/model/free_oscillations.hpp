// The free oscillations of a linear oscillator's mode (linear_oscillator_data.hpp): from the
// eigenvalues lambda of its first-order system, each complex pair (Im lambda > 0) as its undamped
// frequency |lambda| and damping ratio -Re lambda / |lambda|; a real eigenvalue as an overdamped
// decay (or, positive, a growth) of rate |lambda|. What `stickslip describe` lists for a slip and a
// stick.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace stickslip {

struct FreeOscillation {
  double frequency = 0.0;      // |lambda|, rad/s in SI
  double damping_ratio = 0.0;  // -Re lambda / |lambda|: 0 undamped, < 0 growing
  bool oscillates = true;      // false for a real eigenvalue
};

// By increasing frequency.
std::vector<FreeOscillation> FreeOscillations(const Eigen::VectorXcd& eigenvalues);

}  // namespace stickslip
