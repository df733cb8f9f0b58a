#include "stickslip/io/model_summary.hpp"

#include <nlohmann/json.hpp>

#include "stickslip/model/linear_oscillator.hpp"

namespace stickslip {

namespace {

using Json = nlohmann::ordered_json;

Json OscillationsJson(const std::vector<FreeOscillation>& modes) {
  Json out = Json::array();
  for (const FreeOscillation& m : modes) {
    out.push_back({{"frequency", m.frequency}, {"damping_ratio", m.damping_ratio}, {"oscillates", m.oscillates}});
  }
  return out;
}

}  // namespace

ModelSummary SummarizeModel(const std::filesystem::path& run_file) {
  ModelSummary m;
  m.table = ReadModelTable(run_file);
  m.data = ModelDataOf(m.table);
  m.modes = ModesOf(m.data);
  m.description = DescribeLinearOscillator(m.data, m.modes);
  m.values = GivenParameters(m.description, m.table);
  // Where the table gives every parameter it needs, their values are checked as find checks them.
  if (m.values[1] && m.values[2] && (m.values[0] || m.Autonomous())) ParametersOf(DynamicLinearOscillator(m.data), m.table);
  m.slip = FreeOscillations(m.modes.slip.eigenvalues);
  m.stick = FreeOscillations(m.modes.stick.eigenvalues);
  return m;
}

std::string ModelSummaryJson(const ModelSummary& m) {
  const ModelDescription& d = m.description;
  Json parameters = Json::array();
  for (std::size_t k = 0; k < d.parameters.size(); ++k) {
    const ParameterDescription& p = d.parameters[k];
    parameters.push_back({{"name", p.name}, {"meaning", p.meaning}, {"unit", p.unit}, {"minimum", p.minimum},
                          {"maximum", p.maximum}, {"range", p.range},
                          {"value", m.values[k] ? Json(*m.values[k]) : Json(nullptr)}});
  }
  Json forcing = Json::object();
  for (Eigen::Index j = 0; j < m.data.forcing.size(); ++j) forcing[d.coordinates[j]] = m.data.forcing(j);
  Json units = Json::object();
  for (const auto& [name, unit] : ModelUnits::kNamed) units[name] = d.units.*unit;
  const Json out{{"model", d.name},
                 {"kind", m.table.kind},
                 {"coordinates", d.coordinates},
                 {"contact", d.coordinates.back()},
                 {"forcing", forcing},
                 {"friction_slope", m.data.friction_slope},
                 {"units", units},
                 {"parameters", parameters},
                 {"autonomous", m.Autonomous()},
                 {"free_oscillations", {{"slip", OscillationsJson(m.slip)}, {"stick", OscillationsJson(m.stick)}}},
                 {"start_state", d.initial_state}};
  return out.dump();
}

}  // namespace stickslip
