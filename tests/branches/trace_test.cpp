// The chain of branches through the changes of orbit type (branches/trace.hpp), on the paper's
// data: the section 4.1 orbit traced downwards in omega switches to the sticking orbit at the
// crossing-sliding (the orbit continuous across the switch, the new type confirmed by the exact and
// the Odeint simulators on its own branch), and the section 5.1 family closes its loop.
#include "stickslip/branches/trace.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <limits>
#include <numbers>
#include <utility>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/io/trace_files.hpp"
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

// Section 4.2 (u_r = u_s) downwards: the stop turns into a stick (crossing-sliding), s grazes
// +eta u_r inside that stick at omega = 0.3211122863 (adding-sliding: the new slip- is found with its
// length given, so its branch starts from the confirmed orbit past the grazing), and further down
// the first part of the split stick vanishes (T0), where the chain goes on on the type with that
// stick removed, the same motion. Each new orbit type is a motion on its branch by the exact simulator.
TEST(Trace, Section42DownwardsSwitchesAtACrossingAGrazingAndAVanishingStick) {
  OrbitContinuationSetup setup = RunFileSetup("paper-4.2-omega-down");
  setup.options.lambda_min = 0.25;
  setup.options.lambda_max = 0.7;
  const TraceResult trace = TraceOrbits(setup);
  SCOPED_TRACE(Describe(trace));
  ASSERT_EQ(trace.down.links.size(), 4u);
  EXPECT_EQ(trace.down.end, TraceEnd::kParameterBound);
  EXPECT_EQ(trace.up.end, TraceEnd::kFamilyEnd) << "u_s = u_r reaches 0 upwards";
  const std::vector<TraceLink>& chain = trace.down.links;
  EXPECT_EQ(chain[1].signature, "slip- slip- stick / antisymmetric");
  EXPECT_EQ(chain[2].signature, "slip- slip- stick slip- stick / antisymmetric");
  EXPECT_EQ(chain[3].signature, "slip- slip- stick / antisymmetric");
  EXPECT_STREQ(chain[1].type_switch->adjacent->bifurcation, "crossing-sliding");
  EXPECT_STREQ(chain[2].type_switch->adjacent->bifurcation, "adding-sliding");
  EXPECT_EQ(chain[3].margin, "duration:3");

  // The grazing: its branch starts past it, on the confirmed orbit, with the new slip short.
  const TypeSwitch& grazing = *chain[2].type_switch;
  EXPECT_TRUE(grazing.singular_start);
  EXPECT_NEAR(chain[1].branch.orbits.back().parameters.omega, 0.3211122863, 1e-9);
  const Orbit& first = chain[2].branch.orbits.front();
  EXPECT_LE(OrbitDistance(first, *grazing.past), 1e-10);
  EXPECT_LT(first.parameters.omega, 0.3211122863);
  EXPECT_GT(first.durations[3], 0.0);
  EXPECT_LT(first.durations[3], 1e-2 * first.Period());
  // The crossing and the vanishing stick: the same state, phase and period on both sides.
  for (const std::size_t k : {std::size_t{1}, std::size_t{3}}) {
    const Orbit& before = chain[k - 1].branch.orbits.back();
    const Orbit& after = chain[k].branch.orbits.front();
    EXPECT_FALSE(chain[k].type_switch->singular_start) << k;
    EXPECT_NEAR(after.parameters.omega, before.parameters.omega, 1e-12) << k;  // events located together
    EXPECT_LE((after.InitialState() - before.InitialState()).lpNorm<Eigen::Infinity>(), 1e-10) << k;
    EXPECT_LE(std::abs(after.phi - before.phi), 1e-10) << k;
    EXPECT_LE(std::abs(after.Period() - before.Period()), 1e-10) << k;
  }
  for (std::size_t k = 1; k < chain.size(); ++k) {
    const std::vector<Orbit>& orbits = chain[k].branch.orbits;
    ASSERT_GE(orbits.size(), 4u) << k;
    const Orbit& o = orbits[orbits.size() / 2];
    EXPECT_GT(SmallestMargin(AdmissibilityMargins(o)).value, 0.0) << k;
    const Verification v = VerifyOrbit(o);
    // Odeint, at its tolerances, merges a short slip between two sticks: the exact simulator
    // resolves every segment.
    EXPECT_TRUE(v.exact.sequence_matches && v.exact.periodicity_mismatch <= 1e-9) << k << ": " << v.Report();
  }
}

