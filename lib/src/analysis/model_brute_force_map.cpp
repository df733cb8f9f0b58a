#include "stickslip/analysis/model_brute_force_map.hpp"

#include <algorithm>
#include <limits>
#include <mutex>
#include <optional>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/numerics/fingerprint.hpp"
#include "stickslip/numerics/parallel_for.hpp"

namespace stickslip {

namespace {

using Model = DynamicLinearOscillator;

std::vector<int> RowsOf(const ModelBruteForceMapOptions& o) {
  std::vector<int> rows;
  for (int j = 0; j < o.second.Count(); ++j) {
    if (RowInShard(j, o.shard, o.shards)) rows.push_back(j);
  }
  return rows;
}

}  // namespace

void ModelBruteForceMapOptions::Validate(const Model& model, const Model::Parameters& base) const {
  const int i_parameter = first.IndexIn(model, "first"), j_parameter = second.IndexIn(model, "second");
  for (const auto& [name, axis] : {std::pair{"first", &first}, std::pair{"second", &second}}) {
    if (!std::isfinite(axis->from)) throw InvalidInput(fmt::format("{}-from", name), axis->from, "a finite number");
    if (!std::isfinite(axis->to - axis->from)) {  // every value between them finite
      throw InvalidInput(fmt::format("{}-to", name), axis->to, fmt::format("a finite number within 1e308 of {}-from", name));
    }
  }
  WholeNumber("first-steps", first.steps, 1, kMaxSteps);  // a row's chained sweep has two values at least
  WholeNumber("second-steps", second.steps, 0, kMaxSteps);
  if (first.parameter == second.parameter) {
    throw InvalidInput("second", "'" + second.parameter + "'", fmt::format("a parameter other than first '{}'", first.parameter));
  }
  runs.Validate(model);
  WholeNumber("shards", shards, 1, kMaxShards);
  WholeNumber("shard", shard, 1, shards);
  const long long rows = static_cast<long long>(RowsOf(*this).size());
  const long long total = rows * first.Count() * runs.RunsPerValue();
  if (total > kMaxRuns) {
    throw InvalidInput("grid", fmt::format("{} runs ({} rows of {} cells, {} runs a cell)", total, rows, first.Count(),
                                           runs.RunsPerValue()),
                       fmt::format("at most {} runs in one shard (fewer cells or starts, or more shards)", kMaxRuns));
  }
  // Every cell, not only the corners: a natural frequency or F_s >= F_k may depend on both.
  for (int j = 0; j < second.Count(); ++j) {
    for (int i = 0; i < first.Count(); ++i) {
      Model::Parameters p = base;
      Model::ParameterAt(p, i_parameter) = first.ValueAt(i);
      Model::ParameterAt(p, j_parameter) = second.ValueAt(j);
      if (const std::optional<InvalidInput> invalid = model.Validate(p)) {
        throw InvalidInput::WithMessage(
            "grid", fmt::format("grid cell (i, j) = ({}, {}) at {} = {}, {} = {} is invalid: {}", i, j, first.parameter,
                                first.ValueAt(i), second.parameter, second.ValueAt(j), invalid->what()));
      }
    }
  }
}

std::uint64_t ModelMapRunFingerprint(const Model& model, const Model::Parameters& base, const ModelBruteForceMapOptions& o) {
  Fingerprint hash;
  model.Data().AddTo(hash);
  for (int k = 0; k < model.Description().ParameterCount(); ++k) hash.AddNumber(Model::ParameterAt(base, k));
  for (const ModelAxis* axis : {&o.first, &o.second}) {
    hash.AddText(axis->parameter);
    hash.AddNumber(axis->from);
    hash.AddNumber(axis->to);
    hash.Add(static_cast<std::uint64_t>(axis->steps));
  }
  const ModelBruteForceOptions& r = o.runs;
  for (const long long count : {r.transient_periods, r.recorded_periods, r.scattered_starts}) {
    hash.Add(static_cast<std::uint64_t>(count));
  }
  for (Eigen::Index k = 0; k < r.centre.size(); ++k) hash.AddNumber(r.centre(k));
  for (const double x : {r.scatter, r.periodicity_tolerance, r.section_phase}) hash.AddNumber(x);
  // Only where it counts: from an eigen-solve, it may differ in its last bits between builds.
  if (model.Autonomous()) hash.AddNumber(r.time_unit);
  hash.Add(r.seed);
  return hash.Value();
}

ModelBruteForceMap ComputeModelBruteForceMap(const Model& model, const Model::Parameters& base,
                                             const ModelBruteForceMapOptions& o) {
  o.Validate(model, base);
  ModelBruteForceMap map{.first = o.first.parameter,
                         .second = o.second.parameter,
                         .contact = model.Description().coordinates[model.Contact()],
                         .state_columns = model.Description().state_columns,
                         .first_count = o.first.Count(),
                         .second_count = o.second.Count(),
                         .section_phase = o.runs.section_phase,
                         .run = ModelMapRunFingerprint(model, base, o)};
  const std::vector<int> rows = RowsOf(o);
  const int count = static_cast<int>(rows.size());
  // Rows side by side, the threads left over inside each (a row's chained sweep is one work item).
  const int outer = WorkerCount(o.runs.threads, count);
  const int inner = std::max(1, WorkerCount(o.runs.threads, std::numeric_limits<int>::max()) / std::max(1, outer));
  const double total = static_cast<double>(count) * o.first.Count() * o.runs.RunsPerValue();
  const int second = o.second.IndexIn(model, "second");
  std::vector<std::vector<std::vector<ModelAttractor>>> computed(rows.size());
  std::mutex report;
  double done = 0.0;
  ParallelFor(count, outer, [&](int r) {
    ModelBruteForceOptions row = o.runs;
    row.threads = inner;
    row.progress = {};
    if (o.progress) {
      row.progress = [&](const Progress& p) {
        const std::lock_guard<std::mutex> lock(report);
        o.progress({done += 1.0, total, "runs", p.value});
      };
    }
    Model::Parameters p = base;
    Model::ParameterAt(p, second) = o.second.ValueAt(rows[r]);
    computed[r] = ModelBruteForce(model, p, o.first, row);
  });
  for (int r = 0; r < count; ++r) {
    for (int i = 0; i < o.first.Count(); ++i) {
      map.cells.push_back({i, rows[r], o.first.ValueAt(i), o.second.ValueAt(rows[r]), std::move(computed[r][i])});
    }
  }
  return map;
}

}  // namespace stickslip
