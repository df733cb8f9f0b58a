// The chain of branches through the changes of orbit type (branches/trace.hpp), on the paper's
// data: the section 4.1 orbit traced downwards in omega switches to the sticking orbit at the
// crossing-sliding (the orbit continuous across the switch, the new type confirmed by the exact and
// the Odeint simulators on its own branch), and the section 5.1 family closes its loop.
#include "stickslip/branches/trace.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/model/simulation.hpp"
#include "stickslip/orbits/verification.hpp"

namespace stickslip {
namespace {

namespace fs = std::filesystem;

OrbitContinuationSetup RunFileSetup(const std::string& run) {
  const fs::path root(STICKSLIP_SOURCE_DIR);
  return MakeSetup(ReadRunFile(root / "continuation-scripts" / (run + ".toml")), root / "results");
}

std::string Describe(const TraceResult& trace) {
  std::string text;
  for (const TraceDirection* chain : {&trace.down, &trace.up}) {
    text += fmt::format("{}: {} ({})\n", chain->direction > 0 ? "up" : "down", ToString(chain->end), chain->message);
    for (const TraceLink& link : chain->links) {
      text += fmt::format("  '{}' {} from {} at '{}': {} points, {} to {}: {}\n", link.signature,
                          link.direction > 0 ? "up" : "down", ToString(link.start), link.margin,
                          link.branch.orbits.size(), link.branch.branch.points.front().lambda,
                          link.branch.branch.points.back().lambda, ToString(link.end));
      for (const SpecialPoint& s : link.branch.branch.special_points) {
        text += fmt::format("    {} {} {:.10g}\n", s.type, s.test_function, s.lambda);
      }
    }
  }
  return text;
}

// The section 4.1 orbit downwards from omega = 0.6: its stops turn into sticks at omega =
// 0.5999775071 (where the run file's branch ends, SK), and the chain goes on as the sticking
// orbit 'slip- stick / antisymmetric', the same motion at the switch.
TEST(Trace, Section41DownwardsGoesOnPastTheCrossingSlidingOnTheStickingOrbit) {
  const OrbitContinuationSetup setup = RunFileSetup("paper-4.1-omega-down");
  const TraceResult trace = TraceOrbits(setup);
  SCOPED_TRACE(Describe(trace));
  ASSERT_GE(trace.down.links.size(), 2u);
  const TraceLink& first = trace.down.links[0];
  const TraceLink& second = trace.down.links[1];
  EXPECT_EQ(first.signature, "slip- / antisymmetric");
  EXPECT_EQ(first.start, LinkStart::kTraceStart);
  EXPECT_EQ(first.end, TraceEnd::kSwitched);
  EXPECT_NEAR(first.branch.branch.points.back().lambda, 0.5999775071, 1e-10);
  EXPECT_EQ(second.signature, "slip- stick / antisymmetric");
  EXPECT_EQ(second.start, LinkStart::kSwitch);
  EXPECT_EQ(second.margin, "reversal:1");
  EXPECT_EQ(second.direction, -1);
  ASSERT_TRUE(second.type_switch.has_value());
  EXPECT_STREQ(second.type_switch->adjacent->bifurcation, "crossing-sliding");
  EXPECT_TRUE(second.type_switch->persists);

  // Continuous across the switch: the same state, phase and period at the located parameter.
  const Orbit& before = first.branch.orbits.back();
  const Orbit& after = second.branch.orbits.front();
  EXPECT_EQ(after.parameters.omega, before.parameters.omega);
  EXPECT_LE((after.InitialState() - before.InitialState()).lpNorm<Eigen::Infinity>(), 1e-10);
  EXPECT_LE(std::abs(after.phi - before.phi), 1e-10);
  EXPECT_LE(std::abs(after.Period() - before.Period()), 1e-10);

  // The sticking orbit is a motion of the system on its branch: below the switch, the exact
  // simulator goes through a stick at each stop, and both simulators agree with the orbit.
  ASSERT_GE(second.branch.orbits.size(), 4u);
  for (const std::size_t k : {std::size_t{1}, second.branch.orbits.size() / 2, second.branch.orbits.size() - 2}) {
    const Orbit& o = second.branch.orbits[k];
    EXPECT_LT(o.parameters.omega, 0.5999775071);
    EXPECT_GT(o.durations[1], 0.0);
    const Verification v = VerifyOrbit(o);
    EXPECT_TRUE(v.Passed()) << "point " << k << ": " << v.Report();
  }
  // Upwards the nonsticking orbit goes on to the range's end.
  ASSERT_FALSE(trace.up.links.empty());
  EXPECT_EQ(trace.up.links.front().signature, "slip- / antisymmetric");
}

}  // namespace
}  // namespace stickslip
