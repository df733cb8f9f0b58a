#include "stickslip/io/model_trace.hpp"

#include <cmath>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "json_number.hpp"

#include "stickslip/branches/model_trace.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/model_restart.hpp"
#include "stickslip/io/model_orbit_json.hpp"
#include "stickslip/orbits/any_orbit.hpp"
#include "stickslip/orbits/signature_edits.hpp"

namespace stickslip {

namespace {

using Model = DynamicLinearOscillator;
using Json = nlohmann::ordered_json;

Json BranchJson(const BasicTraceLink<Model>& link, const Model& model, const std::string& parameter) {
  Json points = Json::array();
  const BasicOrbitBranch<Model>& b = link.branch;
  for (std::size_t i = 0; i < b.branch.points.size(); ++i) {
    Json point{{parameter, b.branch.points[i].lambda}};
    point["period"] = PeriodOf(model, AsBasicOrbit(b.orbits[i]));
    const std::vector<double> values = ColumnValues(b.columns, b.branch.points[i]);
    for (std::size_t k = 0; k < b.columns.size(); ++k) point[b.columns[k].name] = detail::JsonNumber(values[k]);
    point["durations"] = b.orbits[i].durations;
    points.push_back(std::move(point));
  }
  return {{"signature", link.signature}, {"direction", link.direction > 0 ? "up" : "down"},
          {"start", ToString(link.start)}, {"margin", link.margin},
          {"end", ToString(link.end)},     {"message", link.message},
          {"points", std::move(points)}};
}

}  // namespace

ModelTraceRun TraceModel(const ModelFileStart& start, int transients, int max_multiple, const std::string& parameter,
                         double low, double high, TraceOptions options, const BranchSteps& steps) {
  // The parameter and the range before the work.
  const int k = start.model.Description().VariedParameter("parameter", parameter, start.model.Autonomous());
  const double value = Model::ParameterAt(start.parameters, k);
  if (!(std::isfinite(low) && std::isfinite(high) && low < high) || !(low <= value && value <= high)) {
    throw InvalidInput("range", fmt::format("'{},{}'", low, high),
                       fmt::format("finite LO < HI with LO <= {} = {} <= HI, the start's", parameter, value));
  }
  options.Validate();
  CheckSteps(steps);
  ContinuationOptions continuation = WithSteps({}, steps);
  continuation.lambda_min = low;
  continuation.lambda_max = high;
  ModelTraceRun run{FindModelOrbitOf(start, transients, max_multiple, options.progress), std::nullopt};
  if (run.find.found.status != FindOrbitStatus::kFound) return run;
  BasicOrbitContinuationSetup<Model> setup{ContinuableIn(run.find.found.solution->orbit, k),
                                           {},
                                           parameter,
                                           ShootingChoice::kAuto,
                                           LinearSolverType::kKlu,
                                           continuation,
                                           {}, {}, {},
                                           kDefaultMaxAmplitude,
                                           kDefaultResonanceApproach,
                                           run.find.model};
  run.trace = TraceOrbits(setup, options);
  return run;
}

StoredTrace StoredModelTrace(const ModelTraceRun& run, const std::filesystem::path& run_file, const NamedValues& set,
                             const std::string& output) {
  StoredTrace stored = RecordTrace(run.find.model,
                                   StoredSummary{.run_file = set.empty() ? run_file.string() : std::string(kOneOffRunPath),
                                                 .output = output,
                                                 .parameter = run.trace->parameter},
                                   *run.trace);
  stored.natural_frequencies = run.find.slip_frequencies;
  return stored;
}

std::string ModelTraceJson(const ModelTraceRun& run) {
  Json out{{"parameter", run.trace ? Json(run.trace->parameter) : Json(nullptr)},
           {"start", Json::parse(ModelFindJson(run.find.model, run.find.found))},
           {"completed", run.trace && run.trace->Completed()}};
  if (!run.trace) return out.dump();
  for (const BasicTraceDirection<Model>* chain : {&run.trace->down, &run.trace->up}) {
    Json branches = Json::array();
    for (const BasicTraceLink<Model>& link : chain->links) branches.push_back(BranchJson(link, run.find.model, run.trace->parameter));
    out[chain->direction > 0 ? "up" : "down"] = {
        {"end", ToString(chain->end)}, {"message", chain->message}, {"branches", std::move(branches)}};
  }
  return out.dump();
}

}  // namespace stickslip
