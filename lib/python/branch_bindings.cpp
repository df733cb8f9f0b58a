// Branches for Python: a continuation run given by keywords (as `stickslip continue`) or by a run
// file (as `stickslip run`), continued in one call or stepped by hand, its stored form with the
// library's one writer and reader of result files, and brute-force sweeps.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "bindings.hpp"
#include "stickslip/analysis/sweep.hpp"
#include "stickslip/branches/bifurcation_branches.hpp"
#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/model_sweep.hpp"
#include "stickslip/io/model_restart.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/io/run_file.hpp"
#include "stickslip/io/stored_run.hpp"
#include "stickslip/numerics/parallel_for.hpp"

namespace stickslip::python {

namespace {

namespace fs = std::filesystem;

std::vector<double> FiniteNumbers(const py::handle& values, const std::string& field) {
  std::vector<double> numbers = values.cast<std::vector<double>>();
  for (double v : numbers) {
    if (!std::isfinite(v)) throw InvalidInput(field, v, "finite numbers");
  }
  return numbers;
}

RunInput OneOffRun(const py::dict& start, const py::dict& o) {
  RunInput input;
  RunFile& run = input.run;
  input.results = o["results"].cast<std::string>();
  run = AsOneOffRun(std::move(run));
  // A [model]'s label: only its run and label here, as on the command line (ModelPointOf).
  py::dict paper_start(start);
  const auto model_point = ModelPointOf(input.results, start.contains("point") && !start["point"].is_none()
                                                            ? start["point"].cast<std::string>()
                                                            : std::string());
  if (model_point) paper_start.attr("pop")("point");
  run = WithStart(std::move(run), ToStartInput(paper_start));
  if (model_point) std::tie(run.restart_run, run.restart_label) = *model_point;
  run.restart_switch_branch = KeywordTrueOrFalse(o["switch_branch"], "switch_branch");
  if (run.restart_switch_branch && run.restart_label.empty()) {
    throw InvalidInput("switch_branch", "True", "True with point='RUN:LABEL' at a PD or an SB; False");
  }
  run.restart_boundary = o["boundary"].cast<std::string>();
  if (!run.restart_boundary.empty() && run.restart_label.empty()) {
    throw InvalidInput("boundary", "'" + run.restart_boundary + "'",
                       "a second parameter with point='RUN:LABEL' at a located special point; None");
  }
  run.output = o["output"].cast<std::string>();
  run.parameter = o["parameter"].cast<std::string>();
  run.direction = ContinuationDirection(o["direction"].cast<std::string>());
  const auto range = o["range"].cast<std::pair<double, double>>();
  run.range_min = range.first;
  run.range_max = range.second;
  run.steps = StepsOf(o, run.steps);
  run.max_amplitude = o["max_amplitude"].cast<double>();
  run.resonance_approach = o["resonance_approach"].cast<double>();
  run.shooting = o["shooting"].cast<std::string>();
  if (!ShootingChoiceFromString(run.shooting)) throw InvalidInput("shooting", "'" + run.shooting + "'", "auto, single, multiple");
  run.linear_solver = o["linear_solver"].cast<std::string>();
  if (!LinearSolverFromString(run.linear_solver)) {
    throw InvalidInput("linear-solver", "'" + run.linear_solver + "'", "klu, umfpack, dense");
  }
  CheckLinearSolverIsUsed(o["linear_solver_given"].cast<bool>() ? run.linear_solver : "", run.shooting);
  run.detect_folds = KeywordTrueOrFalse(o["detect_folds"], "detect_folds");
  run.detect_branch_points = KeywordTrueOrFalse(o["detect_branch_points"], "detect_branch_points");
  run.continue_past_type_changes = KeywordTrueOrFalse(o["continue_past_type_changes"], "continue_past_type_changes");
  for (double v : FiniteNumbers(o["user_values"], "user_values")) run.user_values.emplace_back(run.parameter, v);
  for (const auto& [name, values] : o["user_values_of"].cast<py::dict>()) {
    const std::string key = name.cast<std::string>();
    for (double v : FiniteNumbers(values, "user_values_of")) run.user_values.emplace_back(key, v);
  }
  CheckRunValues(run);  // every field set: the rules join several
  return input;
}

// A run file of one branch or of a trace ([trace]): the Python layer runs the one it is.
RunInput RunFileInput(const std::string& path, const std::string& results) { return RunInput{ReadRunFile(path), results}; }

// A continuation's run: one branch. A trace run file is refused here (stickslip.run traces it).
const RunInput& OneBranch(const RunInput& input) {
  if (input.run.trace) {
    throw RunFileError(fmt::format("{}: [trace] is invalid here: valid a run file of one branch (trace it with "
                                   "stickslip.run or stickslip.trace)",
                                   input.run.path),
                       "trace");
  }
  return input;
}

// A branch that did not start ends nothing: a start that did not converge raises ConvergenceError,
// as the command line exits 3; a first point outside the range (a switched branch's, ds from its
// label) raises the run file's error (ValueError), as the command line refuses it.
void RaiseUnlessStarted(const RunInput& input, const Branch& branch) {
  if (branch.end != BranchEnd::kStartFailed) {
    CheckRangeHoldsFirstPoint(input.run, branch);
    return;
  }
  py::dict summary;
  summary["termination"] = ToString(branch.end);
  summary["message"] = branch.end_message;
  RaiseConvergenceError(fmt::format("{}: {}", RunInMessages(input.run), branch.end_message), summary);
}

// A branch computed in this process: its stored form, and what the engine knew of it, so that the
// branch leaving one of its bifurcations starts from the engine's own point and tangent (a BP
// needs them: result files do not keep the tangent).
struct ComputedRun {
  RunInput input;
  std::optional<OrbitContinuationSetup> setup;  // the paper's; none for a [model]'s (no switching)
  std::vector<SpecialPoint> special_points;  // the engine's, one per row of stored.special_points
  StoredRun stored;
};

ComputedRun Computed(const RunInput& input, OrbitContinuationSetup setup, const OrbitBranch& branch) {
  RaiseUnlessStarted(input, branch.branch);
  StoredRun stored = RecordRun(input.run, branch);
  return {input, std::move(setup), branch.branch.special_points, std::move(stored)};
}

// The continuation of `setup` (either model's) with the GIL released. Between steps the GIL is taken
// for a moment to see Ctrl-C (KeyboardInterrupt), which ends the continuation there.
template <typename Setup>
auto Continued(const Setup& setup) {
  py::gil_scoped_release release;
  return ContinueOrbit(setup, [](const Branch&) {
    const py::gil_scoped_acquire acquire;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  });
}

ComputedRun ContinueSetup(const RunInput& input, OrbitContinuationSetup setup) {
  const OrbitBranch branch = Continued(setup);
  return Computed(input, std::move(setup), branch);
}

ComputedRun Continue(const RunInput& input) {
  OneBranch(input);
  if (const std::optional<ModelRunSetup> model = MakeModelSetup(input.run, input.results)) {
    const BasicOrbitBranch<DynamicLinearOscillator> branch = Continued(model->setup);
    RaiseUnlessStarted(input, branch.branch);
    return {input, std::nullopt, branch.branch.special_points, model->Recorded(input.run, branch)};
  }
  OrbitContinuationSetup setup = [&] {
    const py::gil_scoped_release release;  // a restart from a PD or an SB solves its point first
    return MakeSetup(input.run, input.results);
  }();
  return ContinueSetup(input, std::move(setup));
}

// The branch that leaves the special point `label` of `from` on the side `side` (BranchFromBifurcation
// with the engine's tangent), continued with `from`'s options but those given in `o` (range, ds,
// ds_min, ds_max, max_points, output; None: from's). Recorded as a one-off run restarted at the
// label with switch_branch, as `restart = { run, label, switch_branch = true }` describes it.
ComputedRun Switch(const ComputedRun& from, const std::string& label, int side, const py::dict& o) {
  if (!from.setup) {
    throw InvalidInput("label", "'" + label + "'",
                       fmt::format("a label of a saved branch for a [model]'s: save() it, then continue_orbit(point="
                                   "'RUN:{}', switch_branch=True, results=...) (or trace() with follow_bifurcations=)",
                                   label));
  }
  const std::vector<StoredSpecialPoint>& rows = from.stored.special_points;
  const auto row = std::find_if(rows.begin(), rows.end(), [&](const StoredSpecialPoint& s) { return s.point.label == label; });
  if (row == rows.end()) {
    std::vector<std::string> labels;
    for (const StoredSpecialPoint& s : rows) labels.push_back(s.point.label);
    throw InvalidInput("label", "'" + label + "'", fmt::format("a label of the branch: {}", fmt::join(labels, ", ")));
  }
  RunInput next = from.input;
  RunFile& run = next.run;
  run = AsOneOffRun(std::move(run));
  run.restart_run = from.stored.summary.output;
  run.restart_label = label;
  run.restart_switch_branch = true;
  run.direction = side;
  run.user_values.clear();  // they address the unknowns of `from`'s problem
  const auto given = [&](const char* key) { return o.contains(key) && !o[key].is_none(); };
  if (given("output")) run.output = o["output"].cast<std::string>();
  if (given("range")) std::tie(run.range_min, run.range_max) = o["range"].cast<std::pair<double, double>>();
  run.steps = StepsOf(o, run.steps);
  CheckRunValues(run);
  OrbitContinuationSetup setup = [&] {
    const py::gil_scoped_release release;
    return BranchFromBifurcation(from.special_points[row - rows.begin()], *from.setup, side).setup;
  }();
  setup.options = WithContinuationKeys(std::move(setup.options), run);  // the direction is the side, as MakeSetup has it
  setup.options.user_values.clear();
  return ContinueSetup(next, std::move(setup));
}

// A run's directory: its three files through the library's one writer, the name of the directory
// in summary.json's "output" (so that a restart by name finds it), other files kept.
std::vector<std::string> Save(const StoredRun& run, const std::string& directory) {
  const auto [root, name] = SplitRunDirectory(directory);
  StoredRun named = run;
  named.summary.output = name;
  return WriteRunFiles(root, named);
}

py::dict SummaryOf(const StoredRun& run) {
  const StoredSummary& s = run.summary;
  py::dict d;
  d["run_file"] = s.run_file;
  d["stickslip_version"] = s.stickslip_version;
  d["output"] = s.output;
  d["signature"] = s.signature;
  d["parameter"] = s.parameter;
  d["shooting"] = s.shooting;
  d["termination"] = s.termination;
  d["message"] = s.message;
  return d;
}

// The continuation stepped by hand: the setup, the orbit problem and the engine, owned together
// so that the engine's references stay valid as long as Python holds the object.
class Stepper {
 public:
  explicit Stepper(const RunInput& input)
      : input_(OneBranch(input)),
        setup_(MakeSetup(input_.run, input_.results)),
        continuation_(std::make_unique<OrbitContinuation>(setup_)) {}

