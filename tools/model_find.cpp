#include "model_find.hpp"

#include <chrono>
#include <cmath>
#include <complex>
#include <filesystem>
#include <numbers>
#include <string>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli_common.hpp"
#include "progress_line.hpp"
#include "stickslip/analysis/model_orbit_finder.hpp"
#include "stickslip/io/model_orbit_json.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/model_find.hpp"
#include "stickslip/io/model_trace.hpp"
#include "stickslip/io/trace_files.hpp"
#include "trace_run.hpp"

namespace stickslip::cli {

namespace {

using Model = DynamicLinearOscillator;
using Found = ModelFindResult<Model>;

std::string Text(const Model& model, const Found& r) {
  const ModelDescription& d = model.Description();
  const BasicOrbit<Model>& o = r.solution->orbit;
  std::string out = fmt::format("signature  {}\nparameters", o.signature.ToString());
  for (int k = model.Autonomous() ? 1 : 0; k < d.ParameterCount(); ++k) {  // omega plays no part without forcing
    out += fmt::format(" {}={}", d.parameters[k].name, Model::ParameterAt(o.parameters, k));
  }
  out += fmt::format("\nnewton     {}\nperiod     {:.12g} {}{}\nstart     ", r.solution->summary.BriefReport(),
                     PeriodOf(model, o), d.units.time, model.Autonomous() ? "" : fmt::format("  phi = {:.12g}", o.phi));
  for (int k = 0; k < model.StateSize(); ++k) out += fmt::format(" {}={:.10g}", d.initial_state[k], o.start(k));
  out += "\n";
  for (std::size_t i = 0; i < o.durations.size(); ++i) {
    out += fmt::format("  d{} = {:<24} {}\n", i + 1, fmt::format("{} {}", o.durations[i], d.units.time),
                       ToString(o.signature.segments()[i]));
  }
  const Margin smallest = SmallestMargin(r.margins);
  out += fmt::format("smallest margin {} = {:.6g}: {}\n", smallest.Name(), smallest.value,
                     smallest.value > 0 ? "admissible" : "NOT a motion of the system");
  out += fmt::format("floquet multipliers{}:", r.stability->one_sided ? " (one-sided)" : "");
  for (const std::complex<double>& mu : r.stability->multipliers) out += fmt::format(" {:.6g}", std::abs(mu));
  out += fmt::format(" (moduli)\nstability  {}\nmeasures over one period (lengths in {})\n",
                     r.stability->stable ? "stable" : "unstable", d.units.length);
  for (std::size_t j = 0; j < d.coordinates.size(); ++j) {
    const CoordinateRange& c = r.measures->coordinates[j];
    out += fmt::format("  {:<8} amplitude {:.10g}  peak-to-peak {:.10g}\n", d.coordinates[j], c.Amplitude(), c.PeakToPeak());
  }
  out += fmt::format("  stick fraction {:.6g}, stops {}, sticks {}\n", r.measures->stick_fraction, r.measures->stops,
                     r.measures->sticks);
  out += std::isnan(r.measures->friction_work)
             ? "  friction work and equivalent viscous damping: not computed (nan: the closed form overflows)\n"
             : fmt::format("  friction work {:.10g} {} per period, equivalent viscous damping {:.6g} {}\n",
                           r.measures->friction_work, d.units.Energy(), r.measures->equivalent_damping,
                           d.units.ViscousDamping());
  out += fmt::format("verification {}\n{}", r.verification->Passed() ? "passed" : "FAILED", r.verification->Report());
  return out;
}

// "LO,HI": two finite numbers, LO < HI (the trace's range; TraceModel checks it holds the start).
std::pair<double, double> ParseRange(const char* field, const std::string& text) {
  const auto comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos) {
    throw InvalidInput(field, "'" + text + "'", "LO,HI: two numbers");
  }
  return {ParseNumber(field, text.substr(0, comma), "LO,HI: two numbers"),
          ParseNumber(field, text.substr(comma + 1), "LO,HI: two numbers")};
}

// The chain of branches both ways: each branch's type, its way, how it began, its points and how it
// ended; then each direction's end.
std::string TraceText(const BasicTraceResult<DynamicLinearOscillator>& trace) {
  std::string out = fmt::format("trace in {}\n", trace.parameter);
  for (const BasicTraceDirection<DynamicLinearOscillator>* chain : {&trace.down, &trace.up}) {
    for (const BasicTraceLink<DynamicLinearOscillator>& link : chain->links) {
      const Branch& b = link.branch.branch;
      out += fmt::format("  '{}' {} from {}{}: {} points, {} = {:.10g} to {:.10g}, {}\n", link.signature,
                         link.direction > 0 ? "up" : "down", ToString(link.start),
                         link.margin.empty() ? "" : " at " + link.margin, b.points.size(), trace.parameter,
                         b.points.front().lambda, b.points.back().lambda, ToString(link.end));
    }
    out += fmt::format("  {}: {}: {}\n", chain->direction > 0 ? "up" : "down", ToString(chain->end), chain->message);
  }
  out += "(printed: --output NAME writes it as stickslip trace does; --json gives every point)\n";
  return out;
}

// find, and with --trace the trace, of the model; bad input (the options, the run file) before the work.
ModelTraceRun FindAndTrace(const ModelFindArgs& args, ProgressLine& line) {
  const NamedValues set = ModelSetOf(args.set);
  const int transients = ParseCount("transients", args.transients, kMinModelTransients, kMaxModelTransients);
  const int max_multiple = ParseCount("max-multiple", args.max_multiple, 1, ModelFindOptions::kMaxMultiple);
  if (!args.trace_parameter.empty() && args.trace.empty()) {
    throw InvalidInput("trace-parameter", "'" + args.trace_parameter + "'", "with --trace");
  }
  if (!args.output.empty() && args.trace.empty()) throw InvalidInput("output", "'" + args.output + "'", "with --trace");
  if (!args.output.empty()) {
    if (!IsRunName(args.output)) throw InvalidInput("output", "'" + args.output + "'", std::string(kRunNameRule));
    CheckTraceOutputDirectory(args.results, args.output);
  }
  if (args.trace.empty()) {
    return {FindModelOrbitOf(ReadModelFileStart(args.file, set), transients, max_multiple, line.Callback()), {}};
  }
  const auto [low, high] = ParseRange("trace", args.trace);
  const ModelFileStart start = ReadModelFileStart(args.file, set);
  const std::string parameter = !args.trace_parameter.empty() ? args.trace_parameter
                                : start.model.Autonomous()    ? "v_b"
                                                              : "omega";
  TraceOptions options;
  options.progress = line.Callback();
  try {
    return TraceModel(start, transients, max_multiple, parameter, low, high, options, args.steps);
  } catch (const InvalidInput& e) {  // the library's names, as the options name them
    if (e.field() == "range") throw e.Renamed("trace");
    if (e.field() == "parameter") throw e.Renamed("trace-parameter");
    throw;
  }
}

}  // namespace

