#include "stickslip/io/model_atlas.hpp"

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/model_map.hpp"
#include "stickslip/io/model_trace.hpp"
#include "stickslip/io/run_file.hpp"

namespace stickslip {

ModelAtlasOptions ModelAtlasOptionsOf(const AtlasCommand& c, const ModelFileStart& start) {
  ModelAtlasOptions o;
  o.parameter = c.parameter;
  o.from = c.from;
  o.to = c.to;
  o.steps = WholeNumber("steps", c.steps, 1, ModelAtlasOptions::kMaxSteps);
  o.brute_force = ModelBruteForceOptionsOf(c, start);
  o.max_multiple = WholeNumber("max-multiple", c.max_multiple, 1, ModelFindOptions::kMaxMultiple);
  o.trace.max_amplitude = c.max_amplitude;
  o.continuation.max_points = WholeNumber("max-points", c.max_points, 1, kMaxRunPoints);
  o.resonance_approach = c.resonance_approach;
  start.RefuseSetOf(o.parameter, "the atlas's grid");
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
