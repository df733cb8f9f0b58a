// The atlas for Python (analysis/atlas.hpp): computed from a start and keywords checked as
// `stickslip atlas` checks its options (io/command_options.hpp AtlasOptionsOf), stored with the
// library's one writer of atlas files (io/atlas_files.hpp); its traces are the stored traces
// stickslip.Trace reads.
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "stickslip/analysis/atlas.hpp"
#include "stickslip/io/atlas_files.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/model_atlas.hpp"
#include "stickslip/io/run_file.hpp"

namespace stickslip::python {

namespace {

// The numeric keywords of atlas() and the members they set; the defaults are AtlasCommand's.
constexpr std::pair<const char*, double AtlasCommand::*> kAtlasNumbers[] = {
    {"from", &AtlasCommand::from},
    {"to", &AtlasCommand::to},
    {"steps", &AtlasCommand::steps},
    {"transients", &AtlasCommand::transients},
    {"periods", &AtlasCommand::periods},
    {"starts", &AtlasCommand::starts},
    {"scatter", &AtlasCommand::scatter},
    {"seed", &AtlasCommand::seed},
    {"tolerance", &AtlasCommand::tolerance},
    {"threads", &AtlasCommand::threads},
    {"max_multiple", &AtlasCommand::max_multiple},
    {"max_amplitude", &AtlasCommand::max_amplitude},
    {"max_points", &AtlasCommand::max_points},
    {"resonance_approach", &AtlasCommand::resonance_approach},
};

AtlasCommand CommandOf(const py::dict& o) {
  AtlasCommand c;
  c.parameter = o["parameter"].cast<std::string>();
  for (const auto& [key, member] : kAtlasNumbers) c.*member = o[key].cast<double>();
  return c;
}

// `compute` run with the GIL released, taken after every stage's step to see Ctrl-C.
template <typename Options, typename Compute>
auto ComputeReleased(Options& options, Compute compute) {
  const py::gil_scoped_release release;
  options.progress = [](const Progress&) {
    const py::gil_scoped_acquire acquire;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  };
  return compute();
}

// The atlas of `start` with the keywords `o`.
StoredAtlas Atlas(const py::dict& start, const py::dict& o, const std::string& output) {
  const ModelStart origin = BuildModelStart(ToStartInput(start));
  AtlasCommand c = CommandOf(o);
  AtlasOptions options = AtlasOptionsOf(c, origin);
  RunFile run;
  run.path = "(python)";
  run.output = output;
  run.parameter = c.parameter;
  const stickslip::Atlas atlas = ComputeReleased(options, [&] { return ComputeAtlas(origin.parameters, options); });
  return RecordAtlas(run, atlas, options);
}

// The atlas of the run file's [model] (`set` over it) with the keywords `o`.
StoredAtlas ModelAtlasOf(const std::string& path, const NamedValues& set, const py::dict& o, const std::string& output) {
  const ModelFileStart start = ReadModelFileStart(path, set);
  ModelAtlasOptions options = ModelAtlasOptionsOf(CommandOf(o), start);
  const ModelAtlas atlas =
      ComputeReleased(options, [&] { return ComputeModelAtlas(start.model, start.parameters, options); });
  return StoredModelAtlas(atlas, options, start, path, set, output);
}

std::vector<std::string> SaveAtlas(const StoredAtlas& atlas, const std::string& directory) {
  const auto [root, name] = SplitRunDirectory(directory);
  StoredAtlas named = atlas;
  named.output = name;
  return WriteAtlasFiles(root, named);
}

}  // namespace

void BindAtlas(py::module_& m) {
  py::class_<StoredAtlas>(m, "_StoredAtlas")
      .def(py::init([](std::string output, std::vector<StoredTrace> traces, std::string atlas_json, std::string intervals_csv,
                       std::string brute_force_csv) {
             return StoredAtlas{std::move(output), std::move(traces),
                                {std::move(atlas_json), std::move(intervals_csv), std::move(brute_force_csv)}};
           }),
           py::arg("output"), py::arg("traces"), py::arg("atlas_json"), py::arg("intervals_csv"), py::arg("brute_force_csv"))
      .def("files",
           [](const StoredAtlas& a) {
             py::dict d;
             d["atlas.json"] = a.files.atlas_json;
             d["atlas-intervals.csv"] = a.files.intervals_csv;
             d["brute-force.csv"] = a.files.brute_force_csv;
             return d;
           })
      .def_property_readonly("traces", [](const StoredAtlas& a) { return a.traces; })
      .def("save", &SaveAtlas, py::arg("directory"));
  m.def("_atlas", &Atlas, py::arg("start"), py::arg("options"), py::arg("output"));
  m.def("_model_atlas", &ModelAtlasOf, py::arg("model"), py::arg("set"), py::arg("options"), py::arg("output"));
  m.def("_atlas_defaults", [] {
    const AtlasCommand c;
    py::dict d;
    d["parameter"] = c.parameter;
    for (const auto& [key, member] : kAtlasNumbers) {
      const double value = c.*member;
      d[key] = std::trunc(value) == value ? py::object(py::int_(static_cast<long long>(value))) : py::object(py::float_(value));
    }
    return d;
  });
}

}  // namespace stickslip::python
