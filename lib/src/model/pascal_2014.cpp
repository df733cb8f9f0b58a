#include "stickslip/model/pascal_2014.hpp"

#include <string>

namespace stickslip {

namespace {

ModelDescription Pascal2014Description() {
  auto parameter = [](const char* name, const char* meaning, double minimum, double maximum,
                      std::string_view range) {
    return ParameterDescription{name, meaning, "1", minimum, maximum, std::string(range)};
  };
  // Eq. (3): every quantity scaled, so every unit is 1. u_r's lower bound is u_s (eq. 4), checked
  // by Validate; its range alone is that of u_s.
  return ModelDescription{
      "pascal-2014",
      {parameter("chi", "stiffness ratio k2/(k1+k2)", kMinChi, kMaxChi, kChiRange),
       parameter("eta", "mass ratio m1/m2", kMinEta, kMaxEta, kEtaRange),
       parameter("omega", "forcing frequency (scaled time)", kMinOmega, kMaxOmega, kOmegaRange),
       parameter("u_s", "sliding friction level", kMinSlidingFriction, kMaxFriction, kSlidingFrictionRange),
       parameter("u_r", "static friction level", kMinSlidingFriction, kMaxFriction, kStaticFrictionRange)},
      {"x1", "x2"},
      {"x1", "x2", "x1'", "x2'"},
      {"x1", "x2", "v1", "v2"},
      {"x10", "x20", "v10", "v20"}};
}

}  // namespace

const ModelDescription& Pascal2014::Description() const {
  static const ModelDescription description = Pascal2014Description();
  return description;
}

}  // namespace stickslip
