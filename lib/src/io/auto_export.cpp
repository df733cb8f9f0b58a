#include "stickslip/io/auto_export.hpp"

#include <algorithm>
#include <cctype>
#include <complex>
#include <map>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "stickslip/branches/orbit_monitor.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/io/command_options.hpp"
#include "stickslip/io/model_find.hpp"
#include "stickslip/io/model_restart.hpp"
#include "stickslip/orbits/any_orbit.hpp"
#include "stickslip/orbits/orbit.hpp"
#include "stickslip/orbits/verification.hpp"

namespace stickslip {

namespace {

// AUTO-07p's point type codes.
int AutoTypeCode(const std::string& type) {
  static const std::map<std::string, int> codes = {{"LP", 2}, {"BP", 1}, {"UZ", -4}, {"EP", 9}, {"PD", 7}, {"TR", 8}, {"SB", 1}};
  const auto it = codes.find(type);
  return it == codes.end() ? -4 : it->second;
}

// AUTO's TY and LAB of a label "LP2": the type code and the running number.
std::pair<int, int> AutoLabel(const std::string& label, const std::filesystem::path& file, int pt) {
  auto is_digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
  const auto digits = std::find_if(label.begin(), label.end(), is_digit);
  const std::string number(digits, label.end());
  if (number.empty() || number.size() > 9 || !std::all_of(number.begin(), number.end(), is_digit)) {
    throw InvalidInput::WithMessage("label", fmt::format("{}: point {}: label '{}' is invalid: valid a type and a number, "
                                                         "as LP2", file.string(), pt, label));
  }
  return {AutoTypeCode(std::string(label.begin(), digits)), std::stoi(number)};
}

// The b. file's columns after BR PT TY LAB, by name, with each point's value: the parameter, then
// the measures (so that AUTO's default axes, column 0 against column 1, draw max |x1| against the
// parameter: a frequency response), then the orbit's start and durations.
struct BranchColumns {
  std::vector<std::string> names;
  std::size_t measures = 0;  // names[1 .. measures] are the measures; the rest the orbit's variables

