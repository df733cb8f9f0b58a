#include "stickslip/numerics/zero_search.hpp"

namespace stickslip {

const char* ToString(ZeroSearchStatus status) {
  // In enum order.
  constexpr const char* kNames[] = {"complete", "too many sub-intervals", "not finite", "not bounded"};
  return kNames[static_cast<int>(status)];
}

}  // namespace stickslip
