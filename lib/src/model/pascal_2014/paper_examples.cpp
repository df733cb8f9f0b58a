#include "stickslip/model/pascal_2014/paper_examples.hpp"

#include <array>
#include <numbers>

#include <fmt/format.h>

namespace stickslip {

namespace {

constexpr double kOmegaEleven = 2.0 * std::numbers::pi / 11.0;  // "omega = 2 pi / 11"

State Start(double x10, double x20, double v10) {
  State x;
  x << x10, x20, v10, 0.0;
  return x;
}

const std::array<PaperExample, 5>& Examples() {
  // Parameters are {chi, eta, omega, u_s, u_r}.
  static const std::array<PaperExample, 5> examples = {{
      {"paper-4.1", "section 4.1", "nonsticking orbit with two stops per period",
       {0.3, 4.0, 0.6, 0.1, 0.2996}, Start(1.5608, 3.3295, 0.1523), 0.3925},
      {"paper-4.2", "eq. (29)", "nonsticking orbit with abnormal stops (u_s = u_r)",
       {0.7, 3.8, kOmegaEleven, 0.1717, 0.1717}, Start(2.1249, 2.0451, -0.7267), 2.6455},
      {"paper-5.1", "eq. (36)", "sticking orbit with one stop per period",
       {0.22, 4.2, kOmegaEleven, 0.0138, 0.4962}, Start(-0.3643, 4.1887, -0.2578), 0.3177},
      {"paper-5.2", "eq. (40)", "another sticking orbit with one stop per period",
       {0.35, 4.0, 0.66, 0.1, 0.4701}, Start(0.8432, 2.1864, -2.1511), 1.5708},
      {"paper-6", "eq. (54)", "symmetric orbit with two stops and two sticks per period",
       {0.7, 3.8, kOmegaEleven, 0.06, 1.4041}, Start(2.8901, 5.1306, -0.8108), 3.0},
  }};
  return examples;
}

}  // namespace

std::span<const PaperExample> PaperExamples() { return Examples(); }

const PaperExample* FindPaperExample(std::string_view name) {
  for (const PaperExample& e : Examples()) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

std::string PaperExampleNames() {
  std::string names;
  for (const PaperExample& e : Examples()) names += fmt::format("{}{}", names.empty() ? "" : ", ", e.name);
  return names;
}

}  // namespace stickslip
