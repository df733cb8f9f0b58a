// Every label any run wrote restarts (issue 22, defect 3): for each special point of every run
// directory in results/ (runs, the branches of traces and atlases, the curves of maps; a [model]'s
// too, through MakeModelSetup as `continue --point` restarts it), the start builder
// accepts its stored variables, Newton at the label's parameter converges from them to 1e-10, and
// one continuation step from it is accepted one way or the other; where the label is a family's
// end (u_s reached 0), the refusal says so. A fixed amount of work per label: one Newton solve
// and at most four one-step branches (0.7 s for the 282 labels under Release).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/run_file.hpp"
#include "stickslip/io/start_input.hpp"
#include "stickslip/io/model_find.hpp"
#include "stickslip/io/model_restart.hpp"
#include "stickslip/io/trace_files.hpp"
#include "stickslip/orbits/model_orbit_solver.hpp"

namespace stickslip {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = STICKSLIP_SOURCE_DIR;
const fs::path kResults = kSource / "results";

// Every run directory under results/, at any depth (a trace's branches, a map's curves).
std::vector<fs::path> RunDirectories() {
  std::vector<fs::path> runs;
  for (const auto& entry : fs::recursive_directory_iterator(kResults)) {
    if (entry.path().filename() == "special-points.csv") runs.push_back(entry.path().parent_path());
  }
  std::sort(runs.begin(), runs.end());
  return runs;
}

// The run file behind a run directory: its summary's run_file, or for a map's curve ("stickslip
// map (...)") that of the trace the map was drawn from (regions.json names it).
RunFile RunFileOf(const fs::path& run, const StoredSummary& summary) {
  if (!summary.run_file.starts_with("stickslip map")) return ReadRunFile(kSource / summary.run_file);
  const std::string regions = [&] {
    std::ifstream in(run.parent_path() / "regions.json");
    return std::string(std::istreambuf_iterator<char>(in), {});
  }();
  const std::size_t key = regions.find("\"trace\": \"");
  const std::size_t begin = key + 10, end = regions.find('"', begin);
  return ReadRunFile(kSource / ReadTraceFiles(kSource / regions.substr(begin, end - begin)).run_file);
}

// The run's choice of unknowns: its run file's; for a run the command line made with no run file (an
// atlas's branches, started from found orbits and switches), the unknowns at fixed parameters.
UnknownChoice UnknownsOf(const fs::path& run, const StoredSummary& summary) {
  if (summary.run_file == kOneOffRunPath) return UnknownsAtFixedParameters(Signature::Parse(summary.signature));
  return StartUnknowns(StartInputOf(RunFileOf(run, summary), kResults));
}

struct LabelCase {
  fs::path run;
  std::string label;
  std::string parameter;
  UnknownChoice unknowns;
  ShootingChoice shooting = ShootingChoice::kAuto;
};

// The run's choice of unknowns as start input: a variable the preset released and the run file
// fixed again (paper-4.2-u_s-up: u_s) is neither.
StartInput RestartInput(const LabelCase& c) {
  StartInput input;
  input.restart = ReadRestartPoint(c.run.parent_path(), c.run.filename().string(), c.label);
  const std::vector<std::string>& release = c.unknowns.release;
  const std::vector<std::string>& fix = c.unknowns.fix;
  std::copy_if(release.begin(), release.end(), std::back_inserter(input.free),
               [&](const std::string& name) { return std::find(fix.begin(), fix.end(), name) == fix.end(); });
  for (const std::string& name : fix) {
    if (std::find(release.begin(), release.end(), name) == release.end()) input.fix.push_back({name, std::nullopt});
  }
  input.tie_u_r = c.unknowns.tie_static_friction;
  input.parameter = c.parameter;
  return input;
}

// One step from the start towards `direction`, past type changes or not.
OrbitBranch OneStep(const StartProblem& start, const LabelCase& c, int direction, bool past_type_changes) {
  ContinuationOptions options;
  options.direction = direction;
  options.max_points = 2;
  options.continue_past_terminal = past_type_changes;
  return ContinueOrbit({.start = start.orbit, .unknowns = start.unknowns, .parameter = c.parameter,
                        .shooting = c.shooting, .sparse_solver = LinearSolverType::kKlu, .options = options,
                        .flow = {}, .max_amplitude = std::numeric_limits<double>::infinity()});
}

// A point beyond the start was computed and kept: the step's end, or a special point located on it.
template <typename AnyBranch>
bool Accepted(const AnyBranch& b) {
  return b.branch.points.size() >= 2;
}

// Why a branch ended at its start: a margin zero there that the first step makes negative, or a
// fold at the start where the branch runs against the asked direction on both sides.
bool SaysWhyItEndsAtTheStart(const Branch& b) {
  const bool margin = b.end == BranchEnd::kTerminalEvent &&
                      b.end_message.find("is zero at the start and the first step leaves its admissible side") != std::string::npos;
  return margin || b.end == BranchEnd::kFoldAtStart;
}

// A step is accepted one way or the other. Where neither way is admissible (a corner of the
// admissible region: a point of a type boundary's curve where a second margin is zero too, as the
// special points on a map's curves, or a type change at a fold), both ends say why, and past the
// type changes (continue_past_type_changes) a step is accepted. `step(direction, past)` is the
// branch of one step, of either model.
template <typename Step>
void ExpectOneStepOf(const Step& step) {
  const auto up = step(+1, false), down = step(-1, false);
  if (Accepted(up) || Accepted(down)) return;
  EXPECT_TRUE(SaysWhyItEndsAtTheStart(up.branch)) << up.branch.end_message;
  EXPECT_TRUE(SaysWhyItEndsAtTheStart(down.branch)) << down.branch.end_message;
  EXPECT_TRUE(Accepted(step(+1, true)) || Accepted(step(-1, true)))
      << "no step accepted either way, even past the type changes: " << up.branch.end_message << "; "
      << down.branch.end_message;
}

void ExpectOneStep(const StartProblem& start, const LabelCase& c) {
  ExpectOneStepOf([&](int direction, bool past) { return OneStep(start, c, direction, past); });
}

void ExpectRestarts(const LabelCase& c) {
  SCOPED_TRACE(fmt::format("{}:{}", c.run.string(), c.label));
  const StartInput input = RestartInput(c);
  const auto u_s = std::find_if(input.restart->values.begin(), input.restart->values.end(),
                                [](const auto& v) { return v.first == "u_s"; });
  if (u_s->second <= 0.0) {  // the family's end: the refusal says so
    try {
      BuildStartProblem(input);
      ADD_FAILURE() << "a start at u_s = " << u_s->second << " was accepted";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find("end of the physical family"), std::string::npos) << e.what();
    }
    return;
  }
  const StartProblem start = BuildStartProblem(input);
  OrbitSolverOptions solver;
  solver.shooting = c.shooting;
  solver.newton.residual_tolerance = 1e-10;
  solver.newton.estimate_condition = false;
  const OrbitSolution solved = SolveOrbit(start.orbit, start.free, start.unknowns.tie_static_friction, solver);
  EXPECT_TRUE(solved.summary.Converged()) << solved.summary.message;
  EXPECT_LE(solved.summary.residual_norms.back(), 1e-10);
  ExpectOneStep(start, c);
}

