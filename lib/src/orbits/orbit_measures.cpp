#include "stickslip/orbits/orbit_measures.hpp"

namespace stickslip {

OrbitMeasures Measure(const Orbit& orbit) {
  const BasicOrbitMeasures basic = Measure(Pascal2014{}, orbit.OnModel());
  OrbitMeasures m;
  m.amplitude_x1 = basic.coordinates[0].Amplitude();
  m.amplitude_x2 = basic.coordinates[1].Amplitude();
  m.peak_to_peak_x2 = basic.coordinates[1].PeakToPeak();
  m.stick_fraction = basic.stick_fraction;
  m.stops = basic.stops;
  m.sticks = basic.sticks;
  m.friction_work = basic.friction_work;
  m.equivalent_damping = basic.equivalent_damping;
  return m;
}

}  // namespace stickslip
