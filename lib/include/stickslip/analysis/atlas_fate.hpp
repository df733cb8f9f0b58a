// What became of a brute-force attractor in an atlas (atlas.hpp, model_atlas.hpp): on a traced
// branch, or why on none.
#pragma once

namespace stickslip {

// What became of one brute-force attractor.
enum class AttractorFate {
  kOnBranch,     // its exact orbit lies on a traced branch (branch, point)
  kNotSettled,   // no period on the section, even after FindOrbit's longer transients
  kAboveLimit,   // periodic with a period above max_multiple
  kIncomplete,   // a simulation stopped early (chattering, the event search's bound)
  kNoOrbitType,  // periodic, but no orbit type describes it (a permanent stick: no segment end)
  kNotSolved,    // FindOrbit gave no exact orbit: its status and message say why
  kOffBranch,    // solved, but on no branch, not even the one traced from it (the reason says why)
};
const char* ToString(AttractorFate fate);  // "on-branch", "not-settled", ...

}  // namespace stickslip