  bool Step() {
    bool more = false;
    std::optional<Branch> started;  // after the first step: the start, seen as RaiseUnlessStarted sees it
    {
      py::gil_scoped_release release;
      const std::lock_guard<std::mutex> lock(mutex_);  // one step at a time, whatever the threads
      more = continuation_->Step();
      const Branch& branch = continuation_->branch();
      if (branch.points.size() <= 1) started = branch;
    }
    if (started) RaiseUnlessStarted(input_, *started);
    return more;
  }

  // The inspections wait for a step running in another thread.
  int Size() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return static_cast<int>(continuation_->branch().points.size());
  }
  bool Ended() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return continuation_->branch().end != BranchEnd::kRunning;
  }
  std::string End() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return ToString(continuation_->branch().end);
  }
  std::string EndMessage() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return continuation_->branch().end_message;
  }

  // Point i (0-based) as the result files have it: the orbit's variables, then every column.
  py::dict Point(int i) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    const Branch& branch = continuation_->branch();
    const int size = static_cast<int>(branch.points.size());
    if (i < 0) i += size;
    if (i < 0 || i >= size) throw py::index_error(fmt::format("point {} of {}", i, size));
    const BranchPoint& p = branch.points[i];
    py::dict d;
    d["pt"] = i + 1;
    d["label"] = PointLabels(branch)[i];
    d["lambda"] = p.lambda;
    const OrbitContinuationProblem& problem = continuation_->problem();
    for (const auto& [name, value] : SolutionColumns(ToOrbit(*problem.system, p.u))) {
      d[py::str(name)] = value;
    }
    const std::vector<PointColumn>& columns = problem.monitor->Columns();
    const std::vector<double> values = ColumnValues(columns, p);
    for (std::size_t k = 0; k < columns.size(); ++k) d[py::str(columns[k].name)] = values[k];
    d["newton_iterations"] = p.newton_iterations;
    d["step_size"] = p.ds;
    return d;
  }

  ComputedRun Stored() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    const OrbitBranch branch = continuation_->Result();
    return {input_, setup_, branch.branch.special_points, RecordRun(input_.run, branch)};
  }

 private:
  RunInput input_;
  OrbitContinuationSetup setup_;
  std::unique_ptr<OrbitContinuation> continuation_;
  mutable std::mutex mutex_;
};

