#include "stickslip/orbits/paper_presets.hpp"

#include <numbers>
#include <stdexcept>
#include <string>

namespace stickslip {

Orbit PaperPreset::Guess() const {
  const State& x = example->initial_state;
  return Orbit{Signature::Parse(signature), example->parameters, x(0), x(1), x(2), example->phi, durations};
}

namespace {

constexpr double kHalfPeriod41 = std::numbers::pi / 0.6;

const std::vector<PaperPreset>& Presets() {
  static const std::vector<PaperPreset> presets = {
      {FindPaperExample("paper-4.1"),
       "slip- / antisymmetric",
       {kHalfPeriod41},
       {},
       {{"Theta", "period", "10.472"},
        {"x10", "x10", "1.5608"},
        {"x20", "x20", "3.3295"},
        {"x'10", "v10", "0.1523"},
        {"phi", "phi", "0.3925"}},
       {},
       "all printed data held; no round value looks fixed"},
      {FindPaperExample("paper-4.2"),
       "slip- slip- / antisymmetric",
       {4.0, 1.5},
       {{"u_s"}, {}, true},
       {{"tau", "half-period", "5.5"},
        {"tau1", "d1", "4"},
        {"phi", "phi", "2.6455"},
        {"u_s = u_r", "u_s", "0.1717"},
        {"x10", "x10", "2.1249"},
        {"x20", "x20", "2.0451"},
        {"x'10", "v10", "-0.7267"}},
       {{"u_s"}, {}, true},
       "u_s = u_r solved as the paper does; no round value fits better: holding tau1 = 4 and "
       "releasing chi, eta or omega moves the other printed values by 0.2 to 2"},
      {FindPaperExample("paper-5.1"),
       "slip- slip+ stick slip+",
       {3.2663, 2.0, 2.7337, 3.0},
       {},
       {{"tau", "d1", "3.2663"},
        {"tau1", "d2", "2"},
        {"T", "d3", "2.7337"},
        {"tau2", "d4", "3"},
        {"phi", "phi", "0.3177"},
        {"x10", "x10", "-0.3643"},
        {"x20", "x20", "4.1887"},
        {"x'10", "v10", "-0.2578"}},
       {{"u_r", "u_s"}, {"d2", "d4"}, false},
       "tau1 = 2 and tau2 = 3 held, u_r and u_s released"},
      {FindPaperExample("paper-5.2"),
       "slip- slip+ stick",
       {3.18, 3.58, 2.76},
       {},
       {{"tau", "d1", "3.18"},
        {"tau1", "d2", "3.58"},
        {"T", "d3", "2.76"},
        {"phi", "phi", "1.5708"},
        {"x10", "x10", "0.8432"},
        {"x20", "x20", "2.1864"},
        {"x'10", "v10", "-2.1511"}},
       {{"u_r"}, {"phi"}, false},
       "phi = pi/2 held, u_r released"},
      {FindPaperExample("paper-6"),
       "slip- stick slip- / antisymmetric",
       {2.175, 1.56, 1.765},
       {},
       {{"tau1", "d1", "2.175"},
        {"T", "d2", "1.56"},
        {"tau2", "d3", "1.765"},
        {"phi", "phi", "3"},
        {"x10", "x10", "2.8901"},
        {"x20", "x20", "5.1306"},
        {"x'10", "v10", "-0.8108"}},
       {{"u_r"}, {"phi"}, false},
       "phi = 3 held, u_r released"},
  };
  return presets;
}

}  // namespace

double PrintedQuantity(const Orbit& orbit, std::string_view variable) {
  if (variable == "period") return orbit.Period();
  if (variable == "half-period") return 0.5 * orbit.Period();
  const std::optional<int> index = orbit_variables::IndexOf(orbit.signature.size(), variable);
  if (!index) throw std::invalid_argument(std::string("no orbit variable ") + std::string(variable));
  return orbit_variables::Pack(orbit)(*index);
}

std::span<const PaperPreset> PaperPresets() { return Presets(); }

const PaperPreset* FindPaperPreset(std::string_view name) {
  for (const PaperPreset& p : Presets()) {
    if (p.example->name == name) return &p;
  }
  return nullptr;
}

}  // namespace stickslip