// The special points of a set of branches but their ends (EP), as (function, lambda), sorted, with
// the points located twice (a branch's end, and a start on it) counted once.
std::vector<std::pair<std::string, double>> SpecialPoints(const std::vector<const OrbitBranch*>& branches) {
  std::vector<std::pair<std::string, double>> points;
  for (const OrbitBranch* b : branches) {
    for (const SpecialPoint& s : b->branch.special_points) {
      if (s.type == "EP") continue;
      const std::string name = s.test_function.starts_with("margin:") ? s.test_function : s.type;
      const bool seen = std::any_of(points.begin(), points.end(), [&](const auto& p) {
        return p.first == name && std::abs(p.second - s.lambda) < 1e-8;
      });
      if (!seen) points.emplace_back(name, s.lambda);
    }
  }
  std::sort(points.begin(), points.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  return points;
}

// Section 5.1 over omega: none of its changes of type switches (the new segments are long), so the
// trace follows the orbit type past them; it goes round the family's closed loop and ends there,
// both chains meeting. Its special points are those of the one branch continued past every change
// of type round the loop (the engine's closed-loop end): the fold, the torus point and the changes of
// type, at the same omega.
TEST(Trace, Section51OverOmegaClosesItsLoopWithItsFoldAndTypeChanges) {
  OrbitContinuationSetup setup = RunFileSetup("paper-5.1-omega-up");
  setup.options.user_values.clear();
  TraceOptions options;
  options.follow_past_unswitched = true;
  const TraceResult trace = TraceOrbits(setup, options);
  SCOPED_TRACE(Describe(trace));
  EXPECT_EQ(trace.down.end, TraceEnd::kLoop) << trace.down.message;
  EXPECT_EQ(trace.up.end, TraceEnd::kLoop) << trace.up.message;
  ASSERT_FALSE(trace.down.links.empty());
  ASSERT_FALSE(trace.up.links.empty());
  // The chains met: both end on one orbit.
  const Orbit& down_end = trace.down.links.back().branch.orbits.back();
  const Orbit& up_end = trace.up.links.back().branch.orbits.back();
  EXPECT_LE(OrbitDistance(down_end, up_end), 1e-7);
  EXPECT_NEAR(down_end.parameters.omega, up_end.parameters.omega, 1e-7);
  std::vector<const OrbitBranch*> traced;
  for (const TraceDirection* chain : {&trace.down, &trace.up}) {
    for (const TraceLink& link : chain->links) {
      EXPECT_EQ(link.signature, "slip- slip+ stick slip+");
      EXPECT_NE(link.end, TraceEnd::kSwitched);
      traced.push_back(&link.branch);
    }
  }

  // The one branch round the loop, past every change of type.
  OrbitContinuationSetup round = setup;
  round.options.continue_past_terminal = true;
  round.options.max_points = 100000;
  const OrbitBranch loop = ContinueOrbit(round);
  ASSERT_EQ(loop.branch.end, BranchEnd::kClosedLoop) << loop.branch.end_message;
  const auto expected = SpecialPoints({&loop});
  const auto found = SpecialPoints(traced);
  ASSERT_EQ(found.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    EXPECT_EQ(found[k].first, expected[k].first) << k;
    // G born at the stick's exit (where exit-slope passes zero, next to it) grows quadratically
    // along the branch: a zero located to rounding in its value fixes omega only to about the square
    // root of that (1.7e-8 apart here, both with |G| < 1e-12).
    const bool born_at_the_exit = found[k].first.starts_with("margin:G:");
    EXPECT_NEAR(found[k].second, expected[k].second, born_at_the_exit ? 1e-7 : 1e-8) << found[k].first;
  }
  for (const OrbitBranch* b : traced) {
    for (const SpecialPoint& s : b->branch.special_points) {
      if (s.test_function.starts_with("margin:")) {
        EXPECT_LE(std::abs(s.test_value), 1e-12) << s.test_function;
      }
    }
  }
  const auto count = [&](const std::string& name) {
    return std::count_if(found.begin(), found.end(), [&](const auto& p) { return p.first == name; });
  };
  EXPECT_GE(count("LP"), 1);
  EXPECT_GE(count("TR"), 1);
  EXPECT_GE(std::count_if(found.begin(), found.end(), [](const auto& p) { return p.first.starts_with("margin:"); }), 3);
}

// The same trace twice gives the same files, byte for byte.
TEST(Trace, GivesTheSameFilesFromRunToRun) {
  const fs::path root(STICKSLIP_SOURCE_DIR);
  RunFile run = ReadRunFile(root / "continuation-scripts" / "paper-4.1-omega-down.toml");
  run.trace = TraceOptions{};
  const OrbitContinuationSetup setup = MakeSetup(run, root / "results");
  const TraceFiles a = FormatTraceFiles(RecordTrace(run, TraceOrbits(setup, *run.trace)));
  const TraceFiles b = FormatTraceFiles(RecordTrace(run, TraceOrbits(setup, *run.trace)));
  EXPECT_EQ(a.trace_csv, b.trace_csv);
  EXPECT_EQ(a.trace_json, b.trace_json);
}

// The §5.2 type's admissible stretch holds a period doubling (paper-5.2-omega-to-pd): the trace
// records the period-2 branch that leaves it, with the period-1 orbit traversed twice singular there
// in the period-2 problem, and does not follow it.
TEST(Trace, RecordsTheBranchLeavingAPeriodDoublingWithoutFollowingIt) {
  OrbitContinuationSetup setup = RunFileSetup("paper-5.2-omega-to-pd");
  setup.options.lambda_min = 0.7;
  const TraceResult trace = TraceOrbits(setup);
  std::vector<BifurcationMet> met;
  std::size_t links = 0;
  for (const TraceDirection* chain : {&trace.down, &trace.up}) {
    for (const TraceLink& link : chain->links) {
      met.insert(met.end(), link.bifurcations.begin(), link.bifurcations.end());
      ++links;
      EXPECT_EQ(link.signature.find("period 2"), std::string::npos);  // not followed
    }
  }
  ASSERT_EQ(met.size(), 1u);
  EXPECT_EQ(met[0].type, "PD");
  EXPECT_NEAR(met[0].lambda, 0.7354877530, 1e-9);  // where ContinueOrbit locates it (results/README.md)
  EXPECT_EQ(met[0].signature, "slip- slip+ stick slip- slip+ stick / period 2");
  EXPECT_LT(met[0].singularity, 1e-7);
  EXPECT_TRUE(met[0].message.empty());
  EXPECT_FALSE(met[0].followed.has_value());
  EXPECT_GE(links, 1u);
}

// Asked to, the trace follows the period-2 branch that leaves the PD: its orbits repeat after two
// forcing periods in the exact simulator and not after one; it is written beside the chain as
// branch-<k>-PD<n>/ and read back to the same bytes.
TEST(Trace, FollowsTheBranchLeavingAPeriodDoublingWhenAsked) {
  OrbitContinuationSetup setup = RunFileSetup("paper-5.2-omega-to-pd");
  setup.options.lambda_min = 0.7;
  TraceOptions options;
  options.follow_bifurcations = 1;
  const TraceResult trace = TraceOrbits(setup, options);
  const OrbitBranch* followed = nullptr;
  for (const TraceDirection* chain : {&trace.down, &trace.up}) {
    for (const TraceLink& link : chain->links) {
      for (const BifurcationMet& m : link.bifurcations) {
        if (m.followed) followed = &*m.followed;
      }
    }
  }
  ASSERT_NE(followed, nullptr);
  ASSERT_GE(followed->orbits.size(), 10u) << followed->branch.end_message;
  const Orbit& o = followed->orbits[5];
  EXPECT_EQ(o.signature.ToString(), "slip- slip+ stick slip- slip+ stick / period 2");
  SimulationOptions simulation;
  for (const double periods : {1.0, 2.0}) {
    simulation.duration = periods * 2.0 * std::numbers::pi / o.parameters.omega;
    const SimulationResult r = SimulateExact(o.parameters, o.InitialState(), o.phi, simulation);
    ASSERT_TRUE(r.Completed());
    const double distance = (StateAt(r, simulation.duration) - o.InitialState()).cwiseAbs().maxCoeff();
    if (periods == 1.0) EXPECT_GT(distance, 1e-4);
    else EXPECT_LT(distance, 1e-9);
  }
  RunFile run = ReadRunFile(fs::path(STICKSLIP_SOURCE_DIR) / "continuation-scripts" / "paper-5.2-omega-to-pd.toml");
  run.output = "followed";
  const StoredTrace stored = RecordTrace(run, trace);
  ASSERT_EQ(stored.followed_runs.size(), 1u);
  const fs::path root = fs::path(::testing::TempDir()) / "trace_follows_test";
  fs::remove_all(root);
  WriteTraceFiles(root, stored);
  const StoredTrace read = ReadTraceFiles(root / "followed");
  ASSERT_EQ(read.followed_runs.size(), 1u);
  EXPECT_EQ(FormatRunFiles(read.followed_runs[0]).branch_csv, FormatRunFiles(stored.followed_runs[0]).branch_csv);
  EXPECT_EQ(FormatTraceFiles(read).trace_json, FormatTraceFiles(stored).trace_json);
  fs::remove_all(root);
}

TEST(Trace, RefusesInvalidOptions) {
  const OrbitContinuationSetup setup = RunFileSetup("paper-4.1-omega-down");
  for (const auto& [field, change] : std::vector<std::pair<std::string, std::function<void(TraceOptions*)>>>{
           {"max_branches", [](TraceOptions* o) { o->max_branches = 0; }},
           {"max_branches", [](TraceOptions* o) { o->max_branches = kMaxTraceBranches + 1; }},
           {"max_amplitude", [](TraceOptions* o) { o->max_amplitude = 0.0; }},
           {"max_amplitude", [](TraceOptions* o) { o->max_amplitude = std::numeric_limits<double>::infinity(); }},
           {"loop_tolerance", [](TraceOptions* o) { o->loop_tolerance = 0.0; }},
           {"loop_tolerance", [](TraceOptions* o) { o->loop_tolerance = 1e300; }},
           {"nudge", [](TraceOptions* o) { o->type_switch.nudge = -1.0; }}}) {
    TraceOptions options;
    change(&options);
    try {
      TraceOrbits(setup, options);
      ADD_FAILURE() << field << " accepted";
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.field(), field) << e.what();
    }
  }
  OrbitContinuationSetup past = setup;
  past.options.continue_past_terminal = true;
  EXPECT_THROW(TraceOrbits(past), InvalidInput);
}

