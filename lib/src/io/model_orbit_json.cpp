#include "stickslip/io/model_orbit_json.hpp"

#include <cmath>
#include <complex>
#include <vector>

#include <nlohmann/json.hpp>

#include "json_number.hpp"

#include "stickslip/orbits/any_orbit.hpp"

namespace stickslip {

namespace {

using Json = nlohmann::ordered_json;

Json Modes(const std::vector<Mode>& sequence) {
  Json list = Json::array();
  for (Mode m : sequence) list.push_back(ToString(m));
  return list;
}

Json VerificationObject(const Verification& v) {
  const bool simulated = v.not_simulated.empty();
  auto check = [&](const SimulatorCheck& c) {
    return Json{{"events", Modes(c.modes)},
                {"sequence_matches", c.sequence_matches},
                {"max_mismatch", simulated ? detail::JsonNumber(c.periodicity_mismatch) : Json(nullptr)},
                {"max_event_time_difference", simulated ? detail::JsonNumber(c.max_event_time_difference) : Json(nullptr)}};
  };
  return {{"passed", v.Passed()},
          {"not_simulated", simulated ? Json(nullptr) : Json(v.not_simulated)},
          {"expected", Modes(v.expected)},
          {"exact", check(v.exact)},
          {"odeint", check(v.odeint)}};
}

}  // namespace

std::string VerificationJson(const Verification& verification) { return VerificationObject(verification).dump(); }

std::string ModelFindJson(const DynamicLinearOscillator& model, const ModelFindResult<DynamicLinearOscillator>& r) {
  using Model = DynamicLinearOscillator;
  const ModelDescription& d = model.Description();
  Json out{{"status", ToString(r.status)}, {"message", r.message},
           {"signature", r.guess ? Json(r.guess->signature.ToString()) : Json(nullptr)}, {"orbit", nullptr}};
  if (!r.solution || !r.solution->summary.Converged()) return out.dump();
  const BasicOrbit<Model>& o = r.solution->orbit;
  Json orbit{{"signature", o.signature.ToString()}};
  for (const auto& [name, unit] : ModelUnits::kNamed) orbit["units"][name] = d.units.*unit;
  for (int k = 0; k < d.ParameterCount(); ++k) orbit["parameters"][d.parameters[k].name] = Model::ParameterAt(o.parameters, k);
  orbit["period"] = PeriodOf(model, o);
  orbit["phi"] = o.phi;
  for (int k = 0; k < model.StateSize(); ++k) orbit["start"][d.initial_state[k]] = o.start(k);
  orbit["durations"] = o.durations;
  orbit["iterations"] = r.solution->summary.iterations;
  orbit["residual_norm"] = detail::JsonNumber(r.solution->summary.residual_norms.back());
  for (const Margin& m : r.margins) orbit["margins"][m.Name()] = detail::JsonNumber(m.value);
  orbit["admissible"] = SmallestMargin(r.margins).value > 0;
  orbit["multipliers"] = Json::array();
  for (const std::complex<double>& mu : r.stability->multipliers) orbit["multipliers"].push_back({detail::JsonNumber(mu.real()), detail::JsonNumber(mu.imag())});
  orbit["stable"] = r.stability->stable;
  for (std::size_t j = 0; j < d.coordinates.size(); ++j) {
    orbit["measures"]["amplitude:" + d.coordinates[j]] = detail::JsonNumber(r.measures->coordinates[j].Amplitude());
    orbit["measures"]["peak-to-peak:" + d.coordinates[j]] = detail::JsonNumber(r.measures->coordinates[j].PeakToPeak());
  }
  orbit["measures"]["stick-fraction"] = detail::JsonNumber(r.measures->stick_fraction);
  orbit["measures"]["stops"] = r.measures->stops;
  orbit["measures"]["sticks"] = r.measures->sticks;
  orbit["measures"]["friction-work"] = detail::JsonNumber(r.measures->friction_work);
  orbit["measures"]["equivalent-damping"] = detail::JsonNumber(r.measures->equivalent_damping);
  orbit["verification"] = VerificationObject(*r.verification);
  out["orbit"] = orbit;
  return out.dump();
}

}  // namespace stickslip