// ---- sweep

// The paper's model's sweep, or (with `model`) a run file's [model]'s.
struct SweepResult {
  std::vector<SweepPoint> points;
  int parameter = 0;  // its index among the model's parameters
  double phi_section = 0.0;
  int threads = 1;  // the threads the sweep ran on
  int chains = 1;
  std::optional<DynamicLinearOscillator> model;

  std::string ParameterName() const {
    return (model ? model->Description() : Pascal2014{}.Description()).parameters[parameter].name;
  }
  std::string Csv() const {
    return model ? SweepCsv(*model, points, parameter, phi_section) : SweepCsv(Pascal2014{}, points, parameter, phi_section);
  }
};

SweepCommand SweepCommandOf(const py::dict& o) {
  SweepCommand command;
  command.parameter = o["parameter"].cast<std::string>();
  command.from = o["from"].cast<double>();
  command.to = o["to"].cast<double>();
  command.steps = o["steps"].cast<double>();
  command.transients = o["transients"].cast<double>();
  command.periods = o["periods"].cast<double>();
  command.start = o["start"].cast<std::string>();
  command.chains = o["chains"].cast<double>();
  command.scatter = o["scatter"].cast<double>();
  command.seed = o["seed"].cast<double>();
  command.threads = o["threads"].cast<double>();
  return command;
}

