// The one place where runs, trace branches and map curves are stored (RecordRun): a duration at
// rounding level below zero is stored as the zero-length segment it stands for (issue 22, defect
// 3), built here directly so that the test does not depend on today's rounding.
#include "stickslip/io/stored_run.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/orbits/start_problem.hpp"

namespace stickslip {
namespace {

// Two points of the section 6 orbit over omega (slip- stick slip- / antisymmetric).
OrbitBranch TwoPoints() {
  StartInput input;
  input.preset = "paper-6";
  input.parameter = "omega";
  const StartProblem start = BuildStartProblem(input);
  ContinuationOptions options;
  options.max_points = 2;
  return ContinueOrbit({.start = start.orbit, .unknowns = start.unknowns, .parameter = "omega", .options = options});
}

double Margin(const StoredPoint& p, const std::string& name) {
  for (const auto& [n, value] : p.margins) {
    if (n == name) return value;
  }
  ADD_FAILURE() << "no margin " << name;
  return 0.0;
}

TEST(RecordRun, StoresARoundingLevelNegativeDurationAsAZeroLengthSegment) {
  OrbitBranch b = TwoPoints();
  ASSERT_EQ(b.orbits.size(), 2u);
  const double period = b.orbits[1].Period();
  b.orbits[1].durations[1] = -0.5 * kDurationRounding * period;  // the stick, d2
  RunFile run;
  run.output = "stored";
  run.parameter = "omega";
  const StoredRun stored = RecordRun(run, b);
  const StoredPoint& p = stored.branch[1];
  const Orbit orbit = OrbitOf(stored, p);
  EXPECT_EQ(orbit.durations[1], 0.0);
  EXPECT_FALSE(std::signbit(orbit.durations[1]));
  EXPECT_EQ(Margin(p, "duration:2"), 0.0);
  // The row's measures are those of the orbit it stores.
  EXPECT_EQ(Named(p.measures, "stick-fraction"), Measure(orbit).stick_fraction);
  EXPECT_EQ(Named(p.measures, "amplitude:x2"), Measure(orbit).amplitude_x2);
  // The other durations and the point that had none below zero are as computed.
  EXPECT_EQ(orbit.durations[0], b.orbits[1].durations[0]);
  EXPECT_EQ(OrbitOf(stored, stored.branch[0]).durations, b.orbits[0].durations);
}

// Beyond rounding a negative duration is a row past a change of type (continue_past_type_changes)
// and is stored as it is.
TEST(RecordRun, KeepsANegativeDurationBeyondRounding) {
  OrbitBranch b = TwoPoints();
  b.orbits[1].durations[1] = -1e-3;
  RunFile run;
  run.output = "stored";
  run.parameter = "omega";
  EXPECT_EQ(Named(RecordRun(run, b).branch[1].solution, "d2"), -1e-3);
}

}  // namespace
}  // namespace stickslip
