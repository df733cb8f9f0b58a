// Brute force against continuation: started near a continued orbit, the simulation settles on it
// where the multipliers say stable and leaves it where they say unstable.
#include <filesystem>

#include <gtest/gtest.h>

#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/analysis/sweep.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/stability.hpp"

namespace stickslip {
namespace {

namespace fs = std::filesystem;

OrbitBranch Branch(const std::string& run_file) {
  const fs::path source(STICKSLIP_SOURCE_DIR);
  return ContinueOrbit(MakeSetup(ReadRunFile(source / "continuation-scripts" / run_file), source / "results"));
}

// One sweep point at the orbit's own parameters, from its initial state moved by `offset`; the
// section is taken at the orbit's phase phi (its time origin). Returns the largest distance of
// the recorded section points from the orbit's initial state.
double SettledDistance(const Orbit& o, double offset) {
  SweepOptions options;
  options.from = options.to = o.parameters.omega;
  options.steps = 1;
  options.transient_periods = 300;
  options.recorded_periods = 4;
  State start = o.InitialState();
  start(0) += offset;
  const std::vector<SweepPoint> points = Sweep(o.parameters, {start}, o.phi, options);
  double distance = 0.0;
  for (const auto& x : points.front().section) {
    distance = std::max(distance, (x - o.InitialState()).lpNorm<Eigen::Infinity>());
  }
  return distance;
}

class SweepAgainstBranch : public ::testing::TestWithParam<std::string> {};

TEST_P(SweepAgainstBranch, SettlesOnStableOrbitsAndLeavesUnstableOnes) {
  const OrbitBranch b = Branch(GetParam());
  const auto admissible = std::find_if(b.columns.begin(), b.columns.end(),
                                       [](const PointColumn& c) { return c.name == "admissible"; });
  ASSERT_NE(admissible, b.columns.end());
  int stable = 0, unstable = 0;
  for (std::size_t i = 0; i < b.orbits.size(); i += 7) {
    if (ColumnValues(b.columns, b.branch.points[i])[admissible - b.columns.begin()] == 0.0) continue;
    const Orbit& o = b.orbits[i];
    const Stability s = StabilityOf(o);
    // Keep clear of the unit circle, where convergence or escape takes too long to see, and of
    // changes of orbit type, where a perturbation may cross into another type of motion (the
    // multipliers describe the orbit's own type only).
    const double largest = std::abs(s.multipliers[0]);
    if (s.one_sided || std::abs(largest - 1.0) < 0.02) continue;
    if (SmallestMargin(AdmissibilityMargins(o)).value < 0.01) continue;
    if (s.stable) {
      ++stable;
      EXPECT_LT(SettledDistance(o, 1e-5), 1e-7) << GetParam() << " point " << i << ", |mu| = " << largest;
    } else {
      ++unstable;
      EXPECT_GT(SettledDistance(o, 1e-6), 1e-4) << GetParam() << " point " << i << ", |mu| = " << largest;
    }
  }
  EXPECT_GT(stable + unstable, 0) << GetParam();
}

INSTANTIATE_TEST_SUITE_P(PaperFamilies, SweepAgainstBranch,
                         ::testing::Values("paper-4.1-omega-up.toml", "paper-5.1-omega-up.toml",
                                           "paper-5.2-omega-down.toml", "paper-6-omega-up.toml"),
                         [](const ::testing::TestParamInfo<std::string>& file) {
                           std::string name = fs::path(file.param).stem().string();
                           for (char& c : name) {
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           }
                           return name;
                         });

}  // namespace
}  // namespace stickslip