SweepResult RunSweep(const py::dict& start, const py::dict& o) {
  const ModelStart origin = BuildModelStart(ToStartInput(start));
  const SweepPlan plan = PlanSweep(SweepCommandOf(o), Pascal2014{}.Description());
  SweepResult result;
  result.parameter = plan.options.parameter;
  result.phi_section = origin.phi;
  result.chains = plan.chains;
  const int items = plan.options.start == SweepStart::kChained ? result.chains
                                                                : result.chains * (plan.options.steps + 1);
  result.threads = WorkerCount(plan.options.threads, items);
  {
    py::gil_scoped_release release;
    result.points = Sweep(origin.parameters, ScatteredStarts(origin.initial_state, plan.scatter, plan.chains, plan.seed),
                          origin.phi, plan.options);
  }
  return result;
}

// A run file's [model] swept from rest (io/model_sweep.hpp), as `stickslip sweep --model`.
SweepResult RunModelSweep(const std::string& path, const NamedValues& set, const py::dict& o) {
  const ModelFileStart start = ReadModelFileStart(path, set);
  const SweepCommand command = SweepCommandOf(o);
  std::optional<ModelSweepRun> run;
  {
    py::gil_scoped_release release;
    run.emplace(SweepModel(start, command));
  }
  return {std::move(run->points), run->options.parameter, run->phi, run->threads, run->chains, std::move(run->model)};
}

template <typename T, typename Get>
py::array_t<T> Column(const SweepResult& r, Get get) {
  py::array_t<T> a(static_cast<py::ssize_t>(r.points.size()));
  for (std::size_t i = 0; i < r.points.size(); ++i) a.mutable_at(i) = get(r.points[i]);
  return a;
}

