#include "model_find.hpp"

#include <cmath>
#include <complex>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cli_common.hpp"
#include "progress_line.hpp"
#include "stickslip/analysis/model_orbit_finder.hpp"
#include "stickslip/io/model_orbit_json.hpp"
#include "stickslip/io/model_find.hpp"

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
  out += fmt::format("\nnewton     {}\nperiod     {:.12g}{}\nstart     ", r.solution->summary.BriefReport(),
                     PeriodOf(model, o), model.Autonomous() ? "" : fmt::format("  phi = {:.12g}", o.phi));
  for (int k = 0; k < model.StateSize(); ++k) out += fmt::format(" {}={:.10g}", d.initial_state[k], o.start(k));
  out += "\n";
  for (std::size_t i = 0; i < o.durations.size(); ++i) {
    out += fmt::format("  d{} = {:<22} {}\n", i + 1, o.durations[i], ToString(o.signature.segments()[i]));
  }
  const Margin smallest = SmallestMargin(r.margins);
  out += fmt::format("smallest margin {} = {:.6g}: {}\n", smallest.Name(), smallest.value,
                     smallest.value > 0 ? "admissible" : "NOT a motion of the system");
  out += fmt::format("floquet multipliers{}:", r.stability->one_sided ? " (one-sided)" : "");
  for (const std::complex<double>& mu : r.stability->multipliers) out += fmt::format(" {:.6g}", std::abs(mu));
  out += fmt::format(" (moduli)\nstability  {}\nmeasures over one period\n", r.stability->stable ? "stable" : "unstable");
  for (std::size_t j = 0; j < d.coordinates.size(); ++j) {
    const CoordinateRange& c = r.measures->coordinates[j];
    out += fmt::format("  {:<8} amplitude {:.10g}  peak-to-peak {:.10g}\n", d.coordinates[j], c.Amplitude(), c.PeakToPeak());
  }
  out += fmt::format("  stick fraction {:.6g}, stops {}, sticks {}\n  friction work {:.10g} J per period, equivalent viscous "
                     "damping {:.6g} N s/m\n",
                     r.measures->stick_fraction, r.measures->stops, r.measures->sticks, r.measures->friction_work,
                     r.measures->equivalent_damping);
  out += fmt::format("verification {}\n{}", r.verification->Passed() ? "passed" : "FAILED", r.verification->Report());
  return out;
}

}  // namespace

int RunModelFind(const ModelFindArgs& args) {
  NamedValues set;
  for (const std::string& text : args.set) {
    const auto equals = text.find('=');
    if (equals == std::string::npos) throw InvalidInput("set", fmt::format("'{}'", text), "NAME=VALUE");
    const std::string name = text.substr(0, equals);
    set.emplace_back(name, ParseNumber(name, text.substr(equals + 1), "a finite number"));
  }
  const int transients = ParseCount("transients", args.transients, kMinModelTransients, kMaxModelTransients);
  ProgressLine line("find: transient");
  const ModelFindRun run = FindModelFileOrbit(args.file, set, transients, line.Callback());
  line.Clear();
  if (args.json) {
    fmt::print("{}\n", ModelFindJson(run.model, run.found));
  } else if (run.found.solution && run.found.solution->summary.Converged()) {
    fmt::print("{}", Text(run.model, run.found));
  }
  const int code = FindExitCode(run.found.status);
  if (code != kExitOk) fmt::print(stderr, "error: {}: {}\n", args.file, run.found.message);
  return code;
}

}  // namespace stickslip::cli
