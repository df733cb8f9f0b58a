// A user's own oscillator with the installed library: one mass on a spring and a viscous damper,
// dragged by a belt at speed v_b through Coulomb friction (static 1.5, kinetic 1), no forcing. Its
// stick-slip cycle at v_b = 0.2 (from the undamped closed form, corrected by Newton) is traced in
// the belt's speed; the trace ends where the slip grazes the belt and the family folds. The same
// at a size fixed at compile time and at a size read with the data.
#include <cmath>
#include <cstdio>
#include <numbers>

#include "stickslip/branches/model_trace.hpp"
#include "stickslip/model/linear_oscillator.hpp"

// The trace of the belt model at a size fixed at compile time (LinearOscillator<1>) or read with
// the data (DynamicLinearOscillator: a model from a file, any number of coordinates).
template <typename Model>
void TraceInBeltSpeed(const char* size) {
  stickslip::LinearOscillatorData data;
  data.mass = Eigen::MatrixXd::Constant(1, 1, 1.0);       // M (kg)
  data.stiffness = Eigen::MatrixXd::Constant(1, 1, 1.0);  // K (N/m)
  data.damping = Eigen::MatrixXd::Constant(1, 1, 0.1);    // C (N s/m)
  data.forcing = Eigen::VectorXd::Zero(1);                // g: no forcing, an autonomous orbit
  const double v_b = 0.2, d = 0.5;                        // d = (F_s - F_k)/k
  stickslip::BasicOrbitContinuationSetup<Model> setup{
      .start = {stickslip::Signature::Parse("stick slip-"), {/*omega*/ 1.0, /*F_k*/ 1.0, /*F_s*/ 1.5, v_b},
                typename Model::State(Eigen::Vector2d(0.5, v_b)), 0.0,
                {2.0 * d / v_b, std::numbers::pi + 2.0 * std::atan(v_b / d)}},
      .parameter = "v_b",
      .model = Model(data)};
  setup.options.lambda_min = 0.1;
  setup.options.lambda_max = 2.0;
  const stickslip::BasicTraceResult<Model> trace = stickslip::TraceOrbits(setup);
  const auto& up = trace.up.links.back();
  std::printf("%s: '%s' up to v_b = %.3f: %s\n", size, up.signature.c_str(), up.branch.orbits.back().parameters.v_b,
              stickslip::ToString(trace.up.end));
}

int main() {
  TraceInBeltSpeed<stickslip::LinearOscillator<1>>("fixed size");  // N coordinates: LinearOscillator<N>
  TraceInBeltSpeed<stickslip::DynamicLinearOscillator>("sized at run time");
  return 0;
}