void BindSweep(py::module_& m) {
  py::class_<SweepResult>(m, "SweepResult",
                          "A brute-force sweep: one row per (chain, pass, step), ordered by chain, pass (up\n"
                          "before down) and step whatever the threads; `section` holds the recorded\n"
                          "stroboscopic states, shape (rows, periods, 4).")
      .def_property_readonly("parameter", [](const SweepResult& r) { return r.ParameterName(); })
      .def_property_readonly("section_phase", [](const SweepResult& r) { return r.phi_section; })
      .def_property_readonly("threads", [](const SweepResult& r) { return r.threads; },
                             "the threads the sweep ran on")
      .def_property_readonly("chains", [](const SweepResult& r) { return r.chains; })
      .def_property_readonly("value", [](const SweepResult& r) { return Column<double>(r, [](auto& p) { return p.value; }); },
                             "the swept parameter's value")
      .def_property_readonly("chain", [](const SweepResult& r) { return Column<int>(r, [](auto& p) { return p.chain; }); })
      .def_property_readonly("step", [](const SweepResult& r) { return Column<int>(r, [](auto& p) { return p.step; }); })
      .def_property_readonly("passes",
                             [](const SweepResult& r) {
                               py::list l;
                               for (const SweepPoint& p : r.points) l.append(ToString(p.pass));
                               return l;
                             },
                             "'up', 'down' or 'fixed' per row")
      .def_property_readonly("stops_per_period",
                             [](const SweepResult& r) { return Column<double>(r, [](auto& p) { return p.stops_per_period; }); })
      .def_property_readonly("sticks_per_period",
                             [](const SweepResult& r) { return Column<double>(r, [](auto& p) { return p.sticks_per_period; }); })
      .def_property_readonly("period", [](const SweepResult& r) { return Column<int>(r, [](auto& p) { return p.period; }); },
                             "the period of the motion in forcing periods; 0 if none was found")
      .def_property_readonly("section",
                             [](const SweepResult& r) {
                               const py::ssize_t rows = static_cast<py::ssize_t>(r.points.size());
                               const py::ssize_t k = rows == 0 ? 0 : static_cast<py::ssize_t>(r.points[0].section.size());
                               const py::ssize_t n = k == 0 ? 4 : static_cast<py::ssize_t>(r.points[0].section[0].size());
                               py::array_t<double> a({rows, k, n});
                               for (py::ssize_t i = 0; i < rows; ++i) {
                                 for (py::ssize_t j = 0; j < k; ++j) {
                                   for (py::ssize_t c = 0; c < n; ++c) a.mutable_at(i, j, c) = r.points[i].section[j](c);
                                 }
                               }
                               return a;
                             })
      .def("csv", [](const SweepResult& r) { return r.Csv(); },
           "The CSV text `stickslip sweep --output` writes for the same sweep")
      .def("__len__", [](const SweepResult& r) { return r.points.size(); });
  m.def("_sweep", &RunSweep, py::arg("start"), py::arg("options"));
  m.def("_sweep_model", &RunModelSweep, py::arg("path"), py::arg("set"), py::arg("options"));
}

}  // namespace

BranchSteps StepsOf(const py::dict& o, BranchSteps steps) {
  const auto given = [&](const char* key) { return o.contains(key) && !o[key].is_none(); };
  if (given("ds")) steps.ds = o["ds"].cast<double>();
  if (given("ds_min")) steps.ds_min = o["ds_min"].cast<double>();
  if (given("ds_max")) steps.ds_max = o["ds_max"].cast<double>();
  if (given("max_points")) {
    steps.max_points = KeywordWholeNumber(o["max_points"], "max-points", WholeNumberRange("max-points", 1, kMaxRunPoints));
  }
  return steps;
}

int KeywordWholeNumber(const py::handle& value, const std::string& field, std::string_view valid) {
  const auto refuse = [&] { return InvalidInput(field, std::string(py::repr(value)), std::string(valid)); };
  if (py::isinstance<py::bool_>(value) || !(PyIndex_Check(value.ptr()) || PyFloat_Check(value.ptr()))) throw refuse();
  double x = 0;
  try {
    x = py::float_(py::reinterpret_borrow<py::object>(value));
  } catch (const py::error_already_set&) {  // an int too large for a double
    throw refuse();
  }
  if (!(std::trunc(x) == x && std::abs(x) <= std::numeric_limits<int>::max())) throw refuse();
  return static_cast<int>(x);
}

bool KeywordTrueOrFalse(const py::handle& value, const std::string& field) {
  if (!py::isinstance<py::bool_>(value)) throw InvalidInput(field, std::string(py::repr(value)), "True or False");
  return value.cast<bool>();
}

