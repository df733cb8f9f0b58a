#include "stickslip/io/model_map.hpp"

namespace stickslip {

ModelBruteForceMapOptions ModelMapOptionsOf(const MapSweepCommand& c, const ModelFileStart& start) {
  ModelBruteForceMapOptions o;
  const auto [first, second] = DefaultMapAxes(start.model);
  o.first = {c.first.empty() ? first : c.first, c.first_from, c.first_to,
             WholeNumber("first-steps", c.first_steps, 1, ModelBruteForceMapOptions::kMaxSteps)};
  o.second = {c.second.empty() ? second : c.second, c.second_from, c.second_to,
              WholeNumber("second-steps", c.second_steps, 0, ModelBruteForceMapOptions::kMaxSteps)};
  o.runs = ModelBruteForceOptionsOf(c, start);
  o.shard = c.shard;
  o.shards = c.shards;
  start.RefuseSetOf(o.first.parameter, "the map's first axis");
  start.RefuseSetOf(o.second.parameter, "the map's second axis");
  o.Validate(start.model, start.parameters);
  return o;
}

}  // namespace stickslip
