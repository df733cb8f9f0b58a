// Solves section 5.1's orbit from its printed values with the installed library, as `stickslip solve
// --preset paper-5.1` does, and prints the version, the signature and whether the orbit is a motion.
#include <cstdio>

#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/orbit_solver.hpp"
#include "stickslip/orbits/paper_presets.hpp"
#include "stickslip/version.hpp"

int main() {
  const stickslip::PaperPreset* preset = stickslip::FindPaperPreset("paper-5.1");
  if (preset == nullptr) return 1;
  const stickslip::Orbit guess = preset->Guess();
  const stickslip::OrbitSolution solved =
      stickslip::SolveOrbit(guess, stickslip::FreeIndices(guess.signature, preset->unknowns),
                            preset->unknowns.tie_static_friction);
  if (!solved.summary.Converged()) return 3;
  const stickslip::Margin smallest = stickslip::SmallestMargin(stickslip::AdmissibilityMargins(solved.orbit));
  std::printf("stickslip %s\n%s\n%s\n", stickslip::Version(), solved.orbit.signature.ToString().c_str(),
              smallest.value > 0 ? "admissible" : "not a motion");
  return 0;
}
