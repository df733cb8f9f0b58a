// A solved orbit as solve and find print it: signature, parameters, unknowns, Newton summary,
// the solution, the admissibility margins, the Floquet multipliers, the orbit's measures
// (amplitudes, peak-to-peak, stick fraction, stops and sticks) and the verification; and
// the exit code it earns (SolvedOrbitExitCode), with the reason on stderr.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/orbit_solver.hpp"
#include "stickslip/orbits/verification.hpp"

namespace stickslip::cli {

// `free`: the unknowns' indices in the full variable vector; `linear_solver`: the sparse solver's
// name, printed for multiple shooting.
std::string OrbitReport(const OrbitSolution& solution, const std::vector<int>& free, bool tie_static_friction,
                        std::string_view linear_solver, const std::vector<Margin>& margins,
                        const Verification& verification);

// SolvedOrbitExitCode of the smallest margin and the verification, with the reason on stderr, so
// that scripts need not parse the output.
int SolvedOrbitOutcome(const std::vector<Margin>& margins, const Verification& verification);

}  // namespace stickslip::cli
