#include "orbit_json.hpp"

#include <cmath>
#include <complex>

#include <nlohmann/json.hpp>

#include "stickslip/branches/orbit_monitor.hpp"
#include "stickslip/io/model_orbit_json.hpp"
#include "stickslip/orbits/orbit_measures.hpp"
#include "stickslip/orbits/stability.hpp"

namespace stickslip::cli {

namespace {

using Json = nlohmann::ordered_json;

Json Number(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

// The library's, one writer for every model.
Json VerificationOf(const Verification& verification) { return Json::parse(VerificationJson(verification)); }

// The orbit itself: signature, parameters, phi, x10, x20, v10, the segments; then its unknowns.
Json OrbitVariablesJson(const Orbit& o, const std::vector<int>& free, bool tie_static_friction) {
  Json out{{"signature", o.signature.ToString()}};
  for (ParameterId id : kAllParameters) out["parameters"][ToString(id)] = o.parameters[id];
  const Eigen::VectorXd variables = orbit_variables::Pack(o);
  out["phi"] = o.phi;  // first, as the keys have always come: phi, then the start state
  for (int i = 0; i < orbit_variables::kPhi; ++i) out[orbit_variables::Name(o.signature.size(), i)] = variables(i);
  out["segments"] = Json::array();
  for (int i = 0; i < o.signature.size(); ++i) {
    out["segments"].push_back({{"mode", ToString(o.signature.segments()[i])}, {"duration", o.durations[i]}});
  }
  const Eigen::VectorXd all = orbit_variables::Pack(o);
  out["unknowns"] = Json::object();
  for (int index : free) out["unknowns"][orbit_variables::Name(o.signature.size(), index)] = all(index);
  out["tie_u_r"] = tie_static_friction;
  return out;
}

}  // namespace

Json OrbitJson(const OrbitSolution& s, const std::vector<int>& free, bool tie_static_friction,
               const std::vector<Margin>& margins, const Verification& verification) {
  Json out = OrbitVariablesJson(s.orbit, free, tie_static_friction);
  out.update(Json{{"converged", s.summary.Converged()},
                  {"termination", ToString(s.summary.termination)},
                  {"iterations", s.summary.iterations},
                  {"residual_norm", Number(s.summary.residual_norms.back())},
                  {"condition_number", Number(s.summary.condition_number)},
                  {"family_dimension", s.family_dimension},
                  {"shooting", ToString(s.shooting)}});
  out["margins"] = Json::object();
  for (const Margin& m : margins) out["margins"][m.Name()] = Number(m.value);
  out["admissible"] = SmallestMargin(margins).value > 0;
  const Stability stability = StabilityOf(s.orbit);
  out["multipliers"] = Json::array();
  for (const std::complex<double>& mu : stability.multipliers) out["multipliers"].push_back({Number(mu.real()), Number(mu.imag())});
  out.update(Json{{"stable", stability.stable}, {"multipliers_one_sided", stability.one_sided}});
  out["measures"] = Json::object();
  const OrbitMeasures measures = Measure(s.orbit);
  orbit_columns::ForEachMeasure(measures, [&](const char* name, const auto& value) {
    out["measures"][name] = std::isfinite(static_cast<double>(value)) ? Json(value) : Json(nullptr);  // counts stay integers
  });
  out["verification"] = VerificationOf(verification);
  return out;
}

}  // namespace stickslip::cli