std::pair<fs::path, std::string> SplitRunDirectory(const std::string& directory) {
  const fs::path path = fs::absolute(fs::path(directory)).lexically_normal();
  const fs::path name = path.filename().empty() ? path.parent_path().filename() : path.filename();
  const fs::path root = path.filename().empty() ? path.parent_path().parent_path() : path.parent_path();
  if (!IsRunName(name.string())) throw InvalidInput("directory", "'" + directory + "'", std::string(kRunNameRule));
  return {root, name.string()};
}

void BindBranches(py::module_& m) {
  py::class_<RunInput>(m, "_RunInput")
      .def_property_readonly("output", [](const RunInput& r) { return r.run.output; })
      .def_property_readonly("parameter", [](const RunInput& r) { return r.run.parameter; })
      .def_property_readonly("path", [](const RunInput& r) { return r.run.path; })
      .def_property_readonly("is_trace", [](const RunInput& r) { return r.run.trace.has_value(); });
  m.def("_one_off_run", &OneOffRun, py::arg("start"), py::arg("options"));
  m.def("_run_file", &RunFileInput, py::arg("path"), py::arg("results"));
  m.def("_continue", &Continue, py::arg("run"));
  py::class_<ComputedRun>(m, "_ComputedRun")
      .def_property_readonly("stored", [](const ComputedRun& r) { return r.stored; })
      .def("switch", &Switch, py::arg("label"), py::arg("side"), py::arg("options"));
  // The defaults of the keywords, stated once: a run file's (the engine's) and the sweep's.
  m.def("_continuation_defaults", [] {
    const RunFile run;
    py::dict d;
    d["ds"] = run.steps.ds;
    d["ds_min"] = run.steps.ds_min;
    d["ds_max"] = run.steps.ds_max;
    d["max_points"] = run.steps.max_points;
    d["shooting"] = run.shooting;
    d["linear_solver"] = run.linear_solver;
    d["detect_folds"] = run.detect_folds;
    d["detect_branch_points"] = run.detect_branch_points;
    d["continue_past_type_changes"] = run.continue_past_type_changes;
    d["max_amplitude"] = run.max_amplitude;
    d["resonance_approach"] = run.resonance_approach;
    return d;
  });
  m.def("_sweep_defaults", [] {
    const SweepCommand c;
    py::dict d;
    d["parameter"] = c.parameter;
    d["steps"] = static_cast<int>(c.steps);
    d["transients"] = static_cast<int>(c.transients);
    d["periods"] = static_cast<int>(c.periods);
    d["start"] = c.start;
    d["chains"] = static_cast<int>(c.chains);
    d["scatter"] = c.scatter;
    d["seed"] = static_cast<int>(c.seed);
    d["threads"] = static_cast<int>(c.threads);
    return d;
  });

  py::class_<StoredRun>(m, "_StoredRun")
      .def("files",
           [](const StoredRun& r) {
             const RunFiles f = FormatRunFiles(r);
             return py::make_tuple(f.branch_csv, f.special_points_csv, f.summary_json);
           })
      .def("save", &Save, py::arg("directory"))
      .def_static("load", [](const std::string& directory) { return ReadRunFiles(directory); }, py::arg("directory"))
      .def_property_readonly("summary", &SummaryOf)
      .def(
          "sample",
          [](const StoredRun& r, int point, int n) {
            const int size = static_cast<int>(r.branch.size());
            if (point < 0) point += size;
            if (point < 0 || point >= size) throw py::index_error(fmt::format("point {} of {}", point, size));
            return SampleOrbit(OrbitOf(r, r.branch[point]), n);
          },
          py::arg("point"), py::arg("n"))
      .def("__len__", [](const StoredRun& r) { return r.branch.size(); });

  py::class_<Stepper>(m, "_Stepper")
      .def(py::init<RunInput>(), py::arg("run"))
      .def("step", &Stepper::Step)
      .def("__len__", &Stepper::Size)
      .def("point", &Stepper::Point, py::arg("index"))
      .def_property_readonly("ended", &Stepper::Ended)
      .def_property_readonly("end", &Stepper::End)
      .def_property_readonly("end_message", &Stepper::EndMessage)
      .def("stored", &Stepper::Stored);

  BindSweep(m);
}

}  // namespace stickslip::python
