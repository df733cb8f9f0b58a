// Time per accepted continuation point for each paper family, event monitoring (every
// admissibility margin, folds, branch points) included: with the closed-form flows, and with the
// same branch's flows and derivatives integrated by Boost.Odeint (variational equations, the
// same 1e-12 tolerances as the cross-check simulator).
//
//   build/release/tests/continuation_benchmark --benchmark_repetitions=5 \
//       --benchmark_report_aggregates_only=true
//
// The counter us_per_point is the figure results/README.md reports (median over the repetitions).
//
// Also the brute-force sweep's wall time on 1 thread and on every core, for the parallel
// speed-up of its chains, and the exact simulator's cost per forcing period over a short and a
// long run; and the brute-force map's cells per second per core; and the wall time of whole traces
// (every branch, switch and confirming simulation), closed form against Odeint; and the boundary
// curves of the section 4.1 data in (omega, u_r) (CurveWallTime, registered in main); and the whole
// orbit-type map of the section 5.1 data in (omega, u_r), as tools/run.sh computes it.
#include <algorithm>
#include <filesystem>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/branches/orbit_type_map.hpp"
#include "stickslip/branches/trace.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/io/orbit_type_map_files.hpp"
#include "stickslip/io/run_file.hpp"
#include "stickslip/io/stored_run.hpp"
#include "stickslip/io/trace_files.hpp"
#include "stickslip/model/pascal_2014/odeint_simulator.hpp"
#include "stickslip/model/pascal_2014/paper_examples.hpp"
#include "stickslip/model/simulation.hpp"
#include "stickslip/analysis/brute_force_map.hpp"
#include "stickslip/analysis/sweep.hpp"
#include "stickslip/numerics/parallel_for.hpp"

