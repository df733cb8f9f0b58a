// The paper's five orbits as solver presets: data and printed values (model/pascal_2014/paper_examples.hpp),
// the orbit signature, the printed durations as starting guess, the default choice of unknowns,
// and every printed number with its name in stickslip's variables, for comparison.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "stickslip/model/pascal_2014/paper_examples.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/orbit_solver.hpp"

namespace stickslip {

// A number as the paper prints it (the text keeps its digits) and the stickslip quantity it is:
// a variable name, or "T" (a stick duration the paper derives), or "Theta" (the period).
struct PrintedValue {
  std::string_view paper_name;  // "tau1", "x'10", ...
  std::string_view variable;    // "d2", "v10", "period", ...
  std::string_view text;        // "2.0000"
};

struct PaperPreset {
  const PaperExample* example = nullptr;
  std::string_view signature;
  std::vector<double> durations;  // printed durations of the listed segments (starting guess)
  UnknownChoice unknowns;          // the default: the paper's data held, state, phi, d solved
  std::vector<PrintedValue> printed;
  // The paper's own choice where a round printed value looks held fixed (ERRATA, issue 3).
  UnknownChoice paper_choice;
  std::string_view paper_choice_note;

  Orbit Guess() const;  // the printed values as an orbit
};

// The value in `orbit` of a printed quantity's variable ("period", "half-period", or any orbit
// variable name).
double PrintedQuantity(const Orbit& orbit, std::string_view variable);

std::span<const PaperPreset> PaperPresets();
const PaperPreset* FindPaperPreset(std::string_view name);

}  // namespace stickslip
