// Solving for a periodic orbit: the choice of unknowns (which variables are free, which fixed)
// and Newton's method on the periodicity equations in single or multiple shooting.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "stickslip/numerics/newton.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/orbit_layout.hpp"
#include "stickslip/orbits/periodicity.hpp"

namespace stickslip {

// Which variables of the full vector are unknowns. By default x10, x20, v10, phi and every
// duration; `release` adds parameters (or any variable), `fix` removes variables.
struct UnknownChoice {
  std::vector<std::string> release;  // variable names, e.g. "u_r"
  std::vector<std::string> fix;      // variable names, e.g. "phi", "d2"
  bool tie_static_friction = false;  // u_r follows u_s (u_r = u_s); u_r may not be released
  // Equations beside the periodicity equations, beyond their own unknowns: a curve's condition's
  // (OrbitContinuationSetup::condition), which a second released parameter pays for.
  int condition_equations = 0;
};

// The variables of an orbit of any model, by name (orbit_layout.hpp), with its friction levels'
// places and its periodicity equations' count: what a choice of unknowns is checked against.
struct OrbitVariableSet {
  Signature signature;
  OrbitLayout layout;
  int kinetic_level = 0;  // indices in the full variable vector
  int static_level = 0;
  int equations = 0;  // the periodicity equations' count in single shooting
};
template <OscillatorModel Model>
OrbitVariableSet VariableSetOf(const Model& model, const Signature& signature) {
  const OrbitLayout layout(model.Description(), signature.size());
  return {signature, layout, layout.Parameter(Model::kKineticLevelParameter),
          layout.Parameter(Model::kStaticLevelParameter),
          BasicPeriodicityEquations<Model>(model, signature, Shooting::kSingle).EquationCount()};
}
OrbitVariableSet VariableSetOf(const Signature& signature);  // the paper's model

// The index of the variable `name` of an orbit. Throws InvalidInput
// "<field> = '<name>' is not a variable: valid x10, x20, ..." naming the caller's field.
int VariableIndex(const OrbitLayout& layout, std::string_view field, std::string_view name);
int VariableIndex(int n, std::string_view field, std::string_view name);  // the paper's model, n segments

// The unknowns an orbit's equations are square in at fixed parameters: the start state, the phase
// and the durations; with an abnormal stop the kinetic level released and the static level tied to
// it (u_s free, u_r = u_s: eq. 25).
UnknownChoice UnknownsAtFixedParameters(const OrbitVariableSet& variables);
UnknownChoice UnknownsAtFixedParameters(const Signature& signature);  // the paper's model

// The free variable indices of a choice for a signature. Throws InvalidInput naming "free" or
// "fix" for a name that is not a variable (or u_r released while tied to u_s), and "unknowns",
// with both counts, when the system would not be square.
std::vector<int> FreeIndices(const OrbitVariableSet& variables, const UnknownChoice& choice);
std::vector<int> FreeIndices(const Signature& signature, const UnknownChoice& choice);  // the paper's model

// The index of the continued variable `parameter` (a variable name): one that is held, not in
// `free`, and not u_r while it is tied to u_s. Throws InvalidInput naming "parameter".
int ContinuedVariable(const OrbitVariableSet& variables, const std::vector<int>& free, bool tie_static_friction,
                      std::string_view parameter);
int ContinuedVariable(const Signature& signature, const std::vector<int>& free, bool tie_static_friction,
                      std::string_view parameter);  // the paper's model

enum class ShootingChoice { kAuto, kSingle, kMultiple };
const char* ToString(ShootingChoice s);  // "auto", "single", "multiple"
std::optional<ShootingChoice> ShootingChoiceFromString(std::string_view text);

// kAuto picks single shooting up to max_single_shooting_segments listed segments, multiple
// shooting beyond (where long products of flow Jacobians lose accuracy).
inline constexpr int kMaxSingleShootingSegments = 6;
Shooting ResolveShooting(ShootingChoice choice, int listed_segments,
                         int max_single_shooting_segments = kMaxSingleShootingSegments);

struct OrbitSolverOptions {
  ShootingChoice shooting = ShootingChoice::kAuto;  // see ResolveShooting
  int max_single_shooting_segments = kMaxSingleShootingSegments;
  LinearSolverType sparse_solver = LinearSolverType::kKlu;  // for multiple shooting
  NewtonOptions newton;
};

template <typename Model>
struct BasicOrbitSolution {
  OrbitOfModel<Model> orbit;  // the last Newton iterate: the orbit when summary.Converged()
  NewtonSummary summary;
  Shooting shooting = Shooting::kSingle;
  // > 0 where the orbit is not isolated: one of a family of orbits of this dimension at its
  // parameters (the periodicity equations' Jacobian that rank-deficient along it), found where
  // Newton met a singular Jacobian by minimum-norm steps (numerics/minimum_norm_newton.hpp): the
  // family's member nearest the guess. Only a family at fixed parameters (its null space moves no
  // released parameter, and a step along it is corrected to another orbit); otherwise Newton's
  // failure stands. The summary's message says so; solve's report and --json show it.
  int family_dimension = 0;
};
using OrbitSolution = BasicOrbitSolution<Pascal2014>;

// Throws InvalidInput naming "free" if `free` does not make the system square. The paper's model;
// any model's in model_orbit_solver.hpp.
OrbitSolution SolveOrbit(const Orbit& guess, const std::vector<int>& free,
                         bool tie_static_friction, const OrbitSolverOptions& options = {});

}  // namespace stickslip