// A label of a run file's [model] (its traces' branches: `find --model --trace --output`, `atlas
// --model`) restarts as `continue --point` and `trace --point` restart from it (MakeModelSetup; the
// run file its summary names relative to the repository's root above results/, where tools/run.sh
// ran, found from any working directory): its stored
// variables are the model's orbit there, Newton at its parameters converges from them to 1e-10, and
// one continuation step in the run's parameter is accepted one way or the other.
void ExpectModelLabelRestarts(const fs::path& run, const StoredRun& stored, const StoredSpecialPoint& s) {
  SCOPED_TRACE(fmt::format("{}:{}", run.string(), s.point.label));
  RunFile restart;
  restart.output = "restarted";
  restart.restart_run = run.filename().string();
  restart.restart_label = s.point.label;
  restart.parameter = stored.summary.parameter;
  restart.range_min = -1e6;
  restart.range_max = 1e6;
  restart.max_amplitude = std::numeric_limits<double>::infinity();
  const std::optional<ModelRunSetup> model = MakeModelSetup(restart, run.parent_path());
  ASSERT_TRUE(model.has_value());
  const BasicOrbitContinuationSetup<DynamicLinearOscillator>& setup = model->setup;
  OrbitSolverOptions solver;
  solver.newton.residual_tolerance = 1e-10;
  solver.newton.estimate_condition = false;
  const OrbitVariableSet variables = VariableSetOf(setup.model, setup.start.signature);
  const BasicOrbitSolution<DynamicLinearOscillator> solved = SolveOrbit(
      setup.model, setup.start, FreeIndices(variables, UnknownsAtFixedParameters(variables)), false, solver);
  EXPECT_TRUE(solved.summary.Converged()) << solved.summary.message;
  EXPECT_LE(solved.summary.residual_norms.back(), 1e-10);
  EXPECT_LE(solved.summary.residual_norms.front(), 1e-8);  // the stored orbit is one already
  ExpectOneStepOf([&setup](int direction, bool past) {
    BasicOrbitContinuationSetup<DynamicLinearOscillator> one = setup;
    one.options.direction = direction;
    one.options.max_points = 2;
    one.options.continue_past_terminal = past;
    return ContinueOrbit(one);
  });
}

