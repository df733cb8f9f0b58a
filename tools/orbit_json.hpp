// A solved orbit as one JSON object, as solve --json prints it and find --json nests it: the keys
// solve's --help lists, the unknowns by name (with tie_u_r) and whether it is a motion
// (admissible), so that a script reads every field by the name the Python Orbit gives it.
#pragma once

#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/orbit_solver.hpp"
#include "stickslip/orbits/verification.hpp"

namespace stickslip::cli {

// `free`: the unknowns' indices in the full variable vector; non-finite numbers are null.
nlohmann::ordered_json OrbitJson(const OrbitSolution& solution, const std::vector<int>& free, bool tie_static_friction,
                                 const std::vector<Margin>& margins, const Verification& verification);

}  // namespace stickslip::cli
