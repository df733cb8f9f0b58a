// stickslip plot: any stored result (a branch, a curve in two parameters, a trace, a sweep, a
// brute-force map, an orbit-type map), or several overlaid, as PNG, PDF or SVG, drawn by
// stickslip_plot.py (beside the program, or in <prefix>/share/stickslip/ when installed) through
// /usr/bin/python3 and Debian's matplotlib. This file checks the inputs and the output file; the
// script checks the drawing options.
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "cli_common.hpp"
#include "commands.hpp"
#include "stickslip/io/atomic_file.hpp"
#include "stickslip/io/map_file.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/io/run_file.hpp"
#include "stickslip/io/trace_files.hpp"

extern char** environ;

namespace stickslip::cli {

namespace {

namespace fs = std::filesystem;

struct PlotArgs {
  std::vector<std::string> inputs;
  std::string results = "results";
  std::string output = "";  // from the first input's name when not given (DefaultOutput)
  bool output_given = false;  // --output "" is refused, not taken as the default
  // The drawing options, forwarded to stickslip_plot.py as given (it checks them: one line naming
  // the option, its value and the valid range, exit 2, nothing written).
  std::vector<std::pair<std::string, std::string>> drawing;
  bool no_natural_frequencies = false;
  bool force = false;  // replace an --output that stickslip plot did not write
};

// The drawing script `name`, found from the program's own place (no path is compiled in): beside
// it, where the build tree copies the scripts (build/release/tools/), else in <prefix>/share/stickslip/
// for the program in <prefix>/bin/, where `cmake --install` puts them.
fs::path DrawingScript(const char* name) {
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  if (error) return {};  // reported as a missing script (never a file of that name in the current directory)
  const fs::path beside = program.parent_path() / name;
  if (fs::is_regular_file(beside)) return beside;
  return program.parent_path().parent_path() / "share" / "stickslip" / name;
}

// The scripts' exit code when matplotlib cannot be imported.
constexpr int kScriptNeedsMatplotlib = 3;

// How a program run ended: its exit status, or -1 with why where it could not start or was killed.
struct ProgramEnd {
  int status = -1;
  std::string why;
};

// Runs `argv` without a shell.
ProgramEnd RunProgram(const std::vector<std::string>& argv) {
  std::vector<char*> pointers;
  for (const std::string& a : argv) pointers.push_back(const_cast<char*>(a.c_str()));
  pointers.push_back(nullptr);
  pid_t pid = 0;
  const int started = posix_spawn(&pid, pointers[0], nullptr, nullptr, pointers.data(), environ);
  if (started != 0) return {-1, std::strerror(started)};
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return {-1, std::strerror(errno)};
  }
  if (WIFEXITED(status)) return {WEXITSTATUS(status), ""};
  return {-1, fmt::format("it ended by signal {}", WIFSIGNALED(status) ? WTERMSIG(status) : 0)};
}

// What plot draws, for the messages of an input it cannot.
std::string PlotInputs() {
  return fmt::format(
      "a run or trace name under --results, or the path of a result: {}, a trace's (trace.json, branch-<k>/), an "
      "orbit-type map's (regions.json), a sweep's or map-sweep's CSV",
      kRunDirectory);
}

// Where an input is: a run or trace named under --results (as before), else a path to a result
// directory or file (a sweep's or map-sweep's CSV, an orbit-type map's directory).
fs::path ResolveInput(const std::string& input, const std::string& results) {
  if (IsRunName(input) && fs::exists(fs::path(results) / input)) return fs::path(results) / input;
  std::error_code error;
  if (!input.empty() && input.find('\n') == std::string::npos && fs::exists(fs::path(input), error)) return input;
  if (IsRunName(input)) return fs::path(results) / input;  // reported missing by the readers below
  throw InvalidInput("run", "'" + input + "'", PlotInputs());
}

// <run>-bifurcation.png, <trace>-frequency-response.png, <map>-map.png, <file>.png (a CSV's stem).
std::string DefaultOutput(const fs::path& input) {
  const std::string name = input.filename().empty() ? input.parent_path().filename().string() : input.filename().string();
  if (fs::is_regular_file(input)) return input.stem().string() + ".png";
  if (IsTraceDirectory(input)) return name + "-frequency-response.png";
  if (fs::is_regular_file(input / "regions.json")) return name + "-map.png";
  if (fs::is_regular_file(input / "atlas.json")) return name + "-atlas.png";
  return name + "-bifurcation.png";
}

int RunPlot(const PlotArgs& args) {
  std::vector<fs::path> inputs;
  for (const std::string& input : args.inputs) {
    fs::path path = ResolveInput(input, args.results);
    // One of a run's or trace's own files given by its path (results/run/branch.csv): the script
    // draws its directory, so its directory is what is read and checked, column by column, here.
    if (const std::string file = path.filename().string();
        (file == "branch.csv" || file == "special-points.csv" || file == "summary.json" || file == "trace.csv" ||
         file == "trace.json" || file == "atlas.json") &&
        fs::is_regular_file(path)) {
      path = path.has_parent_path() ? path.parent_path() : fs::path(".");
    }
    // A brute-force map's CSV is read by the one reader of map-sweep --merge and map --brute-force,
    // which checks every column (the script's own checks are by kind, row by row).
    if (fs::is_regular_file(path)) {
      std::ifstream in(path, std::ios::binary);
      std::string first;
      std::getline(in, first);
      if (!first.empty() && first.back() == '\r') first.pop_back();
      if (in && IsBruteForceMapCsvHeader(first)) {
        in.seekg(0);
        std::ostringstream text;
        text << in.rdbuf();
        CheckBruteForceMapCsv(text.str(), path.string());
      }
    }
    // A missing or damaged run or trace is bad input, before any work (sweeps, orbit-type maps and
    // atlases: the script).
    if (!fs::is_regular_file(path) && !fs::is_regular_file(path / "regions.json") && !fs::is_regular_file(path / "atlas.json")) {
      if (IsTraceDirectory(path)) {
        ReadTraceFiles(path);
      } else {
        CheckHoldsRun(path, "run", PlotInputs());
        ReadRunFiles(path);
      }
    }
    inputs.push_back(path);
  }
  const fs::path output = args.output_given ? fs::path(args.output) : fs::path(DefaultOutput(inputs.front()));
  CheckOutputFile(output, "output");
  const std::string extension = output.extension().string();
  if (extension != ".png" && extension != ".pdf" && extension != ".svg") {
    throw InvalidInput("output", "'" + output.string() + "'", "a file name ending in .png, .pdf or .svg");
  }
  // STICKSLIP_PYTHON: another interpreter (the tests use it to see a missing one reported).
  const char* python = std::getenv("STICKSLIP_PYTHON");
  const std::string interpreter = python && *python ? python : "/usr/bin/python3";
  const fs::path script = DrawingScript("stickslip_plot.py");
  // A program copied away from its scripts: python3 would say "can't open file" and exit 2, which
  // reads as bad input. It is an installation's failure: one line, exit 1, nothing written.
  if (std::error_code missing; script.empty() || !fs::is_regular_file(script, missing)) {
    fmt::print(stderr,
               "error: plot needs its drawing script stickslip_plot.py{}, found beside the program (the build tree) "
               "or in ../share/stickslip/ of an installed one (cmake --install); nothing was written\n",
               script.empty() ? std::string() : fmt::format(" at '{}', which is not there", script.string()));
    return kExitFailure;
  }
  std::vector<std::string> argv = {interpreter, script.string(), "--output", output.string()};
  for (const auto& [option, value] : args.drawing) {
    argv.push_back(option);
    argv.push_back(value);
  }
  if (args.no_natural_frequencies) argv.push_back("--no-natural-frequencies");
  if (args.force) argv.push_back("--force");  // the script checks the output's marker (check_replaceable)
  argv.push_back("--");  // the inputs, whatever their names begin with
  for (const fs::path& input : inputs) argv.push_back(input.string());
  const auto [status, why] = RunProgram(argv);
  if (status == -1 || status == kScriptNeedsMatplotlib) {
    fmt::print(stderr, "error: plot needs {} with matplotlib (Debian: apt-get install python3 python3-matplotlib): {}\n",
               interpreter, status == -1 ? why : "matplotlib cannot be imported");
    return kExitFailure;
  }
  if (status == kExitBadInput) return kExitBadInput;  // the script printed the one line
  if (status != 0) {
    fmt::print(stderr, "error: {} {} failed (exit {}); nothing was written\n", interpreter, script.string(), status);
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

namespace {

// How --help shows each drawing option's value.
std::string TypeName(const std::string& option) {
  if (option == "--x" || option == "--y") return "COLUMN";
  if (option == "--xscale" || option == "--yscale") return "linear|log";
  if (option == "--xlim" || option == "--ylim") return "LOW,HIGH";
  if (option == "--size") return "W,H";
  if (option == "--dpi") return "DPI";
  if (option == "--legend") return "right|inside|none";
  return "TEXT";
}

}  // namespace

Command AddPlotCommand(CLI::App& app) {
  auto args = std::make_shared<PlotArgs>();
  CLI::App* cmd = app.add_subcommand(
      "plot",
      "Draw stored results as a figure for a paper: a branch (a run), a curve in two parameters, a trace, a sweep "
      "(stickslip sweep's CSV), a brute-force map (map-sweep's CSV) or an orbit-type map (stickslip map's "
      "directory); several inputs are overlaid on one set of axes (branches, curves, traces and sweeps over the same "
      "x; an orbit-type map and a brute-force map with curves in their plane). Stable solid, unstable dashed, no "
      "motion thin grey, each orbit type in its own colour, special points and switches marked and labelled without "
      "overprinting, the branches a trace followed at bifurcations drawn, the natural frequencies omega1, omega2 "
      "(eq. 56) marked where an axis is omega. PNG, PDF or SVG by the --output extension. Runs /usr/bin/python3 "
      "with matplotlib (python3-matplotlib); exit 1 if it is missing.");
  cmd->add_option("inputs", args->inputs,
                  "runs or traces under --results (e.g. paper-5.1-omega-up, paper-4.1-omega-trace), or paths of "
                  "results (results/sweeps/paper-5.1-omega.csv, results/maps/paper-6-omega-u_r)")
      ->type_name("RESULT")
      ->required();
  cmd->add_option("--results", args->results, "where named runs and traces are stored")
      ->type_name("DIR")
      ->capture_default_str();
  cmd->add_option("--output", args->output,
                  "the figure, written whole or not at all; its extension gives the format: .png, .pdf or .svg "
                  "(default from the first input: <run>-bifurcation.png, <trace>-frequency-response.png, "
                  "<map>-map.png, <csv name>.png)")
      ->type_name("FILE")
      ->each([args](const std::string&) { args->output_given = true; });
  const std::pair<const char*, const char*> drawing[] = {
      {"--x", "the x quantity: any numeric column (default the continued or swept parameter; a map: its first)"},
      {"--y", "the y quantity: any numeric column: amplitude:x1, amplitude:x2, peak-to-peak:x2, stick-fraction, "
              "x20, d1, a margin, ... (default amplitude:x2, max |x2| over a period; curves in two parameters "
              "alone: the second parameter; a map: its second)"},
      {"--xscale", "linear or log (default linear; never switched automatically)"},
      {"--yscale", "linear or log (default linear; never switched automatically)"},
      {"--xlim", "LOW,HIGH: the x axis's range (default the data's)"},
      {"--ylim", "LOW,HIGH: the y axis's range (default the data's)"},
      {"--size", "WIDTH,HEIGHT in inches, each 1 to 40 (default 9,5; maps wider)"},
      {"--dpi", "dots per inch of a PNG, 10 to 1200 (default 150), at most 20000 pixels a side and 60 million in all"},
      {"--title", "the title (default: what is drawn and how each branch ended, in words; \"\" for none)"},
      {"--legend", "right (beside the axes, the default), inside or none"}};
  for (const auto& [name, help] : drawing) {
    const std::string option = name;
    cmd->add_option_function<std::string>(
           option, [args, option](const std::string& value) { args->drawing.emplace_back(option, value); }, help)
        ->type_name(TypeName(option));
  }
  cmd->add_flag("--no-natural-frequencies", args->no_natural_frequencies,
                "do not mark omega1 and omega2 (marked by default where an axis is omega)");
  cmd->add_flag("--force", args->force,
                "replace --output even if stickslip plot did not write it (a figure of the user's, a thesis.pdf); "
                "without it such a file is kept and plot exits 2");
  return {cmd, [args] { return RunPlot(*args); }};
}

}  // namespace stickslip::cli
