// A continuation (or trace) of any model in the forcing frequency omega, from `start`, with the
// library's defaults but the range [low, high] in the scaled frequency and max_points; `scale`
// is the model's unit of frequency (support/pascal_in_physical_units.hpp's Omega, 1 for the
// paper's scaled model), so that the same scaled range is asked of both models.
#pragma once

#include <utility>

#include "stickslip/branches/orbit_continuation.hpp"

namespace stickslip {

template <OscillatorModel Model>
BasicOrbitContinuationSetup<Model> OmegaSetup(OrbitOfModel<Model> start, Model model, double low, double high,
                                              double scale, int max_points) {
  BasicOrbitContinuationSetup<Model> setup{std::move(start), {}, "omega", ShootingChoice::kAuto, LinearSolverType::kKlu,
                                           {}, {}, {}, {}, kDefaultMaxAmplitude, kDefaultResonanceApproach,
                                           std::move(model)};
  setup.options.lambda_min = low * scale;
  setup.options.lambda_max = high * scale;
  setup.options.max_points = max_points;
  return setup;
}

}  // namespace stickslip
