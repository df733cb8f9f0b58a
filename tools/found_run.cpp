#include "found_run.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <tuple>

#include <fmt/format.h>

#include "number_text.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/model/pascal_2014/parameters.hpp"

namespace stickslip::cli {

namespace {

std::string Rounded(double x) { return ExactNumber(std::stod(fmt::format("{:.6g}", x))); }

// A TOML inline table of name = value pairs.
std::string InlineTable(const NamedValues& values) {
  std::string text;
  for (const auto& [name, value] : values) text += fmt::format("{}{} = {}", text.empty() ? "" : ", ", name, ExactNumber(value));
  return "{ " + text + " }";
}

// A TOML basic string: quotes, backslashes and control characters escaped (a run name may hold
// any of them).
std::string Quoted(std::string_view text) {
  std::string quoted = "\"";
  for (const char c : text) {
    const auto code = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      quoted += '\\';
      quoted += c;
    } else if (code < 0x20 || code == 0x7f) {
      quoted += fmt::format("\\u{:04X}", code);
    } else {
      quoted += c;
    }
  }
  return quoted + "\"";
}

std::string StringArray(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += fmt::format("{}{}", text.empty() ? "" : ", ", Quoted(name));
  return "[" + text + "]";
}

}  // namespace

std::string ExactNumber(double x) {
  std::string text = fmt::format("{}", x);
  if (text.find_first_of(".en") == std::string::npos) text += ".0";  // a TOML float, and plain to read
  return text;
}

OmegaRange ParseOmegaRange(const char* field, const std::string& text) {
  const std::string valid = fmt::format("LO,HI with {} <= LO < HI <= {} (omega)", kMinOmega, kMaxOmega);
  // Exactly one comma: with more, the message would name a part ('0.7,0.9' of '0.5,0.7,0.9').
  const auto comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos) {
    throw InvalidInput(field, "'" + text + "'", valid);
  }
  const OmegaRange range{ParseNumber(field, text.substr(0, comma), valid), ParseNumber(field, text.substr(comma + 1), valid)};
  if (!(kMinOmega <= range.low && range.low < range.high && range.high <= kMaxOmega)) {
    throw InvalidInput(field, "'" + text + "'", valid);
  }
  return range;
}

OmegaRange RangeAround(double omega) {
  return {std::stod(Rounded(std::max(kMinOmega, 0.9 * omega))), std::stod(Rounded(std::min(kMaxOmega, 1.1 * omega)))};
}

RunFile FoundRun(const StartInput& start, OmegaRange range, const std::string& output, bool trace, const BranchSteps& steps) {
  RunFile run = AsOneOffRun({});
  run.steps = steps;
  run.output = output;
  run = WithStart(std::move(run), start);
  run.parameter = "omega";
  run.range_min = range.low;
  run.range_max = range.high;
  if (trace) run.trace = TraceOptions{};
  return run;
}

std::string RunFileText(const RunFile& run) {
  std::string text = fmt::format("{}\noutput = {}\n", kFoundRunFileMarker, Quoted(run.output));
  text += fmt::format("[start]\nsignature = {}\nset = {}\nguess = {}\n", Quoted(run.signature), InlineTable(run.set),
                      InlineTable(run.guess));
  text += fmt::format("[unknowns]\nfree = {}\n", StringArray(run.free));
  if (!run.fix.empty()) text += fmt::format("fix = {}\n", StringArray(run.fix));
  text += fmt::format("tie_u_r = {}\n", run.tie_u_r);
  text += fmt::format("[continuation]                         # edit: the parameter{} and range\nparameter = {}\n",
                      run.trace ? "" : ", direction", Quoted(run.parameter));
  if (!run.trace) text += fmt::format("direction = \"{}\"\n", run.direction > 0 ? "up" : "down");
  text += fmt::format("range = [{}, {}]\n", ExactNumber(run.range_min), ExactNumber(run.range_max));
  const BranchSteps& steps = run.steps;
  const BranchSteps defaults;
  using Step = std::tuple<const char*, double, double>;  // the key, its value, its default
  for (const auto& [key, value, default_value] : {Step{"ds", steps.ds, defaults.ds}, Step{"ds_min", steps.ds_min, defaults.ds_min},
                                                  Step{"ds_max", steps.ds_max, defaults.ds_max}}) {
    if (value != default_value) text += fmt::format("{} = {}\n", key, ExactNumber(value));
  }
  if (steps.max_points != defaults.max_points) text += fmt::format("max_points = {}\n", steps.max_points);
  if (run.trace) text += "[trace]                                # both ways from the start, with the trace's defaults\n";
  return text;
}

}  // namespace stickslip::cli
