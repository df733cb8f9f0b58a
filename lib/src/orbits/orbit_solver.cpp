#include "stickslip/orbits/orbit_solver.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

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

int VariableIndex(int n, std::string_view field, std::string_view name) {
  if (const std::optional<int> index = ov::IndexOf(n, name)) return *index;
  std::vector<std::string> names;
  for (int i = 0; i < ov::Count(n); ++i) names.push_back(ov::Name(n, i));
  throw InvalidInput::WithMessage(std::string(field), fmt::format("{} = '{}' is not a variable: valid {}", field,
                                                                  name, fmt::join(names, ", ")));
}

UnknownChoice UnknownsAtFixedParameters(const Signature& signature) {
  for (int i = 0; i < signature.size(); ++i) {
    if (signature.EndKind(i) == SegmentEndKind::kAbnormalStop) {
      const int n = signature.size();
      return {{ov::Name(n, ov::KineticLevel(n))}, {}, true};
    }
  }
  return {};
}

std::vector<int> FreeIndices(const Signature& signature, const UnknownChoice& choice) {
  const int n = signature.size();
  std::vector<int> free = {ov::kX10, ov::kX20, ov::kV10, ov::kPhi};
  for (int i = 0; i < n; ++i) free.push_back(ov::Duration(i));
  for (const std::string& name : choice.release) {
    const int index = VariableIndex(n, "free", name);
    if (choice.tie_static_friction && index == ov::StaticLevel(n)) {
      throw InvalidInput::WithMessage("free", "free = 'u_r' is tied to u_s (u_r = u_s): release u_s instead");
    }
    if (index < ov::FirstParameter(n)) {
      throw InvalidInput::WithMessage("free", fmt::format("free = '{}' is an unknown already: x10, x20, v10, phi and "
                                                          "the durations always are (free releases a parameter)", name));
    }
    if (std::find(free.begin(), free.end(), index) == free.end()) free.push_back(index);
  }
  for (const std::string& name : choice.fix) std::erase(free, VariableIndex(n, "fix", name));
  const PeriodicityEquations equations(signature, Shooting::kSingle);
  const int equation_count = equations.EquationCount() + choice.condition_equations;
  if (static_cast<int>(free.size()) != equation_count) {
    std::string unknowns;
    for (int index : free) unknowns += (unknowns.empty() ? "" : ", ") + ov::Name(n, index);
    throw InvalidInput::WithMessage(
        "unknowns", fmt::format("the system is not square: signature '{}' has {} equations but there "
                                "are {} unknowns ({}); release or fix {} variable(s)",
                                signature.ToString(), equation_count, free.size(), unknowns,
                                std::abs(static_cast<int>(free.size()) - equation_count)));
  }
  return free;
}

int ContinuedVariable(const Signature& signature, const std::vector<int>& free, bool tie_static_friction,
                      std::string_view parameter) {
  const int n = signature.size();
  const int index = VariableIndex(n, "parameter", parameter);
  if (tie_static_friction && index == ov::StaticLevel(n)) {
    throw InvalidInput::WithMessage("parameter", "parameter = 'u_r' is tied to u_s (tie_u_r): continue in u_s");
  }
  if (std::find(free.begin(), free.end(), index) != free.end()) {
    throw InvalidInput::WithMessage(
        "parameter", fmt::format("parameter = '{}' is an unknown already: continue in a held variable", parameter));
  }
  return index;
}

std::optional<ShootingChoice> ShootingChoiceFromString(std::string_view text) {
  for (ShootingChoice s : {ShootingChoice::kAuto, ShootingChoice::kSingle, ShootingChoice::kMultiple}) {
    if (text == ToString(s)) return s;
  }
  return std::nullopt;
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
    throw InvalidInput("free", fmt::format("{} unknowns", system.UnknownCount()),
                       fmt::format("{} unknowns, as many as the equations", system.EquationCount()));
  }
  NewtonOptions newton = options.newton;
  if (shooting == Shooting::kMultiple && newton.linear_solver == LinearSolverType::kDenseLu) {
    newton.linear_solver = options.sparse_solver;
  }
  NewtonResult result = SolveNewton(system, system.Unknowns(guess), newton);
  return {system.ToOrbit(result.solution), std::move(result.summary), shooting};
}

}  // namespace stickslip