  std::vector<double> Values(const StoredPoint& p) const {
    std::vector<double> values = {Named(p.solution, names.front())};
    for (const auto& [name, value] : p.measures) values.push_back(value);
    for (std::size_t k = 1 + measures; k < names.size(); ++k) values.push_back(Named(p.solution, names[k]));
    return values;
  }
};

// The b. file's columns of any model's run: the start state (the solution's columns between phi and
// d1), phi and the durations after the measures (for the paper's model: x10, x20, v10, phi, d1..dn).
BranchColumns ColumnsOf(const StoredRun& run) {
  BranchColumns columns{.names = {run.summary.parameter}, .measures = run.branch.front().measures.size()};
  for (const auto& [name, value] : run.branch.front().measures) columns.names.push_back(name);
  for (const std::string& name : StartStateNames(run.branch.front().solution)) columns.names.push_back(name);
  columns.names.push_back("phi");
  const int segments = Signature::Parse(run.summary.signature).size();
  for (int i = 1; i <= segments; ++i) columns.names.push_back(fmt::format("d{}", i));
  return columns;
}

// The b. file's two header lines: AUTO's RL0, RL1 (the parameter's range) and A0, A1; the names.
std::string BranchHeader(const StoredRun& run, const BranchColumns& columns) {
  double low = columns.Values(run.branch.front()).front();
  double high = low;
  for (const StoredPoint& p : run.branch) {
    const double value = columns.Values(p).front();
    low = std::min(low, value);
    high = std::max(high, value);
  }
  std::string header = fmt::format("   0 {:>19.10E}{:>19.10E}{:>19.10E}{:>19.10E}\n", low, high, 0.0, 0.0);
  header += "   0    PT  TY  LAB ";
  for (const std::string& n : columns.names) header += fmt::format("{:<19}", n);
  return header + "\n";
}

// One period of a labelled point's orbit as the s. file holds it: the state at `samples` equally
// spaced times, and AUTO's parameters PAR(1..) (the model's, in its order) with PAR(11) the period.
struct SampledOrbit {
  std::vector<std::vector<double>> states;
  std::vector<double> parameters;
  double period = 0.0;
};

// The paper's orbit by its closed forms (Orbit::Sample).
SampledOrbit SampledOf(const Orbit& orbit, int samples) {
  SampledOrbit sampled;
  for (const State& x : orbit.Sample(samples)) sampled.states.emplace_back(x.data(), x.data() + x.size());
  for (int k = 0; k < kParameterCount; ++k) sampled.parameters.push_back(orbit.parameters[kAllParameters[k]]);
  sampled.period = orbit.Period();
  return sampled;
}

// A [model]'s orbit by its closed forms (SampledStoredOrbit: it must come back to its start).
SampledOrbit SampledOf(const ModelFileStart& file, const StoredRun& run, const StoredPoint& p, int samples) {
  const BasicOrbit<DynamicLinearOscillator> orbit = OrbitOf(file.model, file.parameters, run, p);
  SampledOrbit sampled;
  sampled.period = PeriodOf(file.model, orbit);
  const std::vector<DynamicLinearOscillator::State> states = SampledStoredOrbit(file, orbit, samples, run, p.label);
  for (const DynamicLinearOscillator::State& x : states) sampled.states.emplace_back(x.data(), x.data() + x.size());
  for (int k = 0; k < file.model.Description().ParameterCount(); ++k) {
    sampled.parameters.push_back(DynamicLinearOscillator::ParameterAt(orbit.parameters, k));
  }
  return sampled;
}

// The s. file's entry of a labelled point: one period (t scaled to [0, 1], then the state, seven
// numbers a line as AUTO writes them), then NPAR = 36 parameters.
std::string SolutionEntry(const StoredPoint& p, int ty, int lab, const SampledOrbit& orbit) {
  constexpr int kParameters = 36;  // AUTO's NPAR
  constexpr int kPerLine = 7;
  std::vector<double> par(kParameters, 0.0);
  std::copy(orbit.parameters.begin(), orbit.parameters.end(), par.begin());
  par[10] = orbit.period;
  const int samples = static_cast<int>(orbit.states.size());
  const int dimension = static_cast<int>(orbit.states.front().size());
  const int rows = (dimension + kPerLine) / kPerLine;  // t and the state
  const int lines = samples * rows + (kParameters + kPerLine - 1) / kPerLine;
  // IBR NTOT ITP LAB NFPR ISW NTPL NAR NROWPR NTST NCOL NPAR
  std::string s = fmt::format("{:6d}{:6d}{:6d}{:6d}{:6d}{:6d}{:8d}{:6d}{:8d}{:5d}{:5d}{:5d}\n", 1,
                              p.stable ? -p.pt : p.pt, ty, lab, 1, 1, samples, dimension + 1, lines, samples - 1, 1,
                              kParameters);
  auto write = [&s](const std::vector<double>& values) {
    for (std::size_t k = 0; k < values.size(); ++k) {
      s += fmt::format("{}{:>19.10E}", k % kPerLine == 0 ? "    " : "", values[k]);
      if (k % kPerLine == kPerLine - 1 || k + 1 == values.size()) s += "\n";
    }
  };
  for (int k = 0; k < samples; ++k) {
    std::vector<double> row = {static_cast<double>(k) / (samples - 1)};
    row.insert(row.end(), orbit.states[k].begin(), orbit.states[k].end());
    write(row);
  }
  write(par);
  return s;
}

// The d. file's block of one point: what stickslip keeps of its computation, in the layout of
// AUTO's diagnostics that parseD reads (BR and PT on the line after the first "BR" line, the LAB
// after a "BR PT TY LAB" line, a "Multiplier" line per Floquet multiplier). AUTO writes a line per
// Newton iteration; stickslip stores their count (IT) and the step that reached the point.
std::string DiagnosticsEntry(const StoredPoint& p, const std::string& parameter, double value, int lab) {
  std::string d = fmt::format("  BR    PT  IT  {:<19}{:<19}\n", parameter, "step_size");
  d += fmt::format("{:4d}{:6d}{:4d}  {:>19.10E}{:>19.10E}\n", 1, p.pt, p.newton_iterations, value, p.step_size);
  for (std::size_t k = 0; k < p.multipliers.size(); ++k) {
    const std::complex<double> mu = p.multipliers[k];
    d += fmt::format(" Multiplier {:3d} {:>19.10E}{:>19.10E}  Abs. Val. {:>19.10E}\n", k + 1, mu.real(), mu.imag(),
                     std::abs(mu));
  }
  d += fmt::format(" Stability: {}\n", p.stable ? "stable (every |multiplier| < 1)" : "unstable (a |multiplier| >= 1)");
  if (!p.label.empty()) {
    d += fmt::format("  BR    PT  TY  LAB  {}\n{:4d}{:6d}  {:<4}{:4d}  {:>19.10E}\n", parameter, 1, p.pt,
                     p.label.substr(0, p.label.find_first_of("0123456789")), lab, value);
  }
  return d;
}

// The divider parseD splits the d. file at, one block per point.
constexpr std::string_view kDiagnosticsDivider = "===============================================\n";

}  // namespace

AutoFiles ExportAuto(const std::filesystem::path& run_directory, int samples) {
  const StoredRun run = ReadRunFiles(run_directory);
  const BranchColumns columns = ColumnsOf(run);
  const std::optional<ModelFileStart> model = run.summary.model.empty() ? std::nullopt : std::optional(ModelOfStoredRun(run, run_directory));
  AutoFiles files;
  files.b = BranchHeader(run, columns);
  for (const StoredPoint& p : run.branch) {
    const auto [ty, lab] = p.label.empty() ? std::pair(0, 0) : AutoLabel(p.label, run_directory / "branch.csv", p.pt);
    const std::vector<double> values = columns.Values(p);
    files.b += fmt::format("{:4d}{:6d}{:4d}{:5d}", 1, p.stable ? -p.pt : p.pt, ty, lab);
    for (double v : values) files.b += fmt::format("{:>19.10E}", v);
    files.b += "\n";
    if (!files.d.empty()) files.d += kDiagnosticsDivider;
    files.d += DiagnosticsEntry(p, run.summary.parameter, values.front(), lab);
    if (p.label.empty()) continue;
    files.s += SolutionEntry(p, ty, lab, model ? SampledOf(*model, run, p, samples) : SampledOf(OrbitOf(run, p), samples));
  }
  return files;
}

}  // namespace stickslip
