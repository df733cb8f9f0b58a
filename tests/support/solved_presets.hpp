// A paper orbit solved by Newton from its printed values, with the preset's choice of unknowns
// (or the paper's own, where a round printed value looks held fixed).
#pragma once

#include "stickslip/orbits/orbit_solver.hpp"
#include "stickslip/orbits/paper_presets.hpp"

namespace stickslip {

inline Orbit SolvedPreset(const char* name, bool paper_choice = false) {
  const PaperPreset& preset = *FindPaperPreset(name);
  const UnknownChoice& choice = paper_choice ? preset.paper_choice : preset.unknowns;
  const Orbit guess = preset.Guess();
  return SolveOrbit(guess, FreeIndices(guess.signature, choice), choice.tie_static_friction).orbit;
}

}  // namespace stickslip
