// Step-size policies for pseudo-arclength continuation: a small strategy interface, as LOCA's
// StepSize and Ceres' trust-region strategies are.
#pragma once

#include <memory>

namespace stickslip {

struct StepSizeOptions {
  double ds = 0.01;       // initial arclength step, > 0
  double ds_min = 1e-8;   // the branch ends when a step would have to be smaller
  double ds_max = 0.05;   // steps never grow beyond this
  double growth = 1.5;    // largest growth factor after a fast corrector
  int target_iterations = 3;  // corrector iterations regarded as "fast"
  double slowest_shrink = 0.5;  // smallest factor after a slow (but converged) corrector
  double rejection_shrink = 0.5;  // factor on the step after a failed corrector

  // Throws InvalidInput naming the first field out of its valid range.
  void Validate() const;
};

class StepSizeController {
 public:
  virtual ~StepSizeController() = default;
  virtual double Initial() const = 0;
  // The next step after an accepted step asked as `ds` (before a clip onto a parameter bound) whose
  // corrector took `iterations` iterations.
  virtual double OnAccepted(double ds, int iterations) = 0;
  // The step to retry with after a failed corrector (may fall below ds_min: the caller stops).
  virtual double OnRejected(double ds) = 0;

  // The default policy: grow by up to `growth` when the corrector needed at most
  // target_iterations, shrink in proportion beyond (down to slowest_shrink), shrink by
  // rejection_shrink on failure; bounded by ds_max, and by ds_min after an accepted step.
  static std::unique_ptr<StepSizeController> Create(const StepSizeOptions& options);
};

}  // namespace stickslip
