#include "stickslip/continuation/step_size.hpp"

#include <algorithm>

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
            : std::max(0.5, static_cast<double>(options_.target_iterations) / iterations);
    return std::min(ds * factor, options_.ds_max);
  }
  double OnRejected(double ds) override { return 0.5 * ds; }

 private:
  StepSizeOptions options_;
};

}  // namespace

std::unique_ptr<StepSizeController> StepSizeController::Create(const StepSizeOptions& options) {
  return std::make_unique<IterationCountController>(options);
}

}  // namespace stickslip
