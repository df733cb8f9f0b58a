#include "stickslip/orbits/orbit.hpp"

#include "stickslip/orbits/any_orbit.hpp"

#include <cmath>
#include <numbers>

#include "stickslip/orbits/orbit_layout.hpp"
#include "stickslip/orbits/segment_walk.hpp"

namespace stickslip {

double Orbit::Period() const {
  return signature.period_multiple() * 2.0 * std::numbers::pi / parameters.omega;
}

std::vector<double> Orbit::SegmentTimes() const {
  std::vector<double> times = {0.0};
  for (double d : durations) times.push_back(times.back() + d);
  return times;
}

std::vector<State> Orbit::SegmentStates() const {
  std::vector<State> states = {InitialState()};
  WalkSegments(*this, Extent::kListed, PhaseRule::kAccumulated,
               [&](const SegmentVisit<double>& s) { states.push_back(s.end); });
  return states;
}

std::vector<State> Orbit::Sample(int count) const { return SampleOrbit(Pascal2014{}, OnModel(), count); }

double PhaseInCycle(double phase) {
  double reduced = std::fmod(phase, 2.0 * std::numbers::pi);
  if (reduced < 0.0) reduced += 2.0 * std::numbers::pi;
  return reduced;
}

namespace orbit_variables {

std::string Name(int n, int index) { return OrbitLayout(Pascal2014{}.Description(), n).Name(index); }

std::optional<int> IndexOf(int n, std::string_view name) {
  return OrbitLayout(Pascal2014{}.Description(), n).IndexOf(name);
}

Eigen::VectorXd Pack(const Orbit& orbit) {
  const int n = orbit.signature.size();
  Eigen::VectorXd v(Count(n));
  v(kX10) = orbit.x10;
  v(kX20) = orbit.x20;
  v(kV10) = orbit.v10;
  v(kPhi) = orbit.phi;
  for (int i = 0; i < n; ++i) v(Duration(i)) = orbit.durations[i];
  for (ParameterId id : kAllParameters) v(Parameter(n, id)) = orbit.parameters[id];
  return v;
}

Orbit Unpack(const Signature& signature, const Eigen::VectorXd& v) {
  const int n = signature.size();
  Orbit orbit{signature, {}, v(kX10), v(kX20), v(kV10), v(kPhi), {}};
  for (int i = 0; i < n; ++i) orbit.durations.push_back(v(Duration(i)));
  for (ParameterId id : kAllParameters) orbit.parameters[id] = v(Parameter(n, id));
  return orbit;
}

}  // namespace orbit_variables

}  // namespace stickslip
