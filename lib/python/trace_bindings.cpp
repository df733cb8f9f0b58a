// Traces and brute-force maps for Python: a trace (branches/trace.hpp) of a run given by keywords
// (as `stickslip trace`) or by a run file with a [trace] table (as `stickslip run`), stored with
// the library's one writer and reader of trace files; the brute-force map over two parameters (as
// `stickslip map-sweep`) with its one CSV writer and reader.
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "stickslip/io/model_restart.hpp"
#include "stickslip/io/model_trace.hpp"
#include "stickslip/analysis/brute_force_map.hpp"
#include "stickslip/branches/trace.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/atomic_file.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/map_file.hpp"
#include "stickslip/io/model_map.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/io/trace_files.hpp"

namespace stickslip::python {

namespace {

namespace fs = std::filesystem;

// ---- trace

// The trace options given as keywords, checked as `stickslip trace` checks its options and named
// as it names them (--max-branches, --max-amplitude, --loop-tolerance).
TraceOptions TraceOptionsOf(const py::dict& o) {
  TraceOptions options;
  const std::string branches = WholeNumberRange("max-branches", 1, kMaxTraceBranches);
  options.max_branches = stickslip::WholeNumber("max-branches", KeywordWholeNumber(o["max_branches"], "max-branches", branches),
                                                1, kMaxTraceBranches);
  options.max_amplitude = o["max_amplitude"].cast<double>();
  options.loop_tolerance = o["loop_tolerance"].cast<double>();
  options.follow_past_unswitched = KeywordTrueOrFalse(o["follow_past_unswitched"], "follow_past_unswitched");
  options.allow_inadmissible = KeywordTrueOrFalse(o["allow_inadmissible"], "allow_inadmissible");
  options.follow_bifurcations =
      KeywordWholeNumber(o["follow_bifurcations"], "follow-bifurcations", WholeNumberRange("follow-bifurcations", 0, kMaxTraceBranches));
  try {
    options.Validate();
  } catch (const InvalidInput& e) {
    std::string option = e.field();
    std::replace(option.begin(), option.end(), '_', '-');
    throw e.Renamed(option);
  }
  return options;
}

// The trace of `setup` (either model's) with input.run's [trace] options, the GIL released; raises as
// Trace says.
template <typename Setup>
auto Traced(const RunInput& input, const Setup& setup) {
  decltype(TraceOrbits(setup, TraceOptions{})) result;
  {
    py::gil_scoped_release release;
    TraceOptions trace = *input.run.trace;
    trace.progress = [](const Progress&) {
      const py::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    };
    result = TraceOrbits(setup, trace);
  }
  if (result.NotAMotion()) throw py::value_error(fmt::format("{}: {}", RunInMessages(input.run), result.down.message));
  if (!result.HasBranches()) {
    py::dict summary;
    summary["termination"] = ToString(result.down.end);
    summary["message"] = result.down.message;
    RaiseConvergenceError(fmt::format("{}: {}", RunInMessages(input.run), result.down.message), summary);
  }
  return result;
}

// The trace of `input` with `options` (a dict of the keywords) or, for None, the run file's
// [trace] table; the GIL is released while it runs, taken after every point to see Ctrl-C. A trace
// whose first branch did not start raises ConvergenceError, as the command line exits 3; one whose
// start is not a motion (and allow_inadmissible not set) raises ValueError, where it exits 4.
StoredTrace Trace(RunInput input, const py::object& options) {
  if (!options.is_none()) input.run.trace = TraceOptionsOf(options.cast<py::dict>());
  if (!input.run.trace) {
    throw RunFileError(fmt::format("{}: [trace] is missing: valid a run file with a [trace] table", input.run.path), "trace");
  }
  if (input.run.continue_past_type_changes) {
    throw InvalidInput("continue_past_type_changes", "True", "False (a trace decides at every change of type)");
  }
  if (std::optional<ModelRunSetup> model = MakeModelSetup(input.run, input.results)) {
    return model->Recorded(input.run, Traced(input, model->setup));
  }
  return RecordTrace(input.run, Traced(input, MakeSetup(input.run, input.results)));
}

std::vector<std::string> SaveTrace(const StoredTrace& trace, const std::string& directory) {
  const auto [root, name] = SplitRunDirectory(directory);
  StoredTrace named = trace;
  named.output = name;
  return WriteTraceFiles(root, named);
}

py::dict BranchOf(const StoredTraceBranch& b) {
  py::dict d;
  d["name"] = b.name;
  d["chain"] = b.chain;
  d["direction"] = b.direction;
  d["signature"] = b.signature;
  d["points"] = b.points;
  d["start"] = b.start;
  d["margin"] = b.margin;
  if (b.has_switch) {
    py::dict s;
    s["status"] = b.type_switch.status;
    s["bifurcation"] = b.type_switch.bifurcation;
    s["edit"] = b.type_switch.edit;
    s["adjacent"] = b.type_switch.adjacent;
    s["persists"] = b.type_switch.persists;
    s["from_past"] = b.type_switch.from_past;
    d["switch"] = s;
  } else {
    d["switch"] = py::none();
  }
  d["end"] = b.end;
  d["message"] = b.message;
  return d;
}

void BindTrace(py::module_& m) {
  py::class_<StoredTrace>(m, "_StoredTrace")
      .def("files",
           [](const StoredTrace& t) {
             const TraceFiles f = FormatTraceFiles(t);
             return py::make_tuple(f.trace_csv, f.trace_json);
           })
      .def("save", &SaveTrace, py::arg("directory"))
      .def_static("load", [](const std::string& directory) { return ReadTraceFiles(directory); }, py::arg("directory"))
      .def_property_readonly("runs", [](const StoredTrace& t) { return t.runs; })
      .def_property_readonly("branches",
                             [](const StoredTrace& t) {
                               py::list l;
                               for (const StoredTraceBranch& b : t.branches) l.append(BranchOf(b));
                               return l;
                             })
      .def_property_readonly("directions",
                             [](const StoredTrace& t) {
                               py::dict d;
                               for (const StoredTraceDirection& direction : t.directions) {
                                 py::dict e;
                                 e["end"] = direction.end;
                                 e["message"] = direction.message;
                                 e["branches"] = direction.branches;
                                 d[py::str(direction.direction)] = e;
                               }
                               return d;
                             })
      .def_property_readonly("summary", [](const StoredTrace& t) {
        py::dict d;
        d["run_file"] = t.run_file;
        d["stickslip_version"] = t.stickslip_version;
        d["output"] = t.output;
        d["parameter"] = t.parameter;
        d["signature"] = t.signature;
        return d;
      });
  m.def("_trace", &Trace, py::arg("run"), py::arg("options"));
  // A run file's [model] traced from the orbit its motion settles on (io/model_trace.hpp), as the
  // JSON text of `stickslip find --model --trace --json`, for the package to load, and its stored
  // form (None where no branch started), whose save() writes what --output writes.
  m.def(
      "_trace_model",
      [](const std::string& path, const NamedValues& set, double transients, const std::string& parameter, double low,
         double high, const py::dict& options, const py::dict& steps) {
        const BranchSteps branch_steps = StepsOf(steps, {});
        CheckSteps(branch_steps);  // first, as the command line checks them
        const int periods = WholeNumber("transients", transients, kMinModelTransients, kMaxModelTransients);
        TraceOptions trace = TraceOptionsOf(options);
        py::gil_scoped_release release;
        trace.progress = [](const Progress&) {
          const py::gil_scoped_acquire acquire;
          if (PyErr_CheckSignals() != 0) throw py::error_already_set();
        };
        const ModelTraceRun run =
            TraceModel(ReadModelFileStart(path, set), periods, FindOrbitOptions{}.max_multiple, parameter, low, high, trace,
                       branch_steps);
        std::optional<StoredTrace> stored;
        if (run.trace && run.trace->HasBranches()) {
          stored = StoredModelTrace(run, path, set, "trace");
        }
        return std::make_pair(ModelTraceJson(run), std::move(stored));
      },
      py::arg("path"), py::arg("set"), py::arg("transients"), py::arg("parameter"), py::arg("low"), py::arg("high"),
      py::arg("options"), py::arg("steps"));
  m.def("_trace_defaults", [] {
    const TraceOptions o;
    py::dict d;
    d["max_branches"] = o.max_branches;
    d["max_amplitude"] = o.max_amplitude;
    d["loop_tolerance"] = o.loop_tolerance;
    d["follow_past_unswitched"] = o.follow_past_unswitched;
    d["follow_bifurcations"] = o.follow_bifurcations;
    d["allow_inadmissible"] = o.allow_inadmissible;
    return d;
  });
}

// ---- brute-force map

// The numeric keywords of map_sweep and the members they set; the defaults are MapSweepCommand's.
constexpr std::array<std::pair<const char*, double MapSweepCommand::*>, 13> kMapNumbers = {{
    {"first_from", &MapSweepCommand::first_from},
    {"first_to", &MapSweepCommand::first_to},
    {"first_steps", &MapSweepCommand::first_steps},
    {"second_from", &MapSweepCommand::second_from},
    {"second_to", &MapSweepCommand::second_to},
    {"second_steps", &MapSweepCommand::second_steps},
    {"transients", &MapSweepCommand::transients},
    {"periods", &MapSweepCommand::periods},
    {"starts", &MapSweepCommand::starts},
    {"scatter", &MapSweepCommand::scatter},
    {"seed", &MapSweepCommand::seed},
    {"tolerance", &MapSweepCommand::tolerance},
    {"threads", &MapSweepCommand::threads},
}};

// map_sweep's keywords as the command line's options (numbers not yet checked).
MapSweepCommand MapCommandOf(const py::dict& o) {
  MapSweepCommand c;
  c.first = o["first"].cast<std::string>();
  c.second = o["second"].cast<std::string>();
  for (const auto& [key, member] : kMapNumbers) c.*member = o[key].cast<double>();
  return c;
}

BruteForceMap MapSweep(const py::dict& start, const py::dict& o) {
  const ModelStart origin = BuildModelStart(ToStartInput(start));
  const BruteForceMapOptions options = MapOptionsOf(MapCommandOf(o), origin);
  const py::gil_scoped_release release;
  return ComputeBruteForceMap(origin.parameters, origin.phi, options);
}

// map_sweep(model=...): the run file's oscillator at its parameters and `set`'s, the options as
// the command line's (the axes' names empty: the model's defaults).
ModelBruteForceMap ModelMapSweep(const fs::path& path, const NamedValues& set, const py::dict& o) {
  const ModelFileStart start = ReadModelFileStart(path, set);
  const ModelBruteForceMapOptions options = ModelMapOptionsOf(MapCommandOf(o), start);
  const py::gil_scoped_release release;
  return ComputeModelBruteForceMap(start.model, start.parameters, options);
}


// The cells as columns: i, j, the two parameters' values and the attractors found in each.
template <typename Map>
py::dict CellColumns(const Map& map) {
  const auto n = static_cast<py::ssize_t>(map.cells.size());
  py::array_t<int> i(n), j(n), count(n);
  py::array_t<double> first(n), second(n);
  for (py::ssize_t k = 0; k < n; ++k) {
    const auto& cell = map.cells[k];
    i.mutable_at(k) = cell.i;
    j.mutable_at(k) = cell.j;
    first.mutable_at(k) = cell.first;
    second.mutable_at(k) = cell.second;
    count.mutable_at(k) = static_cast<int>(cell.attractors.size());
  }
  py::dict d;
  d["i"] = i;
  d["j"] = j;
  d[py::str(AxisName(map.first))] = first;
  d[py::str(AxisName(map.second))] = second;
  d["attractors"] = count;
  return d;
}

// The attractor's own column: the paper's signature, a model's contact amplitude.
void AddOwn(const Attractor& a, py::list& signature, std::vector<double>&) { signature.append(a.signature); }
void AddOwn(const ModelAttractor& a, py::list&, std::vector<double>& amplitude) { amplitude.push_back(a.contact_amplitude); }
py::array_t<double> SectionOf(const Attractor& a) { return StateArray(a.section); }
py::array_t<double> SectionOf(const ModelAttractor& a) { return StateArray(a.section, a.section.front().size()); }

// One row per attractor of every cell: its cell (index into the cells), its index in the cell,
// status, period, stops and sticks per period, starts, signature (the paper's model) or the
// contact's amplitude (a [model]'s), and section points (period x state size, or the last state,
// 1 x state size, when not periodic).
template <typename Map>
py::dict AttractorColumns(const Map& map) {
  std::vector<int> cell, index, period, starts;
  std::vector<double> stops, sticks, amplitude;
  py::list status, signature, section;
  for (std::size_t k = 0; k < map.cells.size(); ++k) {
    const auto& attractors = map.cells[k].attractors;
    for (std::size_t a = 0; a < attractors.size(); ++a) {
      const auto& attractor = attractors[a];
      cell.push_back(static_cast<int>(k));
      index.push_back(static_cast<int>(a));
      status.append(ToString(attractor.status));
      period.push_back(attractor.period);
      stops.push_back(attractor.stops_per_period);
      sticks.push_back(attractor.sticks_per_period);
      starts.push_back(attractor.starts);
      AddOwn(attractor, signature, amplitude);
      section.append(SectionOf(attractor));
    }
  }
  const auto array = [](const auto& values) {
    using T = typename std::decay_t<decltype(values)>::value_type;
    return py::array_t<T>(static_cast<py::ssize_t>(values.size()), values.data());
  };
  py::dict d;
  d["cell"] = array(cell);
  d["attractor"] = array(index);
  d["status"] = status;
  d["period"] = array(period);
  d["stops_per_period"] = array(stops);
  d["sticks_per_period"] = array(sticks);
  d["starts"] = array(starts);
  if constexpr (std::is_same_v<Map, ModelBruteForceMap>) {
    d[py::str("amplitude:" + map.contact)] = array(amplitude);
  } else {
    d["signature"] = signature;
  }
  d["section"] = section;
  return d;
}

// The result class of map_sweep for either map: its axes, cells and attractors as NumPy columns, its file.
template <typename Map>
void BindMapResult(py::module_& m, const char* name, const char* doc, const char* attractors_doc,
                   Map (*read)(std::string_view, const std::string&)) {
  py::class_<Map>(m, name, doc)
      .def_property_readonly("first", [](const Map& map) { return std::string(AxisName(map.first)); },
                             "the parameter stepped along i")
      .def_property_readonly("second", [](const Map& map) { return std::string(AxisName(map.second)); },
                             "the parameter stepped along j (a row per value)")
      .def_property_readonly("shape", [](const Map& map) { return py::make_tuple(map.first_count, map.second_count); },
                             "(cells along i, cells along j)")
      .def_property_readonly("section_phase", [](const Map& map) { return map.section_phase; },
                             "the forcing phase of the stroboscopic section, rad")
      .def_property_readonly("cells", &CellColumns<Map>,
                             "{'i', 'j', <first>, <second>, 'attractors'}: one entry per cell, by j then i")
      .def_property_readonly("attractors", &AttractorColumns<Map>, attractors_doc)
      .def("csv", [](const Map& map) { return BruteForceMapCsv(map); },
           "The CSV text `stickslip map-sweep --output` writes for the same map")
      .def(
          "save", [](const Map& map, const fs::path& path) { WriteFileAtomically(path, BruteForceMapCsv(map)); },
          py::arg("path"), "Writes csv() to `path` (whole or not at all)")
      .def_static(
          "load",
          [read](const fs::path& path) {
            std::ifstream in(path, std::ios::binary);
            if (!in) throw InvalidInput("path", "'" + path.string() + "'", "a readable map file of stickslip map-sweep");
            std::ostringstream text;
            text << in.rdbuf();
            return read(text.str(), path.string());
          },
          py::arg("path"), "The map of a file `stickslip map-sweep` (or save) wrote")
      .def("__len__", [](const Map& map) { return map.cells.size(); });
}

void BindMap(py::module_& m) {
  BindMapResult<BruteForceMap>(
      m, "MapSweepResult",
      "A brute-force map over two parameters (as `stickslip map-sweep`): `cells` and\n"
      "`attractors` as columns of NumPy arrays (see stickslip.map_sweep); csv() is the\n"
      "command line's file, save(path) writes it, MapSweepResult.load(path) reads one.",
      "one entry per attractor of every cell: 'cell' (index into cells), 'attractor',\n"
      "'status' (periodic, not-settled, incomplete), 'period' (forcing periods; 0 unless\n"
      "periodic), 'stops_per_period', 'sticks_per_period', 'starts' (the runs that ended\n"
      "on it), 'signature' ('' if none was read), 'section' (period x 4 section states\n"
      "x1, x2, v1, v2; the last state, 1 x 4, when not periodic)",
      &ReadBruteForceMapCsv);
  BindMapResult<ModelBruteForceMap>(
      m, "ModelMapSweepResult",
      "A brute-force map of an oscillator of your own over two of its parameters (as `stickslip\n"
      "map-sweep --model`): `cells` and `attractors` as columns of NumPy arrays; csv(), save(path)\n"
      "and ModelMapSweepResult.load(path) as MapSweepResult's.",
      "one entry per attractor of every cell: 'cell' (index into cells), 'attractor',\n"
      "'status' (periodic, not-settled, incomplete), 'period' (forcing periods, stick-slip cycles\n"
      "without forcing; 0 unless periodic), 'stops_per_period', 'sticks_per_period', 'starts',\n"
      "'amplitude:<contact>' (max |q| of the contact's coordinate over the recorded periods),\n"
      "'section' (period x state size, the model's units; the last state when not periodic)",
      &ReadModelBruteForceMapCsv);
  m.def("_map_sweep", &MapSweep, py::arg("start"), py::arg("options"));
  m.def("_map_sweep_model", &ModelMapSweep, py::arg("path"), py::arg("set"), py::arg("options"));
  // The defaults of the keywords, stated once (MapSweepCommand): whole numbers as int.
  m.def("_map_sweep_defaults", [] {
    const MapSweepCommand c;
    py::dict d;
    d["first"] = c.first;
    d["second"] = c.second;
    for (const auto& [key, member] : kMapNumbers) {
      const double value = c.*member;
      d[key] = std::trunc(value) == value ? py::object(py::int_(static_cast<long long>(value))) : py::object(py::float_(value));
    }
    return d;
  });
}

}  // namespace

void BindTraces(py::module_& m) {
  BindTrace(m);
  BindMap(m);
}

}  // namespace stickslip::python
