// A run file's [model] through the brute force (model_find.hpp reads it): the options of
// `stickslip map-sweep` and `stickslip atlas` as every front end gives them (command_options.hpp),
// read for the model's brute force (analysis/model_brute_force.hpp) and map
// (analysis/model_brute_force_map.hpp) and checked before any work.
//
//   const ModelFileStart start = ReadModelFileStart("three-mass-belt.toml", {});
//   const ModelBruteForceMap map = ComputeModelBruteForceMap(start.model, start.parameters,
//                                                            ModelMapOptionsOf(command, start));
#pragma once

#include <cstdint>
#include <numbers>

#include "stickslip/analysis/model_brute_force_map.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/model_file_start.hpp"

namespace stickslip {

// The brute force's flags of `command` (MapSweepCommand, AtlasCommand) as the paper's, but
// --tolerance relative to the section states' size, --scatter in the model's units around the
// start's state, the section at the start's phase, and without forcing the transient in units of
// the slowest free oscillation of its slip (as find's). Throws InvalidInput naming the flag.
template <typename Command>
ModelBruteForceOptions ModelBruteForceOptionsOf(const Command& c, const ModelFileStart& start) {
  ModelBruteForceOptions o;
  o.transient_periods = WholeNumber("transients", c.transients, 0, ModelBruteForceOptions::kMaxPeriods);
  o.recorded_periods = WholeNumber("periods", c.periods, 2, ModelBruteForceOptions::kMaxPeriods);
  o.scattered_starts = WholeNumber("starts", c.starts, 0, ModelBruteForceOptions::kMaxScatteredStarts);
  o.scatter = c.scatter;
  o.centre = start.state;       // the file's start, or --set's (rest unless given)
  o.section_phase = start.phi;  // the file's or --set's phi, as sweep --model's section
  o.seed = static_cast<std::uint64_t>(WholeNumber("seed", c.seed, 0, 1000000000));
  o.periodicity_tolerance = c.tolerance;
  o.threads = WholeNumber("threads", c.threads, 0, 1024);
  o.time_unit = 2.0 * std::numbers::pi / start.slowest_frequency;
  return o;
}

// map-sweep's options for the model's map (its axes by the model's parameter names: where empty,
// omega, or v_b without forcing, and F_s; the shard as given). Throws InvalidInput naming the flag (ModelBruteForceMapOptions::Validate, WholeNumber),
// before any simulation.
ModelBruteForceMapOptions ModelMapOptionsOf(const MapSweepCommand& command, const ModelFileStart& start);

}  // namespace stickslip
