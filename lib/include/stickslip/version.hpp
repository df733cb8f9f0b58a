// The version of stickslip: the project's VERSION in the top-level CMakeLists.txt, the one source
// of `stickslip --version`, `stickslip.__version__` and the stickslip_version of the result files.
#pragma once

namespace stickslip {

// "0.1.0"
const char* Version();

}  // namespace stickslip