NamedValues ModelSetOf(const std::vector<std::string>& texts) {
  NamedValues set;
  for (const std::string& text : texts) {
    const auto equals = text.find('=');
    if (equals == std::string::npos) throw InvalidInput("set", fmt::format("'{}'", text), "NAME=VALUE");
    const std::string name = text.substr(0, equals);
    set.emplace_back(name, ParseNumber(name, text.substr(equals + 1), "a finite number"));
  }
  return set;
}

void RefuseWithModel(const CLI::App& cmd, std::initializer_list<const char*> options, std::string_view instead) {
  for (const char* option : options) {
    if (cmd.count(option) == 0) continue;
    throw InvalidInput::WithMessage(option + 2, fmt::format("{} is not taken with --model: {}", option, instead));
  }
}

void RefuseOutputOverModel(const std::string& output, const std::string& model, const char* field) {
  std::error_code error;  // none when the output does not exist yet
  if (!std::filesystem::equivalent(output, model, error)) return;
  throw InvalidInput::WithMessage(field, fmt::format("{} = '{}' is invalid: it is the run file --model reads: valid "
                                                     "another file",
                                                     field, output));
}

int RunModelSolve(const std::filesystem::path& results, const std::string& point, const OrbitSolverOptions& solver,
                  bool json) {
  const ModelFindRun solved = SolveAtModelLabel(results, point, solver);
  const Found& r = solved.found;
  if (!r.solution->summary.Converged()) {
    fmt::print(stderr, "error: {}: Newton did not converge from the stored orbit: {}\n", point,
               r.solution->summary.BriefReport());
    return kExitNoConvergence;
  }
  fmt::print("{}{}", json ? ModelFindJson(solved.model, r) : Text(solved.model, r), json ? "\n" : "");
  if (r.status != FindOrbitStatus::kFound) fmt::print(stderr, "error: {}: {}\n", point, r.message);
  return FindExitCode(r.status);
}

int RunModelFind(const ModelFindArgs& args) {
  ProgressLine line("find: transient");
  const auto started = std::chrono::steady_clock::now();
  const ModelTraceRun run = FindAndTrace(args, line);
  line.Clear();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const ModelFindResult<DynamicLinearOscillator>& found = run.find.found;
  const bool written = run.trace && !args.output.empty() && run.trace->HasBranches();
  if (args.json) {
    fmt::print("{}\n", run.trace ? ModelTraceJson(run) : ModelFindJson(run.find.model, found));
  } else if (found.solution && found.solution->summary.Converged()) {
    fmt::print("{}", Text(run.find.model, found));
    if (run.trace && !written) fmt::print("{}", TraceText(*run.trace));
    if (run.trace && !written && !args.output.empty()) fmt::print("{}: no branch started: nothing written\n", args.output);
  }
  if (const int code = FindExitCode(found.status); code != kExitOk) {
    fmt::print(stderr, "error: {}: {}{}\n", args.file, found.message,
               LongerMayFind(found) ? fmt::format(" (--transients {} periods now: more simulates longer)", args.transients) : "");
    return code;
  }
  if (written) {
    const StoredTrace stored = StoredModelTrace(run, args.file, ModelSetOf(args.set), args.output);
    if (!args.json) return WriteAndReportTrace(stored, seconds, args.results);
    WriteTraceFiles(args.results, stored);
  }
  if (!run.trace || !run.trace->Failed()) return kExitOk;
  for (const BasicTraceDirection<DynamicLinearOscillator>* chain : {&run.trace->down, &run.trace->up}) {
    if (chain->end != TraceEnd::kContinuationFailed) continue;
    fmt::print(stderr, "error: {}: the {} chain failed: {}\n", args.file, chain->direction > 0 ? "up" : "down",
               chain->message);
  }
  return kExitNoConvergence;
}

}  // namespace stickslip::cli
