// stickslip plot: the bifurcation diagram of one stored run, or the frequency response of one stored
// trace, as a PNG, drawn by bifurcation_diagram.py or trace_figure.py (beside the program, or in
// <prefix>/share/stickslip/ when installed) through /usr/bin/python3 and Debian's matplotlib.
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "cli_common.hpp"
#include "commands.hpp"
#include "stickslip/io/atomic_file.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/io/run_file.hpp"
#include "stickslip/io/trace_files.hpp"

extern char** environ;

namespace stickslip::cli {

namespace {

namespace fs = std::filesystem;

struct PlotArgs {
  std::string run;
  std::string results = "results";
  std::string output = "";  // <run>-bifurcation.png (a trace: <run>-frequency-response.png) when not given
  bool output_given = false;  // --output "" is refused, not taken as the default
};

// The drawing script `name`, found from the program's own place (no path is compiled in): beside
// it, where the build tree copies the scripts (build/release/tools/), else in <prefix>/share/stickslip/
// for the program in <prefix>/bin/, where `cmake --install` puts them.
fs::path DrawingScript(const char* name) {
  std::error_code error;
  const fs::path program = fs::read_symlink("/proc/self/exe", error);
  if (error) return name;  // reported as a script that cannot be run
  const fs::path beside = program.parent_path() / name;
  if (fs::is_regular_file(beside)) return beside;
  return program.parent_path().parent_path() / "share" / "stickslip" / name;
}

// The scripts' exit code when matplotlib cannot be imported.
constexpr int kScriptNeedsMatplotlib = 3;

// Runs `argv` without a shell and returns its exit status, or -1 with *why if it could not start.
int RunProgram(const std::vector<std::string>& argv, std::string* why) {
  std::vector<char*> pointers;
  for (const std::string& a : argv) pointers.push_back(const_cast<char*>(a.c_str()));
  pointers.push_back(nullptr);
  pid_t pid = 0;
  const int started = posix_spawn(&pid, pointers[0], nullptr, nullptr, pointers.data(), environ);
  if (started != 0) {
    *why = std::strerror(started);
    return -1;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      *why = std::strerror(errno);
      return -1;
    }
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  *why = fmt::format("it ended by signal {}", WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  return -1;
}

int RunPlot(const PlotArgs& args) {
  if (!IsRunName(args.run)) throw InvalidInput("run", "'" + args.run + "'", std::string(kRunNameRule));
  const fs::path directory = fs::path(args.results) / args.run;
  // A missing or damaged run or trace is bad input, before any work.
  const bool trace = IsTraceDirectory(directory);
  if (trace) {
    ReadTraceFiles(directory);
  } else {
    ReadRunFiles(directory);
  }
  const fs::path output = args.output_given ? fs::path(args.output)
                                            : fs::path(args.run + (trace ? "-frequency-response.png" : "-bifurcation.png"));
  CheckOutputFile(output, "output");
  if (output.extension() != ".png") {
    throw InvalidInput("output", "'" + output.string() + "'", "a file name ending in .png");
  }
  // STICKSLIP_PYTHON: another interpreter (the tests use it to see a missing one reported).
  const char* python = std::getenv("STICKSLIP_PYTHON");
  const std::string interpreter = python && *python ? python : "/usr/bin/python3";
  const fs::path script = DrawingScript(trace ? "trace_figure.py" : "bifurcation_diagram.py");
  std::string why;
  const int status = RunProgram({interpreter, script.string(), directory.string(), output.string()}, &why);
  if (status == -1 || status == kScriptNeedsMatplotlib) {
    fmt::print(stderr, "error: plot needs {} with matplotlib (Debian: apt-get install python3 python3-matplotlib): {}\n",
               interpreter, status == -1 ? why : "matplotlib cannot be imported");
    return kExitFailure;
  }
  if (status != 0) {
    fmt::print(stderr, "error: {} {} failed (exit {}); nothing was written\n", interpreter, script.string(), status);
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace

Command AddPlotCommand(CLI::App& app) {
  auto args = std::make_shared<PlotArgs>();
  CLI::App* cmd = app.add_subcommand(
      "plot",
      "Draw the bifurcation diagram of a stored run as a PNG (800 x 600): x20 and the segment durations over the "
      "continued parameter, stable solid, unstable dashed, stretches that are no motion (a margin < 0) grey, special "
      "points marked and labelled without overprinting. Of a stored trace (stickslip trace), its frequency response "
      "(1150 x 600): max |x2| over the period against the parameter on every branch, each orbit type in its own "
      "colour, switches and special points marked and labelled. Runs /usr/bin/python3 with matplotlib "
      "(python3-matplotlib); exit 1 if it is missing.");
  cmd->add_option("run", args->run, "the run or trace: results/<run>/ (e.g. paper-5.1-omega-up, paper-4.1-omega-trace)")
      ->type_name("RUN")
      ->required();
  cmd->add_option("--results", args->results, "where the run is stored")->type_name("DIR")->capture_default_str();
  cmd->add_option("--output", args->output,
                  "the PNG file, written whole or not at all (default <run>-bifurcation.png, for a trace "
                  "<run>-frequency-response.png)")
      ->type_name("FILE.png")
      ->each([args](const std::string&) { args->output_given = true; });
  return {cmd, [args] { return RunPlot(*args); }};
}

}  // namespace stickslip::cli
