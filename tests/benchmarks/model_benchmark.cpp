// The general linear oscillator (model/linear_oscillator.hpp) against the paper model's
// specialised closed forms, on the same orbit (section 4.1's, converted to a physical two-mass
// description as tests/model/linear_oscillator_test.cpp does), and its cost against the number of
// coordinates on chains of n = 1, 2, 5, 10 masses. Per evaluation of what a continuation point
// asks: the periodicity equations with their Jacobian, the admissibility margins (root finding
// included), the monodromy and its multipliers; and per accepted point of a branch and of a trace
// through the one path every model takes (ContinueOrbit, TraceOrbits).
//
//   build/release/tests/model_benchmark --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// The ratio general/pascal of the medians of one run is the figure the general-oscillator issue asks for.
// Last, the atlas of section 4.1's data both ways, its wall time split by stage (--benchmark_filter=Atlas).
#include <chrono>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <string>
#include <utility>

#include <benchmark/benchmark.h>

#include "stickslip/analysis/atlas.hpp"
#include "stickslip/analysis/model_atlas.hpp"
#include "stickslip/branches/model_trace.hpp"
#include "stickslip/model/linear_oscillator.hpp"
#include "stickslip/model/pascal_2014.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/model_orbit_problem.hpp"
#include "stickslip/orbits/orbit_solver.hpp"
#include "stickslip/orbits/paper_presets.hpp"
#include "stickslip/orbits/periodicity_equations.hpp"
#include "stickslip/orbits/stability.hpp"
#include "support/five_mass_chain.hpp"
#include "support/omega_setup.hpp"
#include "support/pascal_in_physical_units.hpp"

