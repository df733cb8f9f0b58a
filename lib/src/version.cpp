#include "stickslip/version.hpp"

#ifndef STICKSLIP_VERSION
#error "STICKSLIP_VERSION is set by lib/CMakeLists.txt from the project's VERSION"
#endif

namespace stickslip {

const char* Version() { return STICKSLIP_VERSION; }

}  // namespace stickslip
