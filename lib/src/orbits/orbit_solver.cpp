#include "stickslip/orbits/orbit_solver.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "stickslip/orbits/model_orbit_solver.hpp"

namespace stickslip {

const char* ToString(ShootingChoice s) {
  switch (s) {
    case ShootingChoice::kAuto: return "auto";
    case ShootingChoice::kSingle: return "single";
    case ShootingChoice::kMultiple: break;
  }
  return "multiple";
}

OrbitVariableSet VariableSetOf(const Signature& signature) { return VariableSetOf(Pascal2014{}, signature); }

int VariableIndex(const OrbitLayout& layout, std::string_view field, std::string_view name) {
  if (const std::optional<int> index = layout.IndexOf(name)) return *index;
  std::vector<std::string> names;
  for (int i = 0; i < layout.Count(); ++i) names.push_back(layout.Name(i));
  throw InvalidInput::WithMessage(std::string(field), fmt::format("{} = '{}' is not a variable: valid {}", field,
                                                                  name, fmt::join(names, ", ")));
}

int VariableIndex(int n, std::string_view field, std::string_view name) {
  return VariableIndex(OrbitLayout(Pascal2014{}.Description(), n), field, name);
}

UnknownChoice UnknownsAtFixedParameters(const OrbitVariableSet& variables) {
  const Signature& signature = variables.signature;
  for (int i = 0; i < signature.size(); ++i) {
    if (signature.EndKind(i) == SegmentEndKind::kAbnormalStop) {
      return {{variables.layout.Name(variables.kinetic_level)}, {}, true};
    }
  }
  return {};
}

UnknownChoice UnknownsAtFixedParameters(const Signature& signature) {
  return UnknownsAtFixedParameters(VariableSetOf(signature));
}

std::vector<int> FreeIndices(const OrbitVariableSet& variables, const UnknownChoice& choice) {
  const OrbitLayout& layout = variables.layout;
  const std::string kinetic = layout.Name(variables.kinetic_level), static_level = layout.Name(variables.static_level);
  std::vector<int> free;
  for (int index = 0; index < layout.Parameter(0); ++index) free.push_back(index);
  for (const std::string& name : choice.release) {
    const int index = VariableIndex(variables.layout, "free", name);
    if (choice.tie_static_friction && index == variables.static_level) {
      throw InvalidInput::WithMessage("free", fmt::format("free = '{0}' is tied to {1} ({0} = {1}): release {1} instead",
                                                          static_level, kinetic));
    }
    if (index < layout.Parameter(0)) {
      std::vector<std::string> always;
      for (int k = 0; k <= layout.Phi(); ++k) always.push_back(layout.Name(k));
      throw InvalidInput::WithMessage("free", fmt::format("free = '{}' is an unknown already: {} and the durations "
                                                          "always are (free releases a parameter)",
                                                          name, fmt::join(always, ", ")));
    }
    if (std::find(free.begin(), free.end(), index) == free.end()) free.push_back(index);
  }
  for (const std::string& name : choice.fix) std::erase(free, VariableIndex(variables.layout, "fix", name));
  const int equation_count = variables.equations + choice.condition_equations;
  if (static_cast<int>(free.size()) != equation_count) {
    std::string unknowns;
    for (int index : free) unknowns += (unknowns.empty() ? "" : ", ") + layout.Name(index);
    throw InvalidInput::WithMessage(
        "unknowns", fmt::format("the system is not square: signature '{}' has {} equations but there "
                                "are {} unknowns ({}); release or fix {} variable(s)",
                                variables.signature.ToString(), equation_count, free.size(), unknowns,
                                std::abs(static_cast<int>(free.size()) - equation_count)));
  }
  return free;
}

std::vector<int> FreeIndices(const Signature& signature, const UnknownChoice& choice) {
  return FreeIndices(VariableSetOf(signature), choice);
}

int ContinuedVariable(const OrbitVariableSet& variables, const std::vector<int>& free, bool tie_static_friction,
                      std::string_view parameter) {
  const int index = VariableIndex(variables.layout, "parameter", parameter);
  if (tie_static_friction && index == variables.static_level) {
    throw InvalidInput::WithMessage("parameter", fmt::format("parameter = '{0}' is tied to {1} (tie_{0}): continue in {1}",
                                                             variables.layout.Name(variables.static_level),
                                                             variables.layout.Name(variables.kinetic_level)));
  }
  if (std::find(free.begin(), free.end(), index) != free.end()) {
    throw InvalidInput::WithMessage(
        "parameter", fmt::format("parameter = '{}' is an unknown already: continue in a held variable", parameter));
  }
  return index;
}

int ContinuedVariable(const Signature& signature, const std::vector<int>& free, bool tie_static_friction,
                      std::string_view parameter) {
  return ContinuedVariable(VariableSetOf(signature), free, tie_static_friction, parameter);
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

template OrbitSolution SolveOrbit<Pascal2014>(const Pascal2014& model, const Orbit& guess,
                                              const std::vector<int>& free, bool tie_static_friction,
                                              const OrbitSolverOptions& options);

OrbitSolution SolveOrbit(const Orbit& guess, const std::vector<int>& free,
                         bool tie_static_friction, const OrbitSolverOptions& options) {
  return SolveOrbit<Pascal2014>(Pascal2014{}, guess, free, tie_static_friction, options);
}

}  // namespace stickslip
