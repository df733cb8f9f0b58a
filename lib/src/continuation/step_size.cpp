#include "stickslip/continuation/step_size.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {

namespace {

class IterationCountController final : public StepSizeController {
 public:
  explicit IterationCountController(const StepSizeOptions& options) : options_(options) {}
  double Initial() const override { return options_.ds; }
  double OnAccepted(double ds, int iterations) override {
    const double factor =
        iterations <= options_.target_iterations
            ? options_.growth
            : std::max(options_.slowest_shrink, static_cast<double>(options_.target_iterations) / iterations);
    // Never below ds_min after a step that converged: the branch ends there only for a corrector
    // that failed (OnRejected), with its failure.
    return std::clamp(ds * factor, options_.ds_min, options_.ds_max);
  }
  double OnRejected(double ds) override { return options_.rejection_shrink * ds; }

 private:
  StepSizeOptions options_;
};

}  // namespace

void StepSizeOptions::Validate() const {
  if (!(ds > 0.0)) throw InvalidInput("ds", ds, "ds > 0");
  if (!(ds_min > 0.0 && ds_min <= ds)) throw InvalidInput("ds_min", ds_min, fmt::format("0 < ds_min <= ds ({})", ds));
  if (!(ds_max >= ds)) throw InvalidInput("ds_max", ds_max, fmt::format("ds_max >= ds ({})", ds));
  if (!(growth >= 1.0)) throw InvalidInput("growth", growth, "growth >= 1");
  if (target_iterations < 1) throw InvalidInput("target_iterations", target_iterations, "target_iterations >= 1");
  if (!(slowest_shrink > 0.0 && slowest_shrink <= 1.0)) {
    throw InvalidInput("slowest_shrink", slowest_shrink, "0 < slowest_shrink <= 1");
  }
  if (!(rejection_shrink > 0.0 && rejection_shrink < 1.0)) {
    throw InvalidInput("rejection_shrink", rejection_shrink, "0 < rejection_shrink < 1");
  }
}

std::unique_ptr<StepSizeController> StepSizeController::Create(const StepSizeOptions& options) {
  return std::make_unique<IterationCountController>(options);
}

}  // namespace stickslip
