// A periodic orbit of a given signature, and the layout of its variables.
//
// Variables (in this order, "full variable vector"): x10, x20, v10 (x2'0 = 0 because the time
// origin is a stop), phi, the segment durations d1..dn of the listed segments, and the
// parameters chi, eta, omega, u_s, u_r. Which of them are unknowns is the solver's choice.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "stickslip/model/pascal_2014/flows.hpp"
#include "stickslip/model/pascal_2014/parameters.hpp"
#include "stickslip/model/pascal_2014.hpp"
#include "stickslip/orbits/signature.hpp"

namespace stickslip {

// A periodic orbit of any model (model/oscillator_model.hpp): its signature, parameters, the
// state at the time origin (a stop: the contact at rest), the forcing phase there and the
// durations of the listed segments.
template <typename Model>
struct BasicOrbit {
  Signature signature;
  typename Model::Parameters parameters;
  typename Model::State start;
  double phi = 0.0;
  std::vector<double> durations;  // one per listed segment
};

struct Orbit {
  Signature signature;
  Parameters parameters;
  double x10 = 0.0;
  double x20 = 0.0;
  double v10 = 0.0;
  double phi = 0.0;
  std::vector<double> durations;  // one per listed segment

  State InitialState() const { return State(x10, x20, v10, 0.0); }
  BasicOrbit<Pascal2014> OnModel() const { return {signature, parameters, InitialState(), phi, durations}; }
  // k 2 pi/omega: the time after which the orbit repeats.
  double Period() const;
  // Start times of the listed segments, and the end of the last one (n + 1 values).
  std::vector<double> SegmentTimes() const;
  // Start state of each listed segment and the state at the end of the last one (n + 1), by the
  // closed-form flows.
  std::vector<State> SegmentStates() const;
  // The state at `count` >= 2 equally spaced times over one whole period (the listed segments,
  // then their mirror images for an antisymmetric orbit), from the closed-form flows of the
  // orbit's own segments: it follows the orbit even where it is not a motion of the system.
  std::vector<State> Sample(int count) const;
};

// The orbit the layers above take of a model: the paper's model's Orbit, any other model's BasicOrbit.
template <typename Model>
using OrbitOfModel = std::conditional_t<std::is_same_v<Model, Pascal2014>, Orbit, BasicOrbit<Model>>;

// A forcing phase reduced to [0, 2 pi).
double PhaseInCycle(double phase);

// Index arithmetic on the full variable vector of an n-segment signature.
namespace orbit_variables {
inline constexpr int kX10 = 0;
inline constexpr int kX20 = 1;
inline constexpr int kV10 = 2;
inline constexpr int kPhi = 3;
inline int Duration(int i) { return 4 + i; }  // i = 0..n-1
inline int FirstParameter(int n) { return 4 + n; }
inline int Parameter(int n, ParameterId id) { return FirstParameter(n) + static_cast<int>(id); }
// The kinetic and static friction levels, as the model's interface names them (u_s and u_r).
inline int KineticLevel(int n) { return FirstParameter(n) + Pascal2014::kKineticLevelParameter; }
inline int StaticLevel(int n) { return FirstParameter(n) + Pascal2014::kStaticLevelParameter; }
inline int Count(int n) { return 4 + n + kParameterCount; }
// The names of OrbitLayout (orbit_layout.hpp) for the paper's model: x10, x20, v10, phi, d1..dn,
// chi, eta, omega, u_s, u_r.
std::string Name(int n, int index);
std::optional<int> IndexOf(int n, std::string_view name);
Eigen::VectorXd Pack(const Orbit& orbit);
Orbit Unpack(const Signature& signature, const Eigen::VectorXd& variables);
}  // namespace orbit_variables

}  // namespace stickslip
