#include "stickslip/model/odeint_options.hpp"

#include <cmath>
#include <utility>

#include "stickslip/invalid_input.hpp"

namespace stickslip {

void OdeintOptions::CheckValid() const {
  for (const auto& [name, value] : {std::pair{"relative_tolerance", relative_tolerance},
                                    std::pair{"absolute_tolerance", absolute_tolerance},
                                    std::pair{"event_time_tolerance", event_time_tolerance}}) {
    if (!(std::isfinite(value) && value > 0.0)) throw InvalidInput(name, value, "finite and > 0");
  }
}

}  // namespace stickslip
