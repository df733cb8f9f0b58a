// What a run file's [model] (model_table.hpp) is, as `stickslip describe` shows it and the Python
// module's describe returns it: the table, the oscillator's data and modes, its description
// (coordinates, parameters with units and ranges), each parameter's value where the table gives it,
// and the free oscillations of its slip and of its stick; and the same as one JSON object.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "stickslip/io/model_table.hpp"
#include "stickslip/model/free_oscillations.hpp"
#include "stickslip/model/linear_oscillator_data.hpp"

namespace stickslip {

struct ModelSummary {
  ModelTable table;
  LinearOscillatorData data;
  LinearOscillatorModes modes;
  ModelDescription description;
  std::vector<std::optional<double>> values;  // GivenParameters
  std::vector<FreeOscillation> slip;          // the slip's free oscillations
  std::vector<FreeOscillation> stick;         // the stick's (the contact's coordinate held)

  bool Autonomous() const { return data.forcing.isZero(); }
};

// Throws RunFileError as ReadModelTable, ModelDataOf and GivenParameters do, and, where the table
// gives F_k, F_s and (forced) omega, as ParametersOf does.
ModelSummary SummarizeModel(const std::filesystem::path& run_file);

// One JSON object: model, kind, coordinates, contact, forcing (per coordinate), friction_slope,
// parameters (name, meaning, unit, minimum, maximum, range, value or null), autonomous,
// free_oscillations (slip, stick: frequency, damping_ratio, oscillates) and start_state.
std::string ModelSummaryJson(const ModelSummary& summary);

}  // namespace stickslip