namespace stickslip {
namespace {

Orbit Section41() {
  const PaperPreset& preset = *FindPaperPreset("paper-4.1");
  const Orbit guess = preset.Guess();
  return SolveOrbit(guess, FreeIndices(guess.signature, preset.unknowns), preset.unknowns.tie_static_friction).orbit;
}

// m2 = 1, k1 + k2 = 1, F0 = 1: m1 = eta, lengths scale by eta, time by sqrt(eta).
constexpr PhysicalTwoMasses kUnitTwoMasses{1.0, 1.0, 1.0};

template <typename Model>
void Periodicity(benchmark::State& state, const Model& model, const BasicOrbit<Model>& orbit) {
  const BasicPeriodicityEquations<Model> equations(model, orbit.signature, Shooting::kSingle);
  const Eigen::VectorXd v = VariablesOf(equations, orbit);
  Eigen::VectorXd residual;
  Eigen::MatrixXd jacobian;
  for (auto _ : state) {
    equations.Evaluate(v, &residual, &jacobian);
    benchmark::DoNotOptimize(jacobian.data());
  }
}
template <typename Model>
void Margins(benchmark::State& state, const Model& model, const BasicOrbit<Model>& orbit) {
  for (auto _ : state) benchmark::DoNotOptimize(AdmissibilityMargins(model, orbit));
}
template <typename Model>
void Multipliers(benchmark::State& state, const Model& model, const BasicOrbit<Model>& orbit) {
  for (auto _ : state) benchmark::DoNotOptimize(StabilityOf(model, orbit));
}

void PeriodicityPascal(benchmark::State& state) { Periodicity(state, Pascal2014{}, Section41().OnModel()); }
void PeriodicityGeneral(benchmark::State& state) {
  const Orbit o = Section41();
  Periodicity(state, LinearOscillator<2>(kUnitTwoMasses.Data(o.parameters)), InPhysicalUnits(o, kUnitTwoMasses));
}
void MarginsPascal(benchmark::State& state) { Margins(state, Pascal2014{}, Section41().OnModel()); }
void MarginsGeneral(benchmark::State& state) {
  const Orbit o = Section41();
  Margins(state, LinearOscillator<2>(kUnitTwoMasses.Data(o.parameters)), InPhysicalUnits(o, kUnitTwoMasses));
}
void MultipliersPascal(benchmark::State& state) { Multipliers(state, Pascal2014{}, Section41().OnModel()); }
void MultipliersGeneral(benchmark::State& state) {
  const Orbit o = Section41();
  Multipliers(state, LinearOscillator<2>(kUnitTwoMasses.Data(o.parameters)), InPhysicalUnits(o, kUnitTwoMasses));
}
BENCHMARK(PeriodicityPascal)->Unit(benchmark::kMicrosecond);
BENCHMARK(PeriodicityGeneral)->Unit(benchmark::kMicrosecond);
BENCHMARK(MarginsPascal)->Unit(benchmark::kMicrosecond);
BENCHMARK(MarginsGeneral)->Unit(benchmark::kMicrosecond);
BENCHMARK(MultipliersPascal)->Unit(benchmark::kMicrosecond);
BENCHMARK(MultipliersGeneral)->Unit(benchmark::kMicrosecond);

// Section 4.1's omega family from its orbit upwards, scaled range [0.3, 0.69], through the
// paper's model or the general one in physical units, at a fixed size or sized at run time (the
// same special points and trace chain: tests/branches/linear_oscillator_branch_test.cpp,
// model_trace_test.cpp).
template <OscillatorModel Model>
BasicOrbitContinuationSetup<Model> Section41Family(int max_points) {
  const Orbit o = Section41();
  return OmegaSetup<Model>(InPhysicalUnits<Model>(o, kUnitTwoMasses), Model(kUnitTwoMasses.Data(o.parameters)), 0.3,
                           0.69, kUnitTwoMasses.Omega(o.parameters), max_points);
}
template <>
OrbitContinuationSetup Section41Family<Pascal2014>(int max_points) {
  return OmegaSetup<Pascal2014>(Section41(), {}, 0.3, 0.69, 1.0, max_points);
}

// Elapsed time per 1e-6 accepted points: microseconds per point.
benchmark::Counter MicrosecondsPerPoint(double points) {
  return benchmark::Counter(points * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// The branch's first 20 points (ContinueOrbit).
template <OscillatorModel Model>
void BranchPerPoint(benchmark::State& state) {
  const BasicOrbitContinuationSetup<Model> setup = Section41Family<Model>(20);
  double points = 0.0;
  for (auto _ : state) {
    const BasicOrbitBranch<Model> branch = ContinueOrbit(setup);
    points += static_cast<double>(branch.branch.points.size());
  }
  state.counters["us_per_point"] = MicrosecondsPerPoint(points);
}

// The whole trace (TraceOrbits: both ways, the switch at omega = 0.5999775 confirmed by the
// exact simulator).
template <OscillatorModel Model>
void TracePerPoint(benchmark::State& state) {
  const BasicOrbitContinuationSetup<Model> setup = Section41Family<Model>(3000);
  double points = 0.0, per_trace = 0.0;
  for (auto _ : state) {
    const BasicTraceResult<Model> trace = TraceOrbits(setup);
    per_trace = 0.0;
    for (const BasicTraceDirection<Model>* chain : {&trace.down, &trace.up}) {
      for (const BasicTraceLink<Model>& link : chain->links) per_trace += static_cast<double>(link.branch.orbits.size());
    }
    points += per_trace;
  }
  state.counters["points"] = per_trace;
  state.counters["us_per_point"] = MicrosecondsPerPoint(points);
}
BENCHMARK(BranchPerPoint<Pascal2014>)->Unit(benchmark::kMicrosecond);
BENCHMARK(BranchPerPoint<LinearOscillator<2>>)->Unit(benchmark::kMicrosecond);
BENCHMARK(BranchPerPoint<DynamicLinearOscillator>)->Unit(benchmark::kMicrosecond);
BENCHMARK(TracePerPoint<Pascal2014>)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(TracePerPoint<LinearOscillator<2>>)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(TracePerPoint<DynamicLinearOscillator>)->UseRealTime()->Unit(benchmark::kMillisecond);

// The five-mass chain (support/five_mass_chain.hpp) traced over a decade of the forcing frequency,
// omega in [0.15, 1.5], from the orbit its motion settles on at omega = 0.6 (the general-oscillator
// issue's goal: under a second on one core).
void FiveMassTrace(benchmark::State& state) {
  const DynamicLinearOscillator model = FiveMassChain();
  const BasicOrbit<DynamicLinearOscillator> start = SettledOrbit(model, {0.6, 0.3, 0.4, 0.0}, 300);
  const BasicOrbitContinuationSetup<DynamicLinearOscillator> setup =
      OmegaSetup<DynamicLinearOscillator>(start, model, 0.15, 1.5, 1.0, 3000);
  double points = 0.0;
  for (auto _ : state) {
    const BasicTraceResult<DynamicLinearOscillator> trace = TraceOrbits(setup);
    points = 0.0;
    for (const BasicTraceDirection<DynamicLinearOscillator>* chain : {&trace.down, &trace.up}) {
      for (const BasicTraceLink<DynamicLinearOscillator>& link : chain->links) {
        points += static_cast<double>(link.branch.orbits.size());
      }
    }
  }
  state.counters["points"] = points;
}
BENCHMARK(FiveMassTrace)->UseRealTime()->Unit(benchmark::kMillisecond);

// n unit masses in a chain, unit springs between neighbours and from the first to the ground,
// forced on the first, the contact on the last; an orbit-like point of "slip- stick / antisymmetric"
// (the cost does not depend on the point being a solution). Size = Eigen::Dynamic: the same chain
// sized at run time (DynamicLinearOscillator, a model from a file).
template <int N, int Size = N>
void Chain(benchmark::State& state) {
  using Model = LinearOscillator<Size>;
  LinearOscillatorData data;
  data.mass = Eigen::MatrixXd::Identity(N, N);
  data.stiffness = Eigen::MatrixXd::Zero(N, N);
  for (int i = 0; i < N; ++i) data.stiffness(i, i) = i + 1 < N ? 2.0 : 1.0;
  for (int i = 0; i + 1 < N; ++i) data.stiffness(i, i + 1) = data.stiffness(i + 1, i) = -1.0;
  data.forcing = Eigen::VectorXd::Unit(N, 0);
  const Model model(data);
  BasicOrbit<Model> orbit{Signature::Parse("slip- stick / antisymmetric"), {0.777, 0.05, 0.08}, {}, 0.3, {2.0, 1.5}};
  orbit.start = FilledState(model, 0.0);
  for (int i = 0; i < N; ++i) orbit.start(i) = 0.1 * (i + 1);
  if (model.Validate(orbit.parameters)) {
    state.SkipWithError("omega on a natural frequency");
    return;
  }
  if (state.range(0) == 0) Periodicity(state, model, orbit);
  if (state.range(0) == 1) Margins(state, model, orbit);
}
BENCHMARK(Chain<1>)->ArgName("margins")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(Chain<2>)->ArgName("margins")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(Chain<5>)->ArgName("margins")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK(Chain<10>)->ArgName("margins")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(Chain, 2, Eigen::Dynamic)->ArgName("margins")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(Chain, 5, Eigen::Dynamic)->ArgName("margins")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(Chain, 10, Eigen::Dynamic)->ArgName("margins")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(Chain, 20, Eigen::Dynamic)->ArgName("margins")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK_TEMPLATE(Chain, 50, Eigen::Dynamic)->ArgName("margins")->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// The atlas of section 4.1's data over omega in [0.3, 0.95] on its 66 grid values (as
// results/atlases/paper-4.1-omega), on every core: the paper's (ComputeAtlas) and the same masses as
// an oscillator of the user's in physical units (ComputeModelAtlas), the wall time split into its
// three stages (brute force, exact orbits, traces) by when each stage's last progress report came.
class StageClock {
 public:
  using Clock = std::chrono::steady_clock;
  ProgressCallback Callback() {
    return [this](const Progress& p) {
      const std::lock_guard<std::mutex> lock(mutex_);
      last_[p.unit] = Clock::now();
    };
  }
  // Seconds from `from` to the last report of `unit` (`from` itself where there was none).
  Clock::time_point Last(const std::string& unit, Clock::time_point from) const {
    const auto it = last_.find(unit);
    return it == last_.end() ? from : it->second;
  }

 private:
  std::mutex mutex_;
  std::map<std::string, Clock::time_point> last_;
};

void ReportStages(benchmark::State& state, StageClock::Clock::time_point start, StageClock::Clock::time_point end,
                  const StageClock& clock, const char* brute_unit) {
  const auto brute = clock.Last(brute_unit, start), finds = clock.Last("attractors solved", brute);
  const auto seconds = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
  state.counters["brute_force_s"] = seconds(start, brute);
  state.counters["finds_s"] = seconds(brute, finds);
  state.counters["traces_s"] = seconds(finds, end);
}

template <typename Compute>
void AtlasStages(benchmark::State& state, Compute compute, const char* brute_unit) {
  for (auto _ : state) {
    StageClock clock;
    const auto start = StageClock::Clock::now();
    const auto counts = compute(clock.Callback());
    const auto end = StageClock::Clock::now();
    state.SetIterationTime(std::chrono::duration<double>(end - start).count());
    ReportStages(state, start, end, clock, brute_unit);
    state.counters["attractors"] = counts.first;
    state.counters["on_branches"] = counts.second;
  }
}

void PaperAtlas(benchmark::State& state) {
  AtlasStages(state, [](ProgressCallback progress) {
    AtlasOptions o;
    o.brute_force.first = {ParameterId::kOmega, 0.3, 0.95, 65};
    o.progress = std::move(progress);
    const Atlas atlas = ComputeAtlas(Section41().parameters, o);
    return std::pair{static_cast<double>(atlas.attractors.size()), static_cast<double>(atlas.OnBranches())};
  }, "cells");
}
void ModelAtlasOfTheSameMasses(benchmark::State& state) {
  AtlasStages(state, [](ProgressCallback progress) {
    const Orbit o = Section41();
    ModelAtlasOptions options;
    options.from = 0.3 * kUnitTwoMasses.Omega(o.parameters);  // the model's time is not the paper's scaled one
    options.to = 0.95 * kUnitTwoMasses.Omega(o.parameters);
    options.steps = 65;
    options.brute_force.scatter = kUnitTwoMasses.Length(o.parameters);
    options.progress = std::move(progress);
    const DynamicLinearOscillator model(kUnitTwoMasses.Data(o.parameters));
    const ModelAtlas atlas = ComputeModelAtlas(model, kUnitTwoMasses.Of<DynamicLinearOscillator>(o.parameters), options);
    return std::pair{static_cast<double>(atlas.attractors.size()), static_cast<double>(atlas.OnBranches())};
  }, "points");
}
BENCHMARK(PaperAtlas)->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(ModelAtlasOfTheSameMasses)->UseManualTime()->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
}  // namespace stickslip

BENCHMARK_MAIN();