TEST(EveryLabel, RestartsOrSaysItIsTheFamilysEnd) {
  const std::vector<fs::path> runs = RunDirectories();
  ASSERT_GE(runs.size(), 70u);
  std::size_t labels = 0, model_labels = 0;
  for (const fs::path& run : runs) {
    const StoredRun stored = ReadRunFiles(run);
    if (!stored.summary.model.empty()) {
      for (const StoredSpecialPoint& s : stored.special_points) ExpectModelLabelRestarts(run, stored, s);
      model_labels += stored.special_points.size();
      continue;
    }
    const UnknownChoice unknowns = UnknownsOf(run, stored.summary);
    const ShootingChoice shooting = *ShootingChoiceFromString(stored.summary.shooting);
    for (const StoredSpecialPoint& s : stored.special_points) {
      ExpectRestarts({run, s.point.label, stored.summary.parameter, unknowns, shooting});
      ++labels;
    }
  }
  // Every stored run was visited: 263 labels when one end point carries one EP label (issue 22,
  // defect 3); a floor, so that a run added to results/ does not need this number changed.
  EXPECT_GE(labels, 250u);
  EXPECT_GE(model_labels, 10u);
  RecordProperty("model_labels", std::to_string(model_labels));
}

// A run past the changes of type (continue_past_type_changes) stores labels whose segment has a
// negative length (the section 4.1 sticking branch past its T0 at omega = 0.59998, as `continue
// --point branch-2:TR2 --direction up --continue-past-type-changes` stores them): each restarts too.
TEST(EveryLabel, PastAChangeOfTypeRestarts) {
  StartInput input;
  input.restart = ReadRestartPoint(kResults / "paper-4.1-omega-trace", "branch-2", "TR2");
  input.parameter = "omega";
  const StartProblem start = BuildStartProblem(input);
  ContinuationOptions options;
  options.lambda_max = 0.61;
  options.continue_past_terminal = true;
  options.max_points = 60;
  RunFile run;
  run.output = "past";
  run.parameter = "omega";
  const StoredRun stored = RecordRun(
      run, ContinueOrbit({.start = start.orbit, .unknowns = start.unknowns, .parameter = "omega", .options = options}));
  int negative = 0;
  for (const StoredSpecialPoint& s : stored.special_points) {
    if (!(Named(s.point.solution, "d2") < 0.0)) continue;
    ++negative;
    SCOPED_TRACE(s.point.label);
    StartInput again;
    again.restart = RestartPoint{"past", s.point.label, stored.summary.signature, s.point.solution};
    again.parameter = "omega";
    const StartProblem from = BuildStartProblem(again);
    EXPECT_EQ(from.orbit.durations[1], Named(s.point.solution, "d2"));
    ExpectOneStep(from, {"past", s.point.label, "omega", from.unknowns, ShootingChoice::kAuto});
  }
  EXPECT_GE(negative, 2);
}

}  // namespace
}  // namespace stickslip
