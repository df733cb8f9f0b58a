// A strict reader of Matrix Market files (NIST's text format for matrices, what finite-element
// codes export): the mass, damping and stiffness matrices and the forcing and contact vectors of a
// reduced model. Strict where Eigen 3.4's loadMarket is not: a file with fewer or more entries than
// its header says is refused (loadMarket trusts the count and returns success on a truncated
// file); a `symmetric` file's lower triangle fills both (loadMarket ignores the header and loses
// half the matrix); an index out of range, a repeated entry, an entry above the diagonal of a
// symmetric file, a value that is not a finite number are each refused with the line they are on.
// Formats `coordinate` and `array`; fields `real`, `double` and `integer`; symmetries `general` and
// `symmetric`. Complex, pattern, hermitian and skew-symmetric files are refused, as are matrices
// larger than the limits.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include <Eigen/Core>

namespace stickslip {

struct MatrixMarketLimits {
  Eigen::Index max_dimension = 1000;       // rows and columns, 1 ... 100000
  std::uintmax_t max_bytes = 16u << 20;   // of the file
};

// The matrix in `text`; throws InvalidInput naming `field` (the model's name for the matrix,
// "stiffness"), `source` (the file) and the line at fault.
Eigen::MatrixXd ParseMatrixMarket(std::string_view text, const std::string& field, const std::string& source,
                                  const MatrixMarketLimits& limits = {});

// The matrix in `file`, refused before it is read if it is larger than limits.max_bytes.
Eigen::MatrixXd ReadMatrixMarket(const std::filesystem::path& file, const std::string& field,
                                 const MatrixMarketLimits& limits = {});

}  // namespace stickslip
