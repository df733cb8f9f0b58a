// trace for a run file's [model] (model_table.hpp), as every front end runs it: the orbit the motion
// from rest settles on (model_find.hpp), then the chain of its branches in one of the model's
// parameters over [low, high] through every change of orbit type, both ways (branches/trace.hpp);
// and the trace as one JSON object. Its result files are any trace's (io/trace_files.hpp,
// RecordTrace of the model).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "stickslip/branches/trace.hpp"
#include "stickslip/io/model_find.hpp"
#include "stickslip/io/trace_files.hpp"

namespace stickslip {

struct ModelTraceRun {
  ModelFindRun find;
  std::optional<BasicTraceResult<DynamicLinearOscillator>> trace;  // where the find found an orbit
};

// `steps`: every branch's. Throws InvalidInput (naming "parameter" for a name that is not one of the
// model's parameters, or omega without forcing; "range" for low >= high or one that does not hold
// the start's value; as CheckSteps for the steps) before any work, and as FindModelOrbitOf and
// TraceOrbits do.
ModelTraceRun TraceModel(const ModelFileStart& start, int transients, int max_multiple, const std::string& parameter,
                         double low, double high, TraceOptions options = {}, const BranchSteps& steps = {});

// The stored form of run.trace (set) as every front end writes it (RecordTrace, trace_files.hpp):
// its run file `run_file`, or "(command line)" where `set` changed what the file gives; and the
// model's slip's natural frequencies (its oscillating free modes', as describe lists them, read with
// the model: ModelFindRun::slip_frequencies), which a figure over omega marks.
StoredTrace StoredModelTrace(const ModelTraceRun& run, const std::filesystem::path& run_file, const NamedValues& set,
                             const std::string& output);

// parameter, start (find's JSON: model_orbit_json.hpp), completed, and per direction ("down",
// "up") its end, message and branches: signature, direction, start, margin, end, message and
// points, each the parameter's value by its name, the orbit's period, the branch's columns by name
// (margins, floquet multipliers and tests, stable, admissible, the measures: amplitude:<coordinate>,
// ...) and the durations. Non-finite numbers are null.
std::string ModelTraceJson(const ModelTraceRun& run);

}  // namespace stickslip
