#include "stickslip/numerics/newton.hpp"

#include <gtest/gtest.h>

namespace stickslip {
namespace {

// The report of a failure names the termination, the iterations and the last residual; the
// condition number only where it was estimated (a number >= 1: 0 means it was not).
TEST(NewtonSummary, BriefReportGivesTheConditionNumberOnlyWhereItWasEstimated) {
  NewtonSummary s;
  s.termination = NewtonTermination::kLineSearchFailed;
  s.iterations = 7;
  s.residual_norms = {1.0, 1.709e-4};
  s.message = "no step along the Newton direction lowers |F|";
  EXPECT_EQ(s.BriefReport(),
            "line-search-failed after 7 iteration(s), residual 1.709e-04: no step along the Newton direction lowers |F|");
  s.condition_number = 7427.0;
  EXPECT_EQ(s.BriefReport(), "line-search-failed after 7 iteration(s), residual 1.709e-04, condition 7.427e+03: no step "
                             "along the Newton direction lowers |F|");
}

}  // namespace
}  // namespace stickslip
