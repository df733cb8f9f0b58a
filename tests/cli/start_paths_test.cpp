// Every way into a computation builds the same start from the same input: a run file (read by
// ParseRunFile, set up by MakeSetup), solve's flags, continue's flags (turned into a run file,
// then MakeSetup), and for a start without orbit members simulate's and sweep's flags. Each case
// also checks a few values against the paper's printed data or the stored point.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "start_options.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/run.hpp"

namespace stickslip {
namespace {

namespace fs = std::filesystem;
namespace ov = orbit_variables;

const fs::path kResults = fs::path(STICKSLIP_SOURCE_DIR) / "results";

struct PathCase {
  const char* name;
  std::string run_file_start;     // the [start] and [unknowns] tables of a run file
  std::vector<std::string> flags;  // the same start as solve's and continue's flags
  std::string parameter;           // continued by the run file and by continue
  bool motion;                     // no orbit members: simulate and sweep take the flags too
  NamedValues expected;            // orbit variables with their independent values
};

// The start as each path sees it: its orbit variables, free indices and tie flag.
struct Seen {
  std::string signature;
  Eigen::VectorXd variables;
  std::vector<int> free;
  bool tied = false;
};

cli::StartFlags ParseFlags(std::vector<std::string> args, cli::StartOptions which) {
  cli::StartFlags flags;
  CLI::App app;
  cli::AddStartOptions(app, &flags, which);
  app.add_option("--results", flags.results);
  args.insert(args.begin(), "stickslip");
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  app.parse(static_cast<int>(argv.size()), argv.data());
  return flags;
}

Seen FromSetup(const OrbitContinuationSetup& setup) {
  return {setup.start.signature.ToString(), ov::Pack(setup.start), FreeIndices(setup.start.signature, setup.unknowns),
          setup.unknowns.tie_static_friction};
}

Seen RunFilePath(const PathCase& c) {
  const std::string text = "output = \"t\"\n" + c.run_file_start + "\n[continuation]\nparameter = \"" + c.parameter +
                           "\"\ndirection = \"up\"\nrange = [-1e9, 1e9]\n";
  return FromSetup(MakeSetup(ParseRunFile(text, "t.toml"), kResults));
}

Seen SolvePath(const PathCase& c) {
  const StartProblem start = BuildStartProblem(cli::ToStartInput(ParseFlags(c.flags, cli::StartOptions::kOrbit)));
  return {start.orbit.signature.ToString(), ov::Pack(start.orbit), start.free, start.unknowns.tie_static_friction};
}

Seen ContinuePath(const PathCase& c) {
  const cli::StartFlags flags = ParseFlags(c.flags, cli::StartOptions::kOrbit);
  RunFile run = AsOneOffRun({});
  run.output = "t";
  run.parameter = c.parameter;
  run.range_min = -1e9;
  run.range_max = 1e9;
  run = WithStart(std::move(run), cli::ToStartInput(flags));
  return FromSetup(MakeSetup(run, flags.results));
}

class StartPaths : public ::testing::TestWithParam<PathCase> {};

TEST_P(StartPaths, EveryPathBuildsTheSameStartProblem) {
  const PathCase& c = GetParam();
  const Seen solve = SolvePath(c);
  for (const auto& [name, value] : c.expected) {
    EXPECT_EQ(solve.variables(*ov::IndexOf(static_cast<int>(solve.variables.size()) - 9, name)), value) << name;
  }
  for (const Seen& other : {RunFilePath(c), ContinuePath(c)}) {
    EXPECT_EQ(other.signature, solve.signature);
    EXPECT_EQ(other.variables, solve.variables);
    EXPECT_EQ(other.free, solve.free);
    EXPECT_EQ(other.tied, solve.tied);
  }
  if (!c.motion) return;
  const ModelStart model = BuildModelStart(cli::ToStartInput(ParseFlags(c.flags, cli::StartOptions::kMotion)));
  for (ParameterId id : kAllParameters) {
    EXPECT_EQ(model.parameters[id], solve.variables(ov::Parameter(static_cast<int>(solve.variables.size()) - 9, id)));
  }
  EXPECT_EQ(model.initial_state, State(solve.variables(ov::kX10), solve.variables(ov::kX20), solve.variables(ov::kV10), 0.0));
  EXPECT_EQ(model.phi, solve.variables(ov::kPhi));
}

const std::string kResultsFlag = "--results=" + kResults.string();

INSTANTIATE_TEST_SUITE_P(
    SameInput, StartPaths,
    ::testing::Values(
        PathCase{"PresetOnly", "[start]\npreset = \"paper-5.1\"", {"--preset", "paper-5.1"}, "omega", true,
                 {{"chi", 0.22}, {"x10", -0.3643}, {"d3", 2.7337}}},
        PathCase{"PresetAndSet", "[start]\npreset = \"paper-5.1\"\nset = { u_r = 0.6, x10 = -0.3 }",
                 {"--preset", "paper-5.1", "--set", "u_r=0.6", "--set", "x10=-0.3"}, "omega", true,
                 {{"u_r", 0.6}, {"x10", -0.3}, {"eta", 4.2}}},
        PathCase{"SignatureAndGuess",
                 "[start]\nsignature = \"slip- stick slip- / antisymmetric\"\n"
                 "set = { chi = 0.7, eta = 3.8, omega = 0.5711986642890533, u_s = 0.06, u_r = 1.4041, x10 = 2.8901, "
                 "x20 = 5.1306, v10 = -0.8108, phi = 3.0 }\nguess = { d1 = 2.175, d2 = 1.56, d3 = 1.765 }",
                 {"--signature", "slip- stick slip- / antisymmetric", "--set", "chi=0.7", "--set", "eta=3.8", "--set",
                  "omega=0.5711986642890533", "--set", "u_s=0.06", "--set", "u_r=1.4041", "--set", "x10=2.8901",
                  "--set", "x20=5.1306", "--set", "v10=-0.8108", "--set", "phi=3", "--guess", "d1=2.175", "--guess",
                  "d2=1.56", "--guess", "d3=1.765"},
                 "omega", false, {{"d2", 1.56}, {"u_r", 1.4041}}},
        PathCase{"FreeAndFix", "[start]\npreset = \"paper-4.2\"\n[unknowns]\nfree = [\"omega\"]\nfix = [\"u_s\"]",
                 {"--preset", "paper-4.2", "--free", "omega", "--fix", "u_s"}, "u_s", false,
                 {{"u_s", 0.1717}, {"u_r", 0.1717}}},
        PathCase{"FixWithValue",
                 "[start]\npreset = \"paper-5.2\"\nguess = { phi = 1.5707963267948966 }\n[unknowns]\nfree = "
                 "[\"u_r\"]\nfix = [\"phi\"]",
                 {"--preset", "paper-5.2", "--fix", "phi=1.5707963267948966", "--free", "u_r"}, "omega", false,
                 {{"phi", 1.5707963267948966}, {"u_r", 0.4701}}},
        PathCase{"TieUr", "[start]\npreset = \"paper-4.1\"\n[unknowns]\ntie_u_r = true\nfree = [\"u_s\"]\nfix = [\"phi\"]",
                 {"--preset", "paper-4.1", "--tie-u_r", "--free", "u_s", "--fix", "phi"}, "omega", false,
                 {{"u_r", 0.1}}},
        PathCase{"RestartFromAStoredPoint", "[start]\nrestart = { run = \"paper-5.1-omega-up\", label = \"UZ5\" }",
                 {"--point", "paper-5.1-omega-up:UZ5", kResultsFlag}, "u_r", true,
                 {{"omega", 0.58}, {"x10", -0.43949016857105755}, {"d4", 2.3584619203844888}}},
        PathCase{"ZeroLengthSegment", "[start]\npreset = \"paper-5.1\"\nguess = { d3 = 0.0 }",
                 {"--preset", "paper-5.1", "--guess", "d3=0"}, "omega", false, {{"d3", 0.0}, {"d4", 3.0}}}),
    [](const ::testing::TestParamInfo<PathCase>& test) { return std::string(test.param.name); });

}  // namespace
}  // namespace stickslip
