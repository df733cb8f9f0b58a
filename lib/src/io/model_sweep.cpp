#include "stickslip/io/model_sweep.hpp"

#include <cstdint>
#include <utility>

#include "stickslip/numerics/parallel_for.hpp"

namespace stickslip {

ModelSweepRun SweepModel(const ModelFileStart& start, const SweepCommand& command, ProgressCallback progress) {
  const SweepPlan plan = PlanSweep(command, start.model.Description());
  ModelSweepRun run{start.model, plan.options, plan.chains, 1, {}};
  run.options.progress = std::move(progress);
  const int items = run.options.start == SweepStart::kChained ? run.chains : run.chains * (run.options.steps + 1);
  run.threads = WorkerCount(run.options.threads, items);
  const Eigen::VectorXd rest = Eigen::VectorXd::Zero(start.model.StateSize());
  run.points = Sweep(start.model, start.parameters, ScatteredStarts(rest, plan.scatter, plan.chains, plan.seed), 0.0,
                     run.options);
  run.options.progress = {};
  return run;
}

std::string ModelSweepCsv(const ModelSweepRun& run) {
  return SweepCsv(run.model, run.points, run.options.parameter, 0.0);
}

}  // namespace stickslip
