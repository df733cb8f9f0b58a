// From a simulated motion to its exact periodic orbit, for any model with equations of motion to
// integrate (model/integrable_oscillator_model.hpp): the orbit the motion settles on
// (settled_orbit.hpp) solved at fixed parameters, its margins, Floquet multipliers and measures,
// and its verification by both simulators (the exact one and Odeint's integration of the equations
// of motion, which shares no flow or event code with the closed forms). The paper's model has its
// own finder (orbit_finder.hpp: section-based period detection, subharmonics); this one takes the
// forcing's period (or, without forcing, the stick-slip cycle's) and says so when the motion has
// not settled onto it.
//
//   ModelFindOptions options;
//   options.duration = 300 * 2 * pi / p.omega;
//   options.record = 10 * 2 * pi / p.omega;
//   const ModelFindResult<Model> r = FindModelOrbit(model, p, options);
//   if (r.status == FindOrbitStatus::kFound) use(r.solution->orbit, *r.stability, *r.measures);
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "stickslip/analysis/orbit_finder.hpp"  // FindOrbitStatus
#include "stickslip/analysis/settled_orbit.hpp"
#include "stickslip/model/exact_simulator.hpp"
#include "stickslip/orbits/linear_oscillator_problem.hpp"
#include "stickslip/model/odeint_simulation.hpp"
#include "stickslip/orbits/least_period.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/model_orbit_solver.hpp"
#include "stickslip/orbits/orbit_measures.hpp"
#include "stickslip/orbits/stability.hpp"
#include "stickslip/orbits/verification.hpp"

