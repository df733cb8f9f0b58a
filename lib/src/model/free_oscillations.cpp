#include "stickslip/model/free_oscillations.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace stickslip {

std::vector<FreeOscillation> FreeOscillations(const Eigen::VectorXcd& eigenvalues) {
  std::vector<FreeOscillation> out;
  for (const std::complex<double>& lambda : eigenvalues) {
    if (lambda.imag() < 0.0) continue;  // the pair's other half
    const double modulus = std::abs(lambda);
    // An undamped mode's ratio is 0, not the eigensolver's rounding (-5e-15, or -0).
    const double ratio = modulus > 0.0 ? -lambda.real() / modulus : 0.0;
    out.push_back({modulus, std::abs(ratio) <= 1e-12 ? 0.0 : ratio, lambda.imag() > 0.0});
  }
  std::sort(out.begin(), out.end(), [](const FreeOscillation& a, const FreeOscillation& b) { return a.frequency < b.frequency; });
  return out;
}

}  // namespace stickslip