// A resonance bound below the orbit's amplitude ends both directions at the start.
TEST(Trace, EndsAtAResonanceWhereTheAmplitudePassesItsBound) {
  const OrbitContinuationSetup setup = RunFileSetup("paper-4.1-omega-down");
  TraceOptions options;
  // Section 4.1's x20 is 3.33 at the start: an amplitude of at least that.
  options.max_amplitude = 3.0;
  const TraceResult trace = TraceOrbits(setup, options);
  EXPECT_EQ(trace.down.end, TraceEnd::kResonance) << trace.down.message;
  EXPECT_EQ(trace.up.end, TraceEnd::kResonance) << trace.up.message;
  ASSERT_EQ(trace.down.links.size(), 1u);
  EXPECT_EQ(trace.down.links[0].branch.orbits.size(), 1u);
  EXPECT_EQ(trace.down.links[0].branch.branch.end, BranchEnd::kStopped);
  // A bound above the whole range's amplitude never ends it.
  options.max_amplitude = 1e3;
  const TraceResult wide = TraceOrbits(setup, options);
  EXPECT_EQ(wide.up.end, TraceEnd::kParameterBound) << wide.up.message;
}

// max_branches bounds each chain.
TEST(Trace, StopsAfterMaxBranches) {
  OrbitContinuationSetup setup = RunFileSetup("paper-5.1-omega-up");
  setup.options.user_values.clear();
  TraceOptions options;
  options.follow_past_unswitched = true;
  options.max_branches = 2;
  const TraceResult trace = TraceOrbits(setup, options);
  EXPECT_EQ(trace.down.end, TraceEnd::kMaxBranches) << trace.down.message;
  EXPECT_EQ(trace.down.links.size(), 2u);
  EXPECT_EQ(trace.up.links.size(), 2u);
}

}  // namespace
}  // namespace stickslip