namespace stickslip {

struct ModelFindOptions {
  double duration = 0.0;  // the model's time simulated from x0, > 0
  double record = 0.0;    // the last part of it the period is read from (settled_orbit.hpp); 0: all
  double phi0 = 0.0;      // the forcing's phase at t = 0
  // A forced model's longest period read, in forcing periods (1 to kMaxMultiple): the least k that
  // is one is taken (settled_orbit.hpp). The record must hold 2 max_multiple forcing periods.
  int max_multiple = 1;
  static constexpr int kMaxMultiple = 20;
  OrbitSolverOptions solver;
  ProgressCallback progress = {};  // the simulation's (model/simulation.hpp)
};

template <OscillatorModel Model>
struct ModelFindResult {
  FindOrbitStatus status = FindOrbitStatus::kNoOrbitType;
  std::string message;
  std::optional<BasicOrbit<Model>> guess;  // read off the simulated motion (at its least period)
  std::optional<BasicOrbitSolution<Model>> solution;
  // Where Newton converged:
  std::vector<Margin> margins;
  std::optional<BasicStability<Model::kStateSize>> stability;
  std::optional<BasicOrbitMeasures> measures;
  std::optional<Verification> verification;
};

// Whether the motion `r` was read off had not settled on a period (settled_orbit.hpp's messages
// say so: a "no orbit type" that a longer simulation may turn into an orbit).
template <OscillatorModel Model>
bool MotionNotSettled(const ModelFindResult<Model>& r) {
  return r.status == FindOrbitStatus::kNoOrbitType && r.message.find("not settled") != std::string::npos;
}

// Whether a longer simulation may find what `r` did not: a motion not settled, or a stick or a
// stick-slip cycle that outlasted the time read ("simulate longer").
template <OscillatorModel Model>
bool LongerMayFind(const ModelFindResult<Model>& r) {
  return MotionNotSettled(r) ||
         (r.status == FindOrbitStatus::kNoOrbitType && r.message.find("simulate longer") != std::string::npos);
}

// The orbit's verification by the model's exact simulator and by Odeint's, both relative to the
// orbit's size (OrbitSize): Odeint's absolute tolerance and the mismatches' thresholds scale with it,
// so that the same motion in other units (forces times 1e-7 or 1e7) verifies the same.
template <IntegrableOscillatorModel Model>
Verification VerifyByBothSimulators(const Model& model, const BasicOrbit<Model>& orbit) {
  using ModelState = typename Model::State;
  const double size = OrbitSize(model, orbit);
  OdeintOptions odeint;
  odeint.absolute_tolerance *= size;
  auto exact = [](const Model& m, const typename Model::Parameters& p, const ModelState& x0, double phi,
                  const BasicSimulationOptions<ModelState>& options) { return SimulateExact(m, p, x0, phi, options); };
  auto integrated = [&odeint](const Model& m, const typename Model::Parameters& p, const ModelState& x0, double phi,
                              const BasicSimulationOptions<ModelState>& options) {
    return SimulateOdeint(m, p, x0, phi, options, odeint);
  };
  Verification v = VerifyOrbit(model, orbit, exact, integrated);
  v.scale = size;
  return v;
}

// `r` with its converged orbit's margins, stability, measures and verification, and its status:
// found where every margin is positive and both simulators follow it.
template <IntegrableOscillatorModel Model>
ModelFindResult<Model> CheckedModelOrbit(const Model& model, ModelFindResult<Model> r) {
  const BasicOrbit<Model>& orbit = r.solution->orbit;
  r.margins = AdmissibilityMargins(model, orbit);
  r.stability = StabilityOf(model, orbit);
  r.measures = Measure(model, orbit);
  r.verification = VerifyByBothSimulators(model, orbit);
  const Margin smallest = SmallestMargin(r.margins);
  if (!(smallest.value > 0.0) || !r.verification->Passed()) {
    r.status = FindOrbitStatus::kNotAMotion;
    r.message = smallest.value > 0.0 ? "the orbit fails its verification by simulation"
                                     : fmt::format("the orbit is no motion of the system: margin {} = {:.6g}",
                                                   smallest.Name(), smallest.value);
    return r;
  }
  r.status = FindOrbitStatus::kFound;
  return r;
}

// r with r.guess solved into r.solution, every start variable, the phase and the durations unknown (the
// parameters held); where it cannot be or did not converge, with the status and the message why.
template <IntegrableOscillatorModel Model>
ModelFindResult<Model> SolvedAtFixedParameters(const Model& model, const ModelFindOptions& options,
                                               ModelFindResult<Model> r) {
  // At the given parameters: an abnormal stop (which the periodicity equations pay for with a
  // released friction level, UnknownsAtFixedParameters) makes the system not square.
  std::vector<int> free;
  try {
    free = FreeIndices(VariableSetOf(model, r.guess->signature), UnknownChoice{});
  } catch (const InvalidInput&) {
    r.status = FindOrbitStatus::kNoOrbitType;
    r.message = fmt::format("the motion's period '{}' has an abnormal stop (a stop without reversal or stick), whose "
                             "orbit is solved only with a friction level released: not at the given parameters",
                             r.guess->signature.ToString());
    return r;
  }
  // Newton's residual mixes units (states, velocities, forces at a stick's exit, times): its
  // tolerances widen with a large orbit, whose rounding floor grows with it (forces of meganewtons),
  // and are never tighter than the default (the times' floor does not shrink with a small orbit,
  // whose verification, relative to its size, judges it).
  OrbitSolverOptions solver = options.solver;
  const double size = std::max(1.0, OrbitSize(model, *r.guess));
  solver.newton.residual_tolerance *= size;
  solver.newton.stagnation_residual *= size;
  r.solution = SolveOrbit(model, *r.guess, free, false, solver);
  if (!r.solution->summary.Converged()) {
    r.status = FindOrbitStatus::kSolveFailed;
    r.message = fmt::format("Newton did not converge from the simulated '{}': {}", r.guess->signature.ToString(),
                             r.solution->summary.BriefReport());
    return r;
  }
  return r;
}

// Simulates from x0 (options.duration > 0), solves the orbit read off the motion's last period with
// every start variable, the phase and the durations unknown (the parameters held), and checks it.
template <IntegrableOscillatorModel Model>
ModelFindResult<Model> FindModelOrbit(const Model& model, const typename Model::Parameters& p,
                                      const typename Model::State& x0, const ModelFindOptions& options) {
  ModelFindResult<Model> r;
  const double record = options.record > 0.0 ? options.record : options.duration;
  SettledOrbitGuess<Model> settled =
      SettledOrbitGuessOf(model, p, x0, options.duration, record, options.phi0, options.progress, options.max_multiple);
  if (!settled.orbit) {
    r.status = settled.message.starts_with("the simulation") ? FindOrbitStatus::kSimulationIncomplete
                                                             : FindOrbitStatus::kNoOrbitType;
    r.message = std::move(settled.message);
    return r;
  }
  r.guess = settled.orbit;
  r = SolvedAtFixedParameters(model, options, std::move(r));
  if (!r.message.empty()) return r;
  // A motion still contracting onto an orbit of period d, with a multiplier near a (k/d)-th root of
  // unity, repeats to tolerance after k > d forcing periods first: the orbit solved over k periods is
  // the period-d one written k/d times. Reduced to its least period and solved there.
  const BasicLeastPeriodOrbit<Model> least = ReduceToLeastPeriod(model, r.solution->orbit);
  if (least.status == LeastPeriodStatus::kReduced) {
    ModelFindResult<Model> reduced = r;
    reduced.guess = least.orbit;
    reduced = SolvedAtFixedParameters(model, options, std::move(reduced));
    if (reduced.message.empty()) r = std::move(reduced);  // else the orbit as read, over k periods
  }
  return CheckedModelOrbit(model, std::move(r));
}

// A model whose size comes with its data (a user's [model]): compiled once, in model_orbit_finder.cpp.
extern template Verification VerifyByBothSimulators(const DynamicLinearOscillator& model,
                                                    const BasicOrbit<DynamicLinearOscillator>& orbit);
extern template ModelFindResult<DynamicLinearOscillator> FindModelOrbit(const DynamicLinearOscillator& model,
                                                                        const DynamicLinearOscillator::Parameters& p,
                                                                        const DynamicLinearOscillator::State& x0,
                                                                        const ModelFindOptions& options);

}  // namespace stickslip
