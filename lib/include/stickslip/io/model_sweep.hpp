// sweep for a run file's [model] (model_table.hpp), as every front end runs it: the brute-force
// bifurcation diagram (analysis/sweep.hpp) of the oscillator at the file's parameters and those of
// `set` (ReadModelFileStart), in one of its parameters by name, from rest (or the start `set` gives)
// and from states scattered around it (PlanSweep's chains, scatter and seed), with the start's
// forcing phase (0 unless `set` gives phi) at every section time, section points repeating within the
// tolerance times their states' size (the model's units are its own); and its CSV, with the model's
// own column names.
//
//   const ModelSweepRun run = SweepModel(ReadModelFileStart("den-hartog.toml", {}), command);
//   WriteFileAtomically("den-hartog-sweep.csv", ModelSweepCsv(run));
#pragma once

#include <string>
#include <vector>

#include "stickslip/analysis/sweep.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/model_file_start.hpp"
#include "stickslip/progress.hpp"

namespace stickslip {

// Forcing periods per transient chunk of a model's sweep.
inline constexpr int kModelChunkPeriods = 20;

struct ModelSweepRun {
  DynamicLinearOscillator model;
  SweepOptions options;  // as PlanSweep gave them, the parameter by its index among the model's
  int chains = 1;
  int threads = 1;  // the threads it ran on
  double phi = 0.0;  // the forcing phase of the section (the start's, ReadModelFileStart)
  std::vector<SweepPoint> points;
};

// A model without forcing is read on its stick-entry section, its time unit the slowest free
// oscillation of its slip (2 pi/omega_1, as find's). Throws InvalidInput as PlanSweep and Sweep do (omega for a model without forcing; a sweep's
// section is a forcing phase), before any simulation; std::runtime_error as Sweep does.
ModelSweepRun SweepModel(const ModelFileStart& start, const SweepCommand& command, ProgressCallback progress = {});

// SweepCsv of the run: chain, direction, step, <parameter>, section_phase, k, the state by the
// model's column names (q, then v<k> for x<k> and v_q for any other name), stops_per_period,
// sticks_per_period, period, amplitude:<the contact's coordinate>.
std::string ModelSweepCsv(const ModelSweepRun& run);

}  // namespace stickslip
