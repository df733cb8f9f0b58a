// libFuzzer target: the Matrix Market reader (io/matrix_market.hpp) turns any text into a matrix
// within the limits, with finite entries (symmetric where the banner says so), or InvalidInput;
// never a crash, an abort or another exception. tests/io/matrix_market_test.cpp checks seeded files.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/matrix_market.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  stickslip::MatrixMarketLimits limits;
  limits.max_dimension = 64;
  try {
    const Eigen::MatrixXd m = stickslip::ParseMatrixMarket(text, "stiffness", "fuzz", limits);
    if (m.rows() < 1 || m.cols() < 1 || m.rows() > 64 || m.cols() > 64 || !m.allFinite()) std::abort();
    if (text.substr(0, text.find('\n')).find("symmetric") != std::string_view::npos && !(m == m.transpose())) std::abort();
  } catch (const stickslip::InvalidInput&) {
  }
  return 0;
}
