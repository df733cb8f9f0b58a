#include "stickslip/orbits/orbit_solver.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

namespace stickslip {

namespace ov = orbit_variables;

const char* ToString(ShootingChoice s) {
  switch (s) {
    case ShootingChoice::kAuto: return "auto";
    case ShootingChoice::kSingle: return "single";
    case ShootingChoice::kMultiple: break;
  }
  return "multiple";
}

FreeVariables ResolveUnknowns(const Signature& signature, const UnknownChoice& choice) {
  const int n = signature.size();
  std::vector<int> free = {ov::kX10, ov::kX20, ov::kV10, ov::kPhi};
  for (int i = 0; i < n; ++i) free.push_back(ov::Duration(i));
  std::string names;
  for (int i = 0; i < ov::Count(n); ++i) names += (i ? ", " : "") + ov::Name(n, i);
  for (const std::string& name : choice.release) {
    const std::optional<int> index = ov::IndexOf(n, name);
    if (!index) return {{}, fmt::format("free = '{}' is not a variable: valid {}", name, names)};
    if (choice.tie_static_friction && *index == ov::Parameter(n, ParameterId::kStaticFriction)) {
      return {{}, "free = 'u_r' is tied to u_s (u_r = u_s): release u_s instead"};
    }
    if (std::find(free.begin(), free.end(), *index) == free.end()) free.push_back(*index);
  }
  for (const std::string& name : choice.fix) {
    const std::optional<int> index = ov::IndexOf(n, name);
    if (!index) return {{}, fmt::format("fix = '{}' is not a variable: valid {}", name, names)};
    std::erase(free, *index);
  }
  const PeriodicityEquations equations(signature, Shooting::kSingle);
  if (static_cast<int>(free.size()) != equations.EquationCount()) {
    std::string unknowns;
    for (int index : free) unknowns += (unknowns.empty() ? "" : ", ") + ov::Name(n, index);
    return {{}, fmt::format("the system is not square: signature '{}' has {} equations but there "
                            "are {} unknowns ({}); release or fix {} variable(s)",
                            signature.ToString(), equations.EquationCount(), free.size(), unknowns,
                            std::abs(static_cast<int>(free.size()) - equations.EquationCount()))};
  }
  return {free, {}};
}

Shooting ResolveShooting(ShootingChoice choice, int listed_segments, int max_single_shooting_segments) {
  const bool multiple = choice == ShootingChoice::kMultiple ||
                        (choice == ShootingChoice::kAuto && listed_segments > max_single_shooting_segments);
  return multiple ? Shooting::kMultiple : Shooting::kSingle;
}

OrbitSolution SolveOrbit(const Orbit& guess, const std::vector<int>& free,
                         bool tie_static_friction, const OrbitSolverOptions& options) {
  const Shooting shooting =
      ResolveShooting(options.shooting, guess.signature.size(), options.max_single_shooting_segments);
  const OrbitSystem system(guess, free, tie_static_friction, shooting);
  if (system.EquationCount() != system.UnknownCount()) {
    throw std::invalid_argument(fmt::format("orbit system is not square: {} equations, {} unknowns",
                                            system.EquationCount(), system.UnknownCount()));
  }
  NewtonOptions newton = options.newton;
  if (shooting == Shooting::kMultiple && newton.linear_solver == LinearSolverType::kDenseLu) {
    newton.linear_solver = options.sparse_solver;
  }
  NewtonResult result = SolveNewton(system, system.Unknowns(guess), newton);
  return {system.ToOrbit(result.solution), std::move(result.summary), shooting};
}

}  // namespace stickslip
