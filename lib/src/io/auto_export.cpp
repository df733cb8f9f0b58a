#include "stickslip/io/auto_export.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <utility>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/orbits/orbit.hpp"

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

}  // namespace

AutoFiles ExportAuto(const std::filesystem::path& run_directory, int samples) {
  const StoredRun run = ReadRunFiles(run_directory);
  const int segments = run.branch.front().orbit.signature.size();
  // The reader checked that the parameter is a variable of the orbit.
  std::vector<std::string> names = {run.summary.parameter, "x10", "x20", "v10", "phi"};
  for (int i = 1; i <= segments; ++i) names.push_back(fmt::format("d{}", i));
  std::vector<int> columns;
  for (const std::string& name : names) columns.push_back(*orbit_variables::IndexOf(segments, name));
  auto parameter = [&](const StoredPoint& p) { return orbit_variables::Pack(p.orbit)(columns.front()); };
  double low = parameter(run.branch.front());
  double high = low;
  for (const StoredPoint& p : run.branch) {
    low = std::min(low, parameter(p));
    high = std::max(high, parameter(p));
  }

  AutoFiles files;
  // The first header line holds AUTO's RL0, RL1 (the parameter range) and A0, A1.
  files.b = fmt::format("   0 {:19.10E}{:19.10E}{:19.10E}{:19.10E}\n", low, high, 0.0, 0.0);
  files.b += "   0    PT  TY  LAB ";
  for (const std::string& n : names) files.b += fmt::format("{:<19}", n);
  files.b += "\n";
  int pt = 0;
  for (const StoredPoint& p : run.branch) {
    ++pt;
    const auto [ty, lab] = p.label.empty() ? std::pair(0, 0) : AutoLabel(p.label, run_directory / "branch.csv", pt);
    files.b += fmt::format("{:4d}{:6d}{:4d}{:5d}", 1, p.stable ? -pt : pt, ty, lab);
    const Eigen::VectorXd variables = orbit_variables::Pack(p.orbit);
    for (int c : columns) files.b += fmt::format("{:19.10E}", variables(c));
    files.b += "\n";
    if (p.label.empty()) continue;

    // The solution file entry of a labelled point.
    const Orbit& orbit = p.orbit;
    const std::vector<State> states = orbit.Sample(samples);
    constexpr int kParameters = 36;  // AUTO's NPAR
    std::vector<double> par(kParameters, 0.0);
    for (int k = 0; k < kParameterCount; ++k) par[k] = orbit.parameters[kAllParameters[k]];
    par[10] = orbit.Period();
    const int rows = samples;
    const int lines = rows + (kParameters + 6) / 7;
    // IBR NTOT ITP LAB NFPR ISW NTPL NAR NROWPR NTST NCOL NPAR
    files.s += fmt::format("{:6d}{:6d}{:6d}{:6d}{:6d}{:6d}{:8d}{:6d}{:8d}{:5d}{:5d}{:5d}\n", 1, p.stable ? -pt : pt, ty, lab,
                           1, 1, rows, 5, lines, rows - 1, 1, kParameters);
    for (int k = 0; k < rows; ++k) {
      const State& x = states[k];
      files.s += fmt::format("    {:19.10E}{:19.10E}{:19.10E}{:19.10E}{:19.10E}\n", static_cast<double>(k) / (rows - 1),
                             x(0), x(1), x(2), x(3));
    }
    for (int k = 0; k < kParameters; ++k) {
      files.s += fmt::format("{}{:19.10E}", k % 7 == 0 ? "    " : "", par[k]);
      if (k % 7 == 6 || k + 1 == kParameters) files.s += "\n";
    }
  }
  return files;
}

}  // namespace stickslip
