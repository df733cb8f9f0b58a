#include "stickslip/analysis/model_brute_force_map.hpp"

#include <mutex>
#include <optional>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/numerics/fingerprint.hpp"

namespace stickslip {

namespace {

using Model = DynamicLinearOscillator;

Model::Parameters CellParameters(const Model& model, const Model::Parameters& base, const ModelBruteForceMapOptions& o,
                                 int i, int j) {
  Model::Parameters p = base;
  Model::ParameterAt(p, o.first.IndexIn(model, "first")) = o.first.ValueAt(i);
  Model::ParameterAt(p, o.second.IndexIn(model, "second")) = o.second.ValueAt(j);
  return p;
}

void CheckCount(const std::string& field, long long value, long long low, long long high) {
  if (value < low || value > high) {
    throw InvalidInput(field, std::to_string(value), fmt::format("whole numbers {} <= {} <= {}", low, field, high));
  }
}

std::vector<int> RowsOf(const ModelBruteForceMapOptions& o) {
  std::vector<int> rows;
  for (int j = 0; j < o.second.Count(); ++j) {
    if (RowInShard(j, o.shard, o.shards)) rows.push_back(j);
  }
  return rows;
}

}  // namespace

void ModelBruteForceMapOptions::Validate(const Model& model, const Model::Parameters& base) const {
  for (const auto& [name, axis] : {std::pair{"first", &first}, std::pair{"second", &second}}) {
    axis->IndexIn(model, name);
    if (!(std::isfinite(axis->from) && std::isfinite(axis->to))) {
      throw InvalidInput(fmt::format("{}-from", name), fmt::format("{},{}", axis->from, axis->to), "finite numbers");
    }
  }
  CheckCount("first-steps", first.steps, 1, kMaxSteps);  // a row's chained sweep has two values at least
  CheckCount("second-steps", second.steps, 0, kMaxSteps);
  if (first.parameter == second.parameter) {
    throw InvalidInput("second", "'" + second.parameter + "'", fmt::format("a parameter other than first '{}'", first.parameter));
  }
  runs.Validate(model);
  CheckCount("shards", shards, 1, kMaxShards);
  CheckCount("shard", shard, 1, shards);
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
      if (const std::optional<InvalidInput> invalid = model.Validate(CellParameters(model, base, *this, i, j))) {
        throw InvalidInput::WithMessage(
            "grid", fmt::format("grid cell (i, j) = ({}, {}) at {} = {}, {} = {} is invalid: {}", i, j, first.parameter,
                                first.ValueAt(i), second.parameter, second.ValueAt(j), invalid->what()));
      }
    }
  }
}

std::uint64_t ModelMapRunFingerprint(const Model& model, const Model::Parameters& base, const ModelBruteForceMapOptions& o) {
  Fingerprint hash;
  const LinearOscillatorData data = model.Data();
  for (const Eigen::MatrixXd* m : {&data.mass, &data.damping, &data.stiffness}) {
    hash.Add(static_cast<std::uint64_t>(m->rows()));
    for (Eigen::Index k = 0; k < m->size(); ++k) hash.AddNumber(m->data()[k]);
  }
  for (Eigen::Index k = 0; k < data.forcing.size(); ++k) hash.AddNumber(data.forcing(k));
  hash.AddNumber(data.friction_slope);
  for (int k = 0; k < model.Description().ParameterCount(); ++k) hash.AddNumber(Model::ParameterAt(base, k));
  for (const ModelAxis* axis : {&o.first, &o.second}) {
    for (const char c : axis->parameter) hash.Add(static_cast<unsigned char>(c));
    hash.AddNumber(axis->from);
    hash.AddNumber(axis->to);
    hash.Add(static_cast<std::uint64_t>(axis->steps));
  }
  const ModelBruteForceOptions& r = o.runs;
  for (const long long count : {r.transient_periods, r.recorded_periods, r.scattered_starts}) {
    hash.Add(static_cast<std::uint64_t>(count));
  }
  for (Eigen::Index k = 0; k < r.centre.size(); ++k) hash.AddNumber(r.centre(k));
  for (const double x : {r.scatter, r.periodicity_tolerance, r.time_unit, r.section_phase}) hash.AddNumber(x);
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
  const double total = static_cast<double>(rows.size()) * o.first.Count() * o.runs.RunsPerValue();
  const int second = o.second.IndexIn(model, "second");
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const int j = rows[r];
    ModelBruteForceOptions row = o.runs;
    if (o.runs.progress) {
      const double before = static_cast<double>(r) * o.first.Count() * o.runs.RunsPerValue();
      row.progress = [&o, before, total](const Progress& p) { o.runs.progress({before + p.done, total, "runs", p.value}); };
    }
    Model::Parameters p = base;
    Model::ParameterAt(p, second) = o.second.ValueAt(j);
    std::vector<std::vector<ModelAttractor>> cells = ModelBruteForce(model, p, o.first, row);
    for (int i = 0; i < o.first.Count(); ++i) {
      map.cells.push_back({i, j, o.first.ValueAt(i), o.second.ValueAt(j), std::move(cells[i])});
    }
  }
  return map;
}

}  // namespace stickslip
