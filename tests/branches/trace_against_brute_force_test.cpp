// The paper traces against brute force (the exact simulator, as `stickslip sweep` runs it), at
// points of every stable, admissible stretch of each trace (issue 12's tests):
//  - started on the trace's orbit, perturbed by 1e-6, the simulation settles back onto it: the
//    stable stretches are found by brute force when started on them;
//  - started from rest and from the paper's initial state, wherever the simulation settles on a
//    motion of period 1 or 2 whose orbit type (read off one simulated period) is the trace's
//    there, it is the trace's orbit (section state within 1e-7).
// The section is taken at the orbit's own phase, where its state is its start (x10, x20, v10, 0).
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "stickslip/analysis/motion_type.hpp"
#include "stickslip/analysis/settled_motion.hpp"
#include "stickslip/branches/trace.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/model/pascal_2014/paper_examples.hpp"
#include "stickslip/orbits/stability.hpp"

namespace stickslip {
namespace {

namespace fs = std::filesystem;

struct Checked {
  int stable_points = 0;  // points of stable stretches checked
  int same_type = 0;      // brute-force motions of the trace's type there, on the trace
};

Checked CheckAgainstBruteForce(const std::string& run_file, const std::string& preset) {
  const fs::path root(STICKSLIP_SOURCE_DIR);
  const RunFile run = ReadRunFile(root / "continuation-scripts" / (run_file + ".toml"));
  const TraceResult trace = TraceOrbits(MakeSetup(run, root / "results"), *run.trace);
  const State paper_start = FindPaperExample(preset)->initial_state;
  SettleOptions settle;
  settle.transient_periods = 1000;
  settle.recorded_periods = 8;
  Checked checked;
  for (const TraceDirection* chain : {&trace.down, &trace.up}) {
    for (const TraceLink& link : chain->links) {
      const OrbitBranch& b = link.branch;
      const std::size_t n = b.orbits.size();
      // Every fifth point away from the branch's ends.
      for (std::size_t i = 2; i + 2 < n; i += 5) {
        const Orbit& orbit = b.orbits[i];
        const Stability stability = StabilityOf(orbit);
        bool admissible = true;
        for (const Margin& m : AdmissibilityMargins(orbit)) admissible = admissible && !(m.value <= 1e-6);
        if (!admissible || !stability.stable || std::abs(stability.multipliers[0]) > 0.99) continue;
        const Parameters& p = orbit.parameters;
        const State start = orbit.InitialState();
        const std::string where = fmt::format("{} '{}' at omega = {}", run_file, link.signature, p.omega);
        ++checked.stable_points;
        const SettledMotion back = SimulateSettled(p, start + State::Constant(1e-6), orbit.phi, settle);
        EXPECT_FALSE(back.section.empty()) << where;
        if (!back.section.empty()) {
          EXPECT_LE(RelativeDistance(back.section.front(), start), 1e-7) << where;
        }
        const double forcing_period = 2.0 * std::numbers::pi / p.omega;
        for (const State& from : {State(State::Zero()), paper_start}) {
          const SettledMotion m = SimulateSettled(p, from, orbit.phi, settle);
          if (m.section.empty() || (m.period != 1 && m.period != 2)) continue;
          const MotionType type = ReadMotionType(m.record, m.period, forcing_period, {});
          if (!type.signature || type.signature->ToString() != link.signature) continue;
          ++checked.same_type;
          // The section repeats every period: the trace's orbit is at one of its points.
          double nearest = INFINITY;
          for (int k = 0; k < m.period; ++k) nearest = std::min(nearest, RelativeDistance(m.section[k], start));
          EXPECT_LE(nearest, 1e-7) << where << ", settled from " << from.transpose();
        }
      }
    }
  }
  return checked;
}

TEST(TraceAgainstBruteForce, Section41StableStretchesAreTheMotionsSimulationSettlesOn) {
  const Checked c = CheckAgainstBruteForce("paper-4.1-omega-trace", "paper-4.1");
  EXPECT_GE(c.stable_points, 10);
  EXPECT_GE(c.same_type, 1);
  RecordProperty("stable_points", c.stable_points);
  RecordProperty("same_type", c.same_type);
}

TEST(TraceAgainstBruteForce, Section52And6StableStretchesAreFoundWhenStartedOnThem) {
  for (const auto& [run, preset] : {std::pair{"paper-5.2-omega-trace", "paper-5.2"}, std::pair{"paper-6-omega-trace", "paper-6"}}) {
    const Checked c = CheckAgainstBruteForce(run, preset);
    EXPECT_GE(c.stable_points, 3) << run;
  }
}

}  // namespace
}  // namespace stickslip