namespace stickslip {
namespace {

// Odeint integrates forward only: a segment of zero length that Newton moves to a tiny negative
// duration (a trace's new segment, -1e-12) is flowed by the closed form, a handful of evaluations.
State OdeintState(Mode mode, const State& start, const double& phase, const double& s, const Parameters& p) {
  return s < 0.0 ? Flow(mode, start, phase, s, p) : IntegrateMode(mode, start, phase, s, p);
}
FlowDerivatives OdeintDerivatives(Mode mode, const State& start, double phase, double s, const Parameters& p) {
  return s < 0.0 ? FlowWithDerivatives(mode, start, phase, s, p) : IntegrateModeWithDerivatives(mode, start, phase, s, p);
}
constexpr FlowEvaluator kClosedForm{};
constexpr FlowEvaluator kOdeint{&OdeintState, &OdeintDerivatives};

// The first `points` points of a family's omega run (the run files of continuation-scripts/).
OrbitContinuationSetup Family(const std::string& run_file, int points, FlowEvaluator flow) {
  const std::filesystem::path source(STICKSLIP_SOURCE_DIR);
  OrbitContinuationSetup setup = MakeSetup(ReadRunFile(source / "continuation-scripts" / run_file), source / "results");
  setup.options.max_points = points;
  setup.flow = flow;
  return setup;
}

void PerPoint(benchmark::State& state, const std::string& run_file, FlowEvaluator flow) {
  const OrbitContinuationSetup setup = Family(run_file, static_cast<int>(state.range(0)), flow);
  double points = 0;
  for (auto _ : state) {
    const OrbitBranch branch = ContinueOrbit(setup);
    points += static_cast<double>(branch.branch.points.size());
    benchmark::DoNotOptimize(branch.branch.points.back().lambda);
  }
  // Elapsed time per 1e-6 points: microseconds per accepted point.
  state.counters["us_per_point"] = benchmark::Counter(points * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// 20 points: the start of each branch, before any of them ends (the shortest, section 4.2
// downwards, has 6 points and is not used).
#define STICKSLIP_FAMILY(name, file)                                                             \
  BENCHMARK_CAPTURE(PerPoint, closed_form_##name, file, kClosedForm)->Arg(20)->Unit(benchmark::kMicrosecond); \
  BENCHMARK_CAPTURE(PerPoint, odeint_##name, file, kOdeint)->Arg(20)->Unit(benchmark::kMicrosecond);

STICKSLIP_FAMILY(paper_4_1, "paper-4.1-omega-up.toml")
STICKSLIP_FAMILY(paper_4_2, "paper-4.2-omega-up.toml")
STICKSLIP_FAMILY(paper_5_1, "paper-5.1-omega-up.toml")
STICKSLIP_FAMILY(paper_5_2, "paper-5.2-omega-down.toml")
STICKSLIP_FAMILY(paper_6, "paper-6-omega-up.toml")

// A whole trace of a run file with a [trace] table, its branches' flows by `flow` (the switches
// are confirmed by the exact simulator either way). Counters: points (all branches') and
// us_per_point.
void TraceWallTime(benchmark::State& state, const std::string& run_file, FlowEvaluator flow) {
  const std::filesystem::path source(STICKSLIP_SOURCE_DIR);
  const RunFile run = ReadRunFile(source / "continuation-scripts" / run_file);
  OrbitContinuationSetup setup = MakeSetup(run, source / "results");
  setup.flow = flow;
  double points = 0.0, per_trace = 0.0;
  for (auto _ : state) {
    const TraceResult trace = TraceOrbits(setup, *run.trace);
    per_trace = 0.0;
    for (const TraceDirection* chain : {&trace.down, &trace.up}) {
      for (const TraceLink& link : chain->links) per_trace += static_cast<double>(link.branch.branch.points.size());
    }
    points += per_trace;
  }
  state.counters["points"] = per_trace;
  state.counters["us_per_point"] = benchmark::Counter(points * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

#define STICKSLIP_TRACE(name, file)                                                                         \
  BENCHMARK_CAPTURE(TraceWallTime, closed_form_##name, file, kClosedForm)->UseRealTime()->Unit(benchmark::kMillisecond); \
  BENCHMARK_CAPTURE(TraceWallTime, odeint_##name, file, kOdeint)->UseRealTime()->Unit(benchmark::kMillisecond);

STICKSLIP_TRACE(paper_4_1, "paper-4.1-omega-trace.toml")
STICKSLIP_TRACE(paper_4_2, "paper-4.2-omega-trace.toml")
STICKSLIP_TRACE(paper_5_1, "paper-5.1-omega-trace.toml")
STICKSLIP_TRACE(paper_5_2, "paper-5.2-omega-trace.toml")
STICKSLIP_TRACE(paper_6, "paper-6-omega-trace.toml")

// Section 5.1 over omega, 11 values, with the command line's default chains (four, up and down)
// and periods (500 transient and 20 recorded per point), on range(0) threads (0: every core).
void SweepWallTime(benchmark::State& state) {
  const PaperExample& e = *FindPaperExample("paper-5.1");
  const SweepOptions options{.from = 0.55, .to = 0.6, .steps = 10, .transient_periods = 500, .recorded_periods = 20,
                             .threads = static_cast<int>(state.range(0))};
  const std::vector<State> starts = ScatteredStarts(e.initial_state, 1.0, 4, 1);
  for (auto _ : state) {
    benchmark::DoNotOptimize(Sweep(e.parameters, starts, e.phi, options).back().section.back());
  }
  state.counters["workers"] = WorkerCount(options.threads, static_cast<int>(starts.size()));
}
BENCHMARK(SweepWallTime)->ArgName("threads")->Arg(1)->Arg(0)->UseRealTime()->Unit(benchmark::kMillisecond);

// The brute-force map of section 6 over (omega, u_r), 6 x 4 cells with the command line's
// defaults (500 transient and 24 recorded periods, rest, the neighbour and 4 more starts per
// cell), on range(0) threads (0: every core): cells per second per core.
void MapCellsPerCore(benchmark::State& state) {
  const PaperExample& e = *FindPaperExample("paper-6");
  BruteForceMapOptions options;
  options.first = {ParameterId::kOmega, 0.55, 0.6, 5};
  options.second = {ParameterId::kStaticFriction, 1.2, 1.5, 3};
  options.centre = e.initial_state;
  options.threads = static_cast<int>(state.range(0));
  const int cells = options.first.Count() * options.second.Count();
  for (auto _ : state) {
    benchmark::DoNotOptimize(ComputeBruteForceMap(e.parameters, e.phi, options).cells.size());
  }
  const int workers = WorkerCount(options.threads, cells);
  state.counters["workers"] = workers;
  state.counters["cells_per_s_per_core"] =
      benchmark::Counter(static_cast<double>(cells) / workers, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(MapCellsPerCore)->ArgName("threads")->Arg(1)->Arg(0)->UseRealTime()->Unit(benchmark::kMillisecond);

// The exact simulator over range(0) forcing periods of section 5.1's motion: the cost per period
// must not grow with the duration (a stick's exit is searched with a reach doubled from one
// period, not to the end of the run).
void SimulationPerPeriod(benchmark::State& state) {
  const PaperExample& e = *FindPaperExample("paper-5.1");
  SimulationOptions options;
  options.duration = static_cast<double>(state.range(0)) * 2.0 * std::numbers::pi / e.parameters.omega;
  for (auto _ : state) {
    benchmark::DoNotOptimize(SimulateExact(e.parameters, e.initial_state, e.phi, options).events.size());
  }
  state.counters["us_per_period"] = benchmark::Counter(static_cast<double>(state.range(0)) * 1e-6,
                                                       benchmark::Counter::kIsIterationInvariantRate |
                                                           benchmark::Counter::kInvert);
}
BENCHMARK(SimulationPerPeriod)->ArgName("periods")->Arg(500)->Arg(4000)->Unit(benchmark::kMillisecond);

// The boundary curves of one paper data set (section 4.1) over the rectangle omega in [0.3, 0.69]
// (u_r released; a curve ends at that range, at a codimension-two point or where its orbit ends):
// from every special point of its trace (results/paper-4.1-omega-trace, every branch) but the ends
// (EP), the curve that BoundaryCurve gives through it, both ways (down, then up), with the options of
// the run file of the section 4.1 crossing-sliding boundary (paper-4.1-sk-boundary.toml, whose
// start is the trace's branch-1:SK2). The context holds each curve's condition (curve:<branch>:<label>)
// and each point whose condition BoundaryCurve refuses (no such curve yet) as
// curve_refused:<branch>:<label>, and how each half ends with the special points on it
// (curve_ends:<branch>:<label>, from one run at registration). Counters: points
// (both halves), us_per_point, and the curve's extent: omega_min/max, u_r_min/max.
// The orbit-type map of results/paper-5.1-omega-trace over tools/run.sh's rectangle: every curve,
// the regions and their content; the cost per curve point counts the whole map's time.
void OrbitTypeMapWallTime(benchmark::State& state) {
  const std::filesystem::path source(STICKSLIP_SOURCE_DIR);
  const StoredTrace trace = ReadTraceFiles(source / "results" / "paper-5.1-omega-trace");
  const RunFile run = ReadRunFile(source / trace.run_file);
  const MapTrace input = MapTraceOf(trace, &run);
  const MapRectangle rectangle{.first = "omega", .second = "u_r", .first_min = 0.5, .first_max = 0.62,
                               .second_min = 0.3, .second_max = 0.8};
  double points = 0.0, maps = 0.0;
  std::size_t curves = 0, regions = 0;
  for (auto _ : state) {
    const OrbitTypeMap map = BuildOrbitTypeMap(input, rectangle);
    curves = map.curves.size();
    regions = map.regions.size();
    for (const MapCurve& curve : map.curves) points += static_cast<double>(curve.first.size());
    maps += 1.0;
  }
  state.counters["curves"] = static_cast<double>(curves);
  state.counters["regions"] = static_cast<double>(regions);
  state.counters["curve_points"] = points / std::max(1.0, maps);
  state.counters["us_per_curve_point"] = benchmark::Counter(points * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(OrbitTypeMapWallTime)->UseRealTime()->Unit(benchmark::kMillisecond);

struct CurveRun {
  std::string name;                             // "branch-1:SK2"
  std::vector<OrbitContinuationSetup> halves;  // down, up
};

void CurveWallTime(benchmark::State& state, const CurveRun& curve) {
  double points = 0.0, per_curve = 0.0;
  double omega_min = std::numeric_limits<double>::infinity(), omega_max = -omega_min;
  double u_r_min = omega_min, u_r_max = omega_max;
  for (auto _ : state) {
    per_curve = 0.0;
    for (const OrbitContinuationSetup& half : curve.halves) {
      const OrbitBranch branch = ContinueOrbit(half);
      per_curve += static_cast<double>(branch.branch.points.size());
      for (const Orbit& orbit : branch.orbits) {
        omega_min = std::min(omega_min, orbit.parameters.omega);
        omega_max = std::max(omega_max, orbit.parameters.omega);
        u_r_min = std::min(u_r_min, orbit.parameters.u_r);
        u_r_max = std::max(u_r_max, orbit.parameters.u_r);
      }
    }
    points += per_curve;
  }
  state.counters["points"] = per_curve;
  state.counters["us_per_point"] = benchmark::Counter(points * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["omega_min"] = omega_min;
  state.counters["omega_max"] = omega_max;
  state.counters["u_r_min"] = u_r_min;
  state.counters["u_r_max"] = u_r_max;
}

void RegisterCurves() {
  const std::filesystem::path source(STICKSLIP_SOURCE_DIR);
  const std::filesystem::path trace = source / "results" / "paper-4.1-omega-trace";
  RunFile run = ReadRunFile(source / "continuation-scripts" / "paper-4.1-sk-boundary.toml");
  std::vector<std::filesystem::path> branches;
  for (const auto& entry : std::filesystem::directory_iterator(trace)) {
    if (entry.is_directory()) branches.push_back(entry.path());
  }
  std::sort(branches.begin(), branches.end());
  for (const std::filesystem::path& branch : branches) {
    for (const StoredSpecialPoint& special : ReadRunFiles(branch).special_points) {
      if (special.type == "EP") continue;
      CurveRun curve{branch.filename().string() + ":" + special.point.label, {}};
      // The condition as a run file's restart reads it: a type change's margin, else the type.
      const std::string condition = special.test_function.starts_with("margin:") ? special.test_function : special.type;
      run.restart_run = branch.filename().string();
      run.restart_label = special.point.label;
      try {
        for (const int direction : {-1, 1}) {
          run.direction = direction;
          curve.halves.push_back(MakeSetup(run, trace));
        }
      } catch (const InvalidInput& e) {
        if (e.field() != "start.restart.boundary") throw;  // only BoundaryCurve's refusal is "no curve yet"
        benchmark::AddCustomContext("curve_refused:" + curve.name, condition);
        continue;
      }
      benchmark::AddCustomContext("curve:" + curve.name, condition);
      // How each half ends, and the special points on it (the codimension-two points): run once here.
      std::string ends;
      for (std::size_t h = 0; h < curve.halves.size(); ++h) {
        const OrbitBranch half = ContinueOrbit(curve.halves[h]);
        ends += std::string(h == 0 ? "" : "; ") + (h == 0 ? "down " : "up ") + ToString(half.branch.end);
        for (const std::string& label : PointLabels(half.branch)) {
          if (!label.empty() && !label.starts_with("EP")) ends += " " + label;
        }
      }
      benchmark::AddCustomContext("curve_ends:" + curve.name, ends);
      benchmark::RegisterBenchmark(("CurveWallTime/" + curve.name).c_str(), CurveWallTime, curve)
          ->UseRealTime()
          ->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace
}  // namespace stickslip

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  stickslip::RegisterCurves();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
