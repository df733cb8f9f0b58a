// The numerical examples printed in Pascal 2014 (sections 4.1, 4.2, 5.1, 5.2, 6): their data
// and initial states exactly as printed. The printed numbers are rounded to 4-5 digits and
// partly inconsistent (shared/paper/ERRATA.md); they are starting points, not exact orbits.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "stickslip/model/pascal_2014/flows.hpp"
#include "stickslip/model/pascal_2014/parameters.hpp"

namespace stickslip {

struct PaperExample {
  std::string_view name;      // preset name: "paper-4.1", ...
  std::string_view equation;  // where the paper prints the values, e.g. "eq. (36)"
  std::string_view title;
  Parameters parameters;
  State initial_state;  // (x10, x20, x1'0, x2'0); every example starts at a stop, x2'0 = 0
  double phi = 0.0;
};

std::span<const PaperExample> PaperExamples();
// nullptr if there is no example of that name.
const PaperExample* FindPaperExample(std::string_view name);
// "paper-4.1, paper-4.2, ...": the names, for messages and help texts (the solver presets of
// orbits/paper_presets.hpp have the same names).
std::string PaperExampleNames();

}  // namespace stickslip
