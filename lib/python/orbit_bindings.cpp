// The model and single orbits for Python: Parameters, the paper presets, simulate, Signature,
// solve and the Orbit it returns; the module's errors; the start dict every computation takes.
#include <cmath>
#include <complex>
#include <numbers>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <pybind11/operators.h>

#include "bindings.hpp"
#include "stickslip/analysis/orbit_finder.hpp"
#include "stickslip/io/model_find.hpp"
#include "stickslip/io/model_orbit_json.hpp"
#include "stickslip/io/model_restart.hpp"
#include "stickslip/io/model_summary.hpp"
#include "stickslip/branches/orbit_monitor.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/version.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/stored_run.hpp"
#include "stickslip/model/pascal_2014.hpp"
#include "stickslip/model/exact_simulator.hpp"
#include "stickslip/model/odeint_simulation.hpp"
#include "stickslip/model/pascal_2014/odeint_simulator.hpp"
#include "stickslip/model/pascal_2014/paper_examples.hpp"
#include "stickslip/model/simulation.hpp"
#include "stickslip/orbits/margins.hpp"
#include "stickslip/orbits/orbit_measures.hpp"
#include "stickslip/orbits/orbit_solver.hpp"
#include "stickslip/orbits/paper_presets.hpp"
#include "stickslip/orbits/stability.hpp"
#include "stickslip/orbits/verification.hpp"

