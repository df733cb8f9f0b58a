#include "stickslip/io/model_atlas.hpp"

#include <cstdint>
#include <numbers>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/model_trace.hpp"
#include "stickslip/io/run_file.hpp"

namespace stickslip {

ModelAtlasOptions ModelAtlasOptionsOf(const AtlasCommand& c, const ModelFileStart& start) {
  ModelAtlasOptions o;
  o.parameter = c.parameter;
  o.from = c.from;
  o.to = c.to;
  o.steps = WholeNumber("steps", c.steps, 1, ModelAtlasOptions::kMaxSteps);
  o.transient_periods = WholeNumber("transients", c.transients, 0, ModelAtlasOptions::kMaxPeriods);
  o.recorded_periods = WholeNumber("periods", c.periods, 2, ModelAtlasOptions::kMaxPeriods);
  o.scattered_starts = WholeNumber("starts", c.starts, 0, ModelAtlasOptions::kMaxScatteredStarts);
  o.scatter = c.scatter;
  o.centre = start.state;       // the file's start, or --set's (rest unless given)
  o.section_phase = start.phi;  // the file's or --set's phi, as sweep --model's section
  o.seed = static_cast<std::uint64_t>(WholeNumber("seed", c.seed, 0, 1000000000));
  o.periodicity_tolerance = c.tolerance;
  o.threads = WholeNumber("threads", c.threads, 0, 1024);
  o.time_unit = 2.0 * std::numbers::pi / start.slowest_frequency;
  o.max_multiple = WholeNumber("max-multiple", c.max_multiple, 1, ModelFindOptions::kMaxMultiple);
  o.trace.max_amplitude = c.max_amplitude;
  o.continuation.max_points = WholeNumber("max-points", c.max_points, 1, kMaxRunPoints);
  o.resonance_approach = c.resonance_approach;
  o.Validate(start.model, start.parameters);
  return o;
}

StoredAtlas StoredModelAtlas(const ModelAtlas& atlas, const ModelAtlasOptions& options, const ModelFileStart& start,
                             const std::filesystem::path& run_file, const NamedValues& set, const std::string& output) {
  RunFile run;
  run.path = set.empty() ? run_file.string() : std::string(kOneOffRunPath);
  run.output = output;
  run.parameter = atlas.parameter;
  return RecordModelAtlas(run, atlas, options, start.slip_frequencies);
}

}  // namespace stickslip
