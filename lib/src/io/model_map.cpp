#include "stickslip/io/model_map.hpp"

namespace stickslip {

ModelBruteForceMapOptions ModelMapOptionsOf(const MapSweepCommand& c, const ModelFileStart& start) {
  ModelBruteForceMapOptions o;
  const std::string first = c.first.empty() ? (start.model.Autonomous() ? "v_b" : "omega") : c.first;
  o.first = {first, c.first_from, c.first_to,
             WholeNumber("first-steps", c.first_steps, 1, ModelBruteForceMapOptions::kMaxSteps)};
  o.second = {c.second.empty() ? "F_s" : c.second, c.second_from, c.second_to,
              WholeNumber("second-steps", c.second_steps, 0, ModelBruteForceMapOptions::kMaxSteps)};
  o.runs = ModelBruteForceOptionsOf(c, start);
  o.shard = c.shard;
  o.shards = c.shards;
  o.Validate(start.model, start.parameters);
  return o;
}

}  // namespace stickslip