namespace stickslip::python {

namespace {

namespace ov = orbit_variables;

// stickslip.ConvergenceError, created once when the module is imported; the module holds the
// reference, so that nothing is released after the interpreter has ended.
PyObject* convergence_error_type = nullptr;

NamedValues ToNamedValues(const py::handle& list) {
  NamedValues values;
  for (const py::handle item : list) {
    const auto pair = item.cast<std::pair<std::string, double>>();
    values.push_back(pair);
  }
  return values;
}

py::list ModeList(const std::vector<Mode>& modes) {
  py::list list;
  for (Mode m : modes) list.append(ToString(m));
  return list;
}

// ---- Parameters

// The model's description: parameter and state names for the bindings below.
const ModelDescription& Model() { return Pascal2014{}.Description(); }

Parameters Checked(const Parameters& p) {
  if (const std::optional<InvalidInput> invalid = Validate(p)) throw *invalid;
  return p;
}

Parameters MakeParameters(double chi, double eta, double omega, double u_s, double u_r) {
  return Checked(Parameters{chi, eta, omega, u_s, u_r});
}

std::string DescribeParameters(const Parameters& p) {
  std::string text;
  for (ParameterId id : kAllParameters) text += fmt::format("{}{}={}", text.empty() ? "" : ", ", ToString(id), p[id]);
  return text;
}

// ---- simulate

// Any model's simulation: events, samples and segments as arrays and lists, states (n, size).
template <typename Result>
py::dict SimulationDict(const Result& r, py::ssize_t size) {
  using StateType = std::decay_t<decltype(r.events.front().state)>;
  const std::size_t n_events = r.events.size();
  py::array_t<double> t_events(static_cast<py::ssize_t>(n_events));
  std::vector<StateType> event_states;
  py::list kinds, before, after;
  for (std::size_t i = 0; i < n_events; ++i) {
    const auto& e = r.events[i];
    t_events.mutable_at(i) = e.t;
    event_states.push_back(e.state);
    kinds.append(e.IsAbnormalStop() ? "abnormal-stop" : ToString(e.kind));
    before.append(ToString(e.mode_before));
    after.append(ToString(e.mode_after));
  }
  py::dict events;
  events["t"] = t_events;
  events["kind"] = kinds;
  events["mode_before"] = before;
  events["mode_after"] = after;
  events["state"] = StateArray(event_states, size);

  py::array_t<double> t_samples(static_cast<py::ssize_t>(r.samples.size()));
  std::vector<StateType> sample_states;
  py::list sample_modes;
  std::size_t segment = 0;
  for (std::size_t i = 0; i < r.samples.size(); ++i) {
    const auto& s = r.samples[i];
    while (segment + 1 < r.segments.size() && r.segments[segment].t_end < s.t) ++segment;
    t_samples.mutable_at(i) = s.t;
    sample_states.push_back(s.state);
    sample_modes.append(r.segments.empty() ? "" : ToString(r.segments[segment].mode));
  }
  py::dict samples;
  samples["t"] = t_samples;
  samples["state"] = StateArray(sample_states, size);
  samples["mode"] = sample_modes;

  py::list segments;
  for (const auto& s : r.segments) {
    segments.append(py::dict(py::arg("mode") = ToString(s.mode), py::arg("t_start") = s.t_start,
                             py::arg("t_end") = s.t_end, py::arg("end") = ToString(s.end_reason)));
  }
  py::dict out;
  out["phi"] = r.phi;
  out["events"] = events;
  out["samples"] = samples;
  out["segments"] = segments;
  out["end"] = ToString(r.end);
  out["message"] = r.message;
  out["completed"] = r.Completed();
  return out;
}

py::dict Simulate(const py::dict& start, double periods, const std::string& method, double samples_per_period) {
  const ModelStart input = BuildModelStart(ToStartInput(start));
  const SimulationOptions options = SimulationOver(input.parameters, periods, samples_per_period, true);
  // The samples are returned as arrays, so they are kept: at most 1e7 (320 MB); the command
  // line streams its CSV instead.
  if (!(periods * samples_per_period <= 1e7)) {
    throw InvalidInput("samples-per-period", samples_per_period,
                       fmt::format("periods ({}) x samples-per-period <= 1e7: the samples are kept in memory", periods));
  }
  if (method != "exact" && method != "odeint") throw InvalidInput("method", "'" + method + "'", "exact, odeint");
  SimulationResult result;
  {
    py::gil_scoped_release release;
    result = method == "exact" ? SimulateExact(input.parameters, input.initial_state, input.phi, options)
                               : SimulateOdeint(input.parameters, input.initial_state, input.phi, options);
  }
  py::dict out = SimulationDict(result, 4);
  out["parameters"] = result.parameters;
  out["initial_state"] = py::array_t<double>(4, input.initial_state.data());
  return out;
}

// simulate(model=...): the run file's oscillator (`set` over it) from its start, as `stickslip
// simulate --model`; its parameters by name, its states (n, the model's size).
py::dict SimulateModel(const std::string& path, const NamedValues& set, double periods, const std::string& method,
                       double samples_per_period) {
  using Model = DynamicLinearOscillator;
  const ModelFileStart start = ReadModelFileStart(path, set);
  const Model& model = start.model;
  const double frequency = model.Autonomous() ? start.slowest_frequency : start.parameters.omega;
  const auto options = SimulationOver<Model::State>(2.0 * std::numbers::pi / frequency, periods, samples_per_period, true);
  if (!(periods * samples_per_period <= 1e7)) {
    throw InvalidInput("samples-per-period", samples_per_period,
                       fmt::format("periods ({}) x samples-per-period <= 1e7: the samples are kept in memory", periods));
  }
  if (method != "exact" && method != "odeint") throw InvalidInput("method", "'" + method + "'", "exact, odeint");
  BasicSimulationResult<Model> result;
  {
    py::gil_scoped_release release;
    result = method == "exact" ? SimulateExact(model, start.parameters, start.state, start.phi, options)
                               : SimulateOdeint(model, start.parameters, start.state, start.phi, options);
  }
  const ModelDescription& d = model.Description();
  py::dict out = SimulationDict(result, model.StateSize());
  py::dict parameters;
  for (int k = 0; k < Model::kParameterCount; ++k) parameters[py::str(d.parameters[k].name)] = Model::ParameterAt(start.parameters, k);
  out["parameters"] = parameters;
  out["initial_state"] = py::array_t<double>(start.state.size(), start.state.data());
  out["state_names"] = d.state_components;
  return out;
}

// ---- solve

// A solved orbit with everything `stickslip solve` reports about it.
struct SolvedOrbit {
  Orbit orbit;
  NewtonSummary summary;
  Shooting shooting = Shooting::kSingle;
  std::vector<std::string> unknowns;  // the free variables' names
  bool tie_u_r = false;
  std::vector<Margin> margins;
  Stability stability;
  Verification verification;
  int family_dimension = 0;  // OrbitSolution's
};

SolvedOrbit Solve(const py::dict& start, const std::string& shooting, const std::string& linear_solver) {
  const StartProblem problem = BuildStartProblem(ToStartInput(start));
  const OrbitSolverOptions options = SolverOptionsOf(shooting, linear_solver);
  std::vector<std::string> unknowns;
  for (int index : problem.free) unknowns.push_back(ov::Name(problem.orbit.signature.size(), index));
  std::optional<SolvedOrbit> solved;
  NewtonSummary failed;
  {
    py::gil_scoped_release release;
    OrbitSolution solution = SolveOrbit(problem.orbit, problem.free, problem.unknowns.tie_static_friction, options);
    if (solution.summary.Converged()) {
      std::vector<Margin> margins = AdmissibilityMargins(solution.orbit);
      Stability stability = StabilityOf(solution.orbit);
      Verification verification = VerifyOrbit(solution.orbit);
      solved = SolvedOrbit{std::move(solution.orbit), std::move(solution.summary), solution.shooting,
                           std::move(unknowns), problem.unknowns.tie_static_friction, std::move(margins),
                           std::move(stability), std::move(verification), solution.family_dimension};
    } else {
      failed = std::move(solution.summary);
    }
  }
  if (!solved) RaiseConvergenceError("Newton did not converge: " + failed.BriefReport(), SummaryDict(failed));
  return std::move(*solved);
}

// ---- find

// From a simulated motion to its exact orbit, as `stickslip find`: the section's verdict, and the
// solved orbit (as solve returns it) when Newton converged.
py::dict Find(const py::dict& start, const FindCommand& command) {
  const ModelStart input = BuildModelStart(ToStartInput(start));
  const FindOrbitOptions options = FindOptionsOf(command);
  FindOrbitResult found;
  std::optional<SolvedOrbit> solved;
  {
    py::gil_scoped_release release;
    found = FindOrbit(input.parameters, input.initial_state, input.phi, options);
    if (found.solution && found.solution->summary.Converged()) {
      std::vector<std::string> unknowns;
      for (int index : found.problem->free) unknowns.push_back(ov::Name(found.solution->orbit.signature.size(), index));
      solved = SolvedOrbit{found.solution->orbit, found.solution->summary, found.solution->shooting,
                           std::move(unknowns), found.problem->unknowns.tie_static_friction, found.margins,
                           StabilityOf(found.solution->orbit), *found.verification, found.solution->family_dimension};
    }
  }
  py::dict out;
  out["status"] = ToString(found.status);
  out["message"] = found.message;
  out["transient_periods"] = found.transient_periods;
  out["period_multiple"] = found.period_multiple;
  out["mismatch"] = found.mismatch;
  out["closest_multiple"] = found.closest_multiple;
  out["antisymmetric"] = found.antisymmetric;
  out["signature"] = found.start ? py::cast(found.start->signature) : py::none();
  out["orbit"] = solved ? py::cast(std::move(*solved)) : py::none();
  return out;
}

py::dict SimulatorCheckDict(const SimulatorCheck& c, bool simulated) {
  py::dict d;
  d["events"] = ModeList(c.modes);
  d["sequence_matches"] = c.sequence_matches;
  d["max_mismatch"] = simulated ? py::cast(c.periodicity_mismatch) : py::none();
  d["max_event_time_difference"] = simulated ? py::cast(c.max_event_time_difference) : py::none();
  return d;
}

py::dict VerificationDict(const Verification& v) {
  const bool simulated = v.not_simulated.empty();
  py::dict d;
  d["passed"] = v.Passed();
  d["not_simulated"] = simulated ? py::none() : py::cast(v.not_simulated);
  d["expected"] = ModeList(v.expected);
  d["exact"] = SimulatorCheckDict(v.exact, simulated);
  d["odeint"] = SimulatorCheckDict(v.odeint, simulated);
  d["report"] = v.Report();
  return d;
}

py::dict VariablesDict(const Orbit& orbit) {
  py::dict d;
  for (const auto& [name, value] : SolutionColumns(orbit)) d[py::str(name)] = value;
  return d;
}

// The start state's variables by the layout's names (x10, x20, v10 in the paper's model); the
// contact's velocity, the last component, is zero at the start.
void BindStartState(py::class_<SolvedOrbit>& orbit) {
  const std::vector<std::string>& components = Model().state_components;
  for (int i = 0; i < ov::kPhi; ++i) {
    const std::string doc = fmt::format("{} at the start (a stop: {} = 0)", components[i], components.back());
    orbit.def_property_readonly(
        ov::Name(0, i).c_str(), [i](const SolvedOrbit& s) { return ov::Pack(s.orbit)(i); }, doc.c_str());
  }
}

void BindSolvedOrbit(py::module_& m) {
  py::class_<SolvedOrbit> orbit(m, "Orbit",
                                "A periodic orbit solved by stickslip.solve: its unknowns, the Newton summary, the\n"
                                "admissibility margins (> 0 admissible), the Floquet multipliers and the verification by\n"
                                "the exact and the Odeint simulators, as `stickslip solve` reports them. Time is the\n"
                                "paper's scaled time t.");
  BindStartState(orbit);
  orbit.def_property_readonly("signature", [](const SolvedOrbit& s) { return s.orbit.signature; })
      .def_property_readonly("parameters", [](const SolvedOrbit& s) { return s.orbit.parameters; })
      .def_property_readonly("phi", [](const SolvedOrbit& s) { return s.orbit.phi; }, "forcing phase at t = 0 (rad)")
      .def_property_readonly(
          "durations", [](const SolvedOrbit& s) { return py::array_t<double>(py::cast(s.orbit.durations)); },
          "d1..dn: the listed segments' durations (scaled time)")
      .def_property_readonly("period", [](const SolvedOrbit& s) { return s.orbit.Period(); },
                             "K 2 pi/omega, the time after which the orbit repeats")
      .def_property_readonly("variables", [](const SolvedOrbit& s) { return VariablesDict(s.orbit); },
                             "every orbit variable by name, in the order of the result files")
      .def_property_readonly(
          "unknowns",
          [](const SolvedOrbit& s) {
            py::dict d;
            const Eigen::VectorXd all = ov::Pack(s.orbit);
            for (const std::string& name : s.unknowns) {
              d[py::str(name)] = all(*ov::IndexOf(s.orbit.signature.size(), name));
            }
            return d;
          },
          "the solved variables and their values (u_r follows u_s when tie_u_r)")
      .def_property_readonly("tie_u_r", [](const SolvedOrbit& s) { return s.tie_u_r; })
      .def_property_readonly("newton", [](const SolvedOrbit& s) { return SummaryDict(s.summary); },
                             "the Newton summary: termination, iterations, residual norms, condition number")
      .def_property_readonly("family_dimension", [](const SolvedOrbit& s) { return s.family_dimension; },
                             "0 for an isolated orbit; k > 0 where it is one of a k-dimensional family of orbits "
                             "at its parameters (not isolated: newton['message'] says so)")
      .def_property_readonly("shooting", [](const SolvedOrbit& s) { return std::string(ToString(s.shooting)); })
      .def_property_readonly(
          "margins",
          [](const SolvedOrbit& s) {
            py::dict d;
            for (const Margin& margin : s.margins) d[py::str(margin.Name())] = margin.value;
            return d;
          },
          "admissibility margins by name (> 0: admissible; NaN: not defined)")
      .def_property_readonly(
          "smallest_margin",
          [](const SolvedOrbit& s) {
            const Margin smallest = SmallestMargin(s.margins);
            return py::make_tuple(smallest.Name(), smallest.value);
          },
          "(name, value) of the smallest margin: the distance to the nearest change of orbit type")
      .def_property_readonly(
          "admissible",
          [](const SolvedOrbit& s) { return SmallestMargin(s.margins).value > 0; },
          "every margin > 0: the orbit is a motion of the system")
      .def_property_readonly(
          "multipliers",
          [](const SolvedOrbit& s) {
            py::array_t<std::complex<double>> mu(4);
            for (int k = 0; k < 4; ++k) mu.mutable_at(k) = s.stability.multipliers[k];
            return mu;
          },
          "Floquet multipliers (monodromy with saltation matrices), by decreasing modulus")
      .def_property_readonly(
          "monodromy",
          [](const SolvedOrbit& s) {
            py::array_t<double> monodromy({4, 4});
            for (int i = 0; i < 4; ++i) {
              for (int j = 0; j < 4; ++j) monodromy.mutable_at(i, j) = s.stability.monodromy(i, j);
            }
            return monodromy;
          },
          "the 4x4 monodromy matrix of the period map")
      .def_property_readonly("stable", [](const SolvedOrbit& s) { return s.stability.stable; },
                             "every |multiplier| < 1")
      .def_property_readonly("multipliers_one_sided", [](const SolvedOrbit& s) { return s.stability.one_sided; },
                             "the multipliers are one-sided (abnormal stops, section 4.2)")
      .def_property_readonly(
          "measures",
          [](const SolvedOrbit& s) {
            py::dict d;
            const OrbitMeasures measures = Measure(s.orbit);
            orbit_columns::ForEachMeasure(measures, [&](const char* name, const auto& value) { d[py::str(name)] = value; });
            return d;
          },
          "what users plot, over one whole period, by the names of a branch's columns: amplitude:x1\n"
          "(max |x1|), amplitude:x2 (max |x2|), peak-to-peak:x2, stick-fraction, stops and sticks (ints)")
      .def_property_readonly("verification", [](const SolvedOrbit& s) { return VerificationDict(s.verification); },
                             "one period simulated by the exact and the Odeint simulators")
      .def("sample", [](const SolvedOrbit& s, int n) { return SampleOrbit(s.orbit, n); }, py::arg("n") = 200,
           "(t, x): n >= 2 equally spaced times over one period, from 0 to the period, and the state\n"
           "(x1, x2, x1', x2') at each, as arrays of shapes (n,) and (n, 4)")
      .def("__repr__", [](const SolvedOrbit& s) {
        return fmt::format("<stickslip.Orbit '{}' {}, period {}>", s.orbit.signature.ToString(),
                           DescribeParameters(s.orbit.parameters), s.orbit.Period());
      });
}

void BindSignature(py::module_& m) {
  py::class_<Signature>(m, "Signature",
                        "An orbit type: the cyclic sequence of slip and stick segments, then options after a\n"
                        "slash: Signature(\"slip- slip+ stick slip+\"), \"slip- stick slip- / antisymmetric\",\n"
                        "\"slip- slip+ / period 2\". Bad text raises ValueError.")
      .def(py::init([](const std::string& text) { return Signature::Parse(text); }), py::arg("text"))
      .def_property_readonly("segments", [](const Signature& s) { return ModeList(s.segments()); },
                             "the listed segments' modes")
      .def_property_readonly("antisymmetric", &Signature::antisymmetric)
      .def_property_readonly("period_multiple", &Signature::period_multiple)
      .def_property_readonly("full_period", [](const Signature& s) { return ModeList(s.FullPeriod()); },
                             "the segments over a whole period (the mirror image added when antisymmetric)")
      .def_property_readonly(
          "end_kinds",
          [](const Signature& s) {
            py::list kinds;
            for (int i = 0; i < s.size(); ++i) kinds.append(ToString(s.EndKind(i)));
            return kinds;
          },
          "what ends each listed segment")
      .def("__len__", &Signature::size)
      .def("__str__", &Signature::ToString)
      .def("__repr__", [](const Signature& s) { return fmt::format("stickslip.Signature('{}')", s.ToString()); })
      .def(py::self == py::self)
      .def("__hash__", [](const Signature& s) { return py::hash(py::str(s.ToString())); });
}

// The parameters' values in the order of the model's description.
std::vector<double> ParameterValues(const Parameters& p) {
  std::vector<double> values;
  for (int k = 0; k < Pascal2014::kParameterCount; ++k) values.push_back(Pascal2014::ParameterAt(p, k));
  return values;
}

// "chi, eta, omega, u_s, u_r": the model's parameter names.
std::string ParameterNames() {
  std::vector<std::string> names;
  for (const ParameterDescription& d : Model().parameters) names.push_back(d.name);
  return fmt::format("{}", fmt::join(names, ", "));
}

// Each parameter by its name as a read-only property: p.omega.
void BindParameterValues(py::class_<Parameters>& parameters) {
  for (int k = 0; k < Pascal2014::kParameterCount; ++k) {
    parameters.def_property_readonly(Model().parameters[k].name.c_str(),
                                     [k](const Parameters& p) { return Pascal2014::ParameterAt(p, k); });
  }
}

void BindParameters(py::module_& m) {
  py::class_<Parameters> parameters(m, "Parameters",
                                    "The oscillator's dimensionless data (Pascal 2014, eq. 3), checked on construction:\n"
                                    "  chi    stiffness ratio k2/(k1+k2), 0.01 <= chi <= 0.99\n"
                                    "  eta    mass ratio m1/m2, 0.01 <= eta <= 100\n"
                                    "  omega  forcing frequency, 0.01 <= omega <= 100, not a natural frequency\n"
                                    "  u_s    sliding friction level, 1e-06 <= u_s <= 1000\n"
                                    "  u_r    static friction level, u_s <= u_r <= 1000\n"
                                    "Bad values raise ValueError with the command line's message.");
  BindParameterValues(parameters);
  parameters
      .def(py::init(&MakeParameters), py::kw_only(), py::arg("chi"), py::arg("eta"), py::arg("omega"), py::arg("u_s"),
           py::arg("u_r"))
      .def_property_readonly(
          "natural_frequencies",
          [](const Parameters& p) { return py::tuple(py::cast(Pascal2014{}.NaturalFrequencies(p))); },
          "(omega1, omega2): the natural frequencies of the slip (eq. 56), where the forced amplitude\n"
          "is singular")
      .def(
          "replace",
          [](const Parameters& p, const py::kwargs& changes) {
            Parameters q = p;
            for (const auto& [key, value] : changes) {
              const std::string name = py::str(key);
              const std::optional<int> k = Model().ParameterIndex(name);
              if (!k) throw InvalidInput("parameter", "'" + name + "'", ParameterNames());
              Pascal2014::ParameterAt(q, *k) = value.cast<double>();
            }
            return Checked(q);
          },
          "A copy with the given values changed, checked: p.replace(omega=0.58)")
      .def("as_dict",
           [](const Parameters& p) {
             py::dict d;
             const std::vector<double> values = ParameterValues(p);
             for (int k = 0; k < Pascal2014::kParameterCount; ++k) d[py::str(Model().parameters[k].name)] = values[k];
             return d;
           })
      .def("__eq__", [](const Parameters& a, const Parameters& b) { return ParameterValues(a) == ParameterValues(b); })
      .def("__repr__", [](const Parameters& p) { return "stickslip.Parameters(" + DescribeParameters(p) + ")"; })
      .def(py::pickle([](const Parameters& p) { return py::tuple(py::cast(ParameterValues(p))); },
                      [](const py::tuple& t) {
                        Parameters p;
                        for (int k = 0; k < Pascal2014::kParameterCount; ++k) {
                          Pascal2014::ParameterAt(p, k) = t[k].cast<double>();
                        }
                        return Checked(p);
                      }));
}

py::dict PresetDict(const std::string& name) {
  StartInput input;
  input.preset = name;
  const ModelStart start = BuildModelStart(input);  // InvalidInput for an unknown name
  const PaperPreset* preset = FindPaperPreset(name);
  py::dict d;
  d["name"] = name;
  d["equation"] = std::string(preset->example->equation);
  d["title"] = std::string(preset->example->title);
  d["parameters"] = start.parameters;
  d["state"] = py::array_t<double>(4, start.initial_state.data());
  d["phi"] = start.phi;
  d["signature"] = Signature::Parse(preset->signature);
  d["durations"] = py::array_t<double>(py::cast(preset->durations));
  return d;
}

}  // namespace

StartInput ToStartInput(const py::dict& start) {
  StartInput input;
  auto text = [&](const char* key) {
    return start.contains(key) && !start[key].is_none() ? start[key].cast<std::string>() : std::string();
  };
  input.preset = text("preset");
  input.signature = text("signature");
  const std::string point = text("point");
  if (!point.empty()) input.restart = ReadRestartPoint(text("results"), point);
  if (start.contains("set")) input.set = ToNamedValues(start["set"]);
  if (start.contains("guess")) input.guess = ToNamedValues(start["guess"]);
  if (start.contains("free")) input.free = start["free"].cast<std::vector<std::string>>();
  if (start.contains("fix")) {
    for (const py::handle item : start["fix"]) {
      const auto fix = item.cast<std::pair<std::string, std::optional<double>>>();
      input.fix.push_back({fix.first, fix.second});
    }
  }
  if (start.contains("tie_u_r")) input.tie_u_r = start["tie_u_r"].cast<bool>();
  if (start.contains("paper_choice")) input.paper_choice = start["paper_choice"].cast<bool>();
  return input;
}

void RaiseConvergenceError(const std::string& message, py::dict summary) {
  py::object error = py::handle(convergence_error_type)(message);
  error.attr("summary") = std::move(summary);
  PyErr_SetObject(convergence_error_type, error.ptr());
  throw py::error_already_set();
}

py::dict SummaryDict(const NewtonSummary& s) {
  py::dict d;
  d["converged"] = s.Converged();
  d["termination"] = ToString(s.termination);
  d["message"] = s.message;
  d["iterations"] = s.iterations;
  d["residual_norms"] = py::array_t<double>(py::cast(s.residual_norms));
  d["condition_number"] = s.condition_number;
  d["report"] = s.BriefReport();
  return d;
}

py::tuple SampleOrbit(const Orbit& orbit, int count) {
  if (count < 2 || count > 10000000) throw InvalidInput("n", count, "2 <= n <= 1e7");
  std::vector<State> states;
  {
    py::gil_scoped_release release;
    states = orbit.Sample(count);
  }
  const double period = orbit.Period();
  py::array_t<double> t(count);
  for (int k = 0; k < count; ++k) t.mutable_at(k) = period * k / (count - 1);
  return py::make_tuple(t, StateArray(states));
}

py::array_t<double> StateArray(const std::vector<State>& states) { return StateArray(states, 4); }

void BindOrbits(py::module_& m) {
  BindParameters(m);
  BindSignature(m);
  BindSolvedOrbit(m);
  m.def("_preset_names", [] {
    py::list names;
    for (const PaperExample& e : PaperExamples()) names.append(std::string(e.name));
    return names;
  });
  m.def("_preset", &PresetDict, py::arg("name"));
  m.def("_simulate", &Simulate, py::arg("start"), py::arg("periods"), py::arg("method"), py::arg("samples_per_period"));
  m.def("_simulate_model", &SimulateModel, py::arg("model"), py::arg("set"), py::arg("periods"), py::arg("method"),
        py::arg("samples_per_period"));
  m.def("_solve", &Solve, py::arg("start"), py::arg("shooting"), py::arg("linear_solver"));
  // solve(point=) at a [model]'s label: whether it is one, and the orbit solved there (as
  // `stickslip solve --point --json` prints it), ConvergenceError where Newton does not converge.
  m.def("_holds_model_point", [](const std::string& results, const std::string& point) {
    return HoldsModelRun(results, RunAndLabel(point).first);
  }, py::arg("results"), py::arg("point"));
  m.def(
      "_solve_model_label",
      [](const std::string& results, const std::string& point, const std::string& shooting,
         const std::string& linear_solver) {
        const OrbitSolverOptions options = SolverOptionsOf(shooting, linear_solver);
        std::optional<ModelFindRun> solved;
        {
          py::gil_scoped_release release;
          solved = SolveAtModelLabel(results, point, options);
        }
        const auto& found = solved->found;
        if (!found.solution->summary.Converged()) {
          RaiseConvergenceError(fmt::format("{}: Newton did not converge from the stored orbit: {}", point,
                                            found.solution->summary.BriefReport()),
                                SummaryDict(found.solution->summary));
        }
        return ModelFindJson(solved->model, found);
      },
      py::arg("results"), py::arg("point"), py::arg("shooting"), py::arg("linear_solver"));
  m.def("_simulate_defaults", [] {
    const SimulateCommand c;
    py::dict d;
    d["periods"] = c.periods;
    d["method"] = c.method;
    d["samples_per_period"] = static_cast<int>(c.samples_per_period);
    return d;
  });
  m.def("_find_defaults", [] {
    const FindCommand c;
    py::dict d;
    d["transients"] = static_cast<int>(c.transients);
    d["max_multiple"] = static_cast<int>(c.max_multiple);
    d["tolerance"] = c.tolerance;
    d["confirmations"] = static_cast<int>(c.confirmations);
    return d;
  });
  m.def(
      "_find",
      [](const py::dict& start, double transients, double max_multiple, double tolerance, double confirmations) {
        return Find(start, FindCommand{transients, max_multiple, tolerance, confirmations});
      },
      py::arg("start"), py::arg("transients"), py::arg("max_multiple"), py::arg("tolerance"), py::arg("confirmations"));
  // A run file's [model]: what describe --json and find --model --json print (io/model_summary.hpp,
  // io/model_orbit_json.hpp), as JSON text for the package to load.
  m.def("_describe_model", [](const std::string& path) { return ModelSummaryJson(SummarizeModel(path)); },
        py::arg("path"));
  m.def(
      "_find_model",
      [](const std::string& path, const NamedValues& set, double transients, double max_multiple) {
        const int periods = WholeNumber("transients", transients, kMinModelTransients, kMaxModelTransients);
        const int multiple = WholeNumber("max_multiple", max_multiple, 1, ModelFindOptions::kMaxMultiple);
        py::gil_scoped_release release;
        const ModelFindRun run = FindModelOrbitOf(ReadModelFileStart(path, set), periods, multiple);
        return ModelFindJson(run.model, run.found);
      },
      py::arg("path"), py::arg("set"), py::arg("transients"), py::arg("max_multiple"));
  // The model's state at t = 0 by name (x10, x20, v10, v20), and the variables of an n-segment
  // orbit before its parameters (x10, x20, v10, phi, d1..dn), unknowns unless fixed (FreeIndices).
  m.def("_initial_state", [] { return Model().initial_state; });
  m.def("_orbit_start_variables", [](int n) {
    std::vector<std::string> names;
    for (int i = 0; i < ov::FirstParameter(n); ++i) names.push_back(ov::Name(n, i));
    return names;
  }, py::arg("n"));
  m.def("_set_keys", [] {
    py::list keys;
    for (const SetKey& k : SetKeys()) {
      keys.append(py::make_tuple(std::string(k.key), std::string(k.meaning), std::string(k.valid_range)));
    }
    return keys;
  });
}

void BindErrors(py::module_& m) {
  m.attr("ConvergenceError") = py::reinterpret_steal<py::object>(
      PyErr_NewExceptionWithDoc("stickslip.ConvergenceError",
                                "Newton did not converge (a solve, or the start of a continuation); `summary` "
                                "holds the Newton summary.",
                                PyExc_RuntimeError, nullptr));
  convergence_error_type = m.attr("ConvergenceError").ptr();
  // Bad input is ValueError with the command line's one line, the fields named as the options.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InvalidInput& e) {
      PyErr_SetString(PyExc_ValueError, OnCommandLine(e).what());
    }
  });
}

}  // namespace stickslip::python

PYBIND11_MODULE(_stickslip, m) {
  m.doc() = "The compiled core of the stickslip package; use `import stickslip`.";
  m.attr("__version__") = stickslip::Version();
  stickslip::python::BindErrors(m);
  stickslip::python::BindOrbits(m);
  stickslip::python::BindBranches(m);
  stickslip::python::BindTraces(m);
  stickslip::python::BindAtlas(m);
}
