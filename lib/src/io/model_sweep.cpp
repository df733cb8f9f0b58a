#include "stickslip/io/model_sweep.hpp"

#include <cstdint>
#include <numbers>
#include <utility>

#include "stickslip/numerics/parallel_for.hpp"

namespace stickslip {

ModelSweepRun SweepModel(const ModelFileStart& start, const SweepCommand& command, ProgressCallback progress) {
  const SweepPlan plan = PlanSweep(command, start.model.Description());
  ModelSweepRun run{start.model, plan.options, plan.chains, 1, 0.0, {}};
  run.options.progress = std::move(progress);
  // In the model's own units: the section's repeat tolerance relative to its states' size; short
  // transient chunks, whose events (each of the model's size) are held at once.
  run.options.relative_tolerance = true;
  run.options.chunk_periods = kModelChunkPeriods;
  // Without forcing, the slowest free oscillation of its slip is the time unit (as find's).
  run.options.time_unit = 2.0 * std::numbers::pi / start.slowest_frequency;
  const int items = run.options.start == SweepStart::kChained ? run.chains : run.chains * (run.options.steps + 1);
  run.threads = WorkerCount(run.options.threads, items);
  run.points = Sweep(start.model, start.parameters, ScatteredStarts(start.state, plan.scatter, plan.chains, plan.seed),
                     start.phi, run.options);
  run.phi = start.phi;
  run.options.progress = {};
  return run;
}

std::string ModelSweepCsv(const ModelSweepRun& run) {
  return SweepCsv(run.model, run.points, run.options.parameter, run.phi);
}

}  // namespace stickslip
