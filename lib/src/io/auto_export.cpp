#include "stickslip/io/auto_export.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "stickslip/io/run.hpp"
#include "stickslip/orbits/orbit.hpp"

namespace stickslip {

namespace {

// AUTO-07p's point type codes.
int AutoTypeCode(const std::string& type) {
  static const std::map<std::string, int> codes = {{"LP", 2}, {"BP", 1}, {"UZ", -4}, {"EP", 9}, {"PD", 7}, {"TR", 8}};
  const auto it = codes.find(type);
  return it == codes.end() ? -4 : it->second;
}

std::string JsonString(const std::string& json, const std::string& key) {
  const std::string pattern = "\"" + key + "\": \"";
  const auto at = json.find(pattern);
  if (at == std::string::npos) throw std::runtime_error("summary.json has no " + key);
  const auto begin = at + pattern.size();
  return json.substr(begin, json.find('"', begin) - begin);
}

}  // namespace

AutoFiles ExportAuto(const std::filesystem::path& run_directory, int samples) {
  const CsvTable branch = ParseCsv(ReadTextFile(run_directory / "branch.csv"));
  const std::string summary = ReadTextFile(run_directory / "summary.json");
  const std::string parameter = JsonString(summary, "parameter");
  std::string error;
  const std::optional<Signature> signature = Signature::Parse(JsonString(summary, "signature"), &error);
  if (!signature) throw std::runtime_error(error);
  auto column = [&](const std::string& name) {
    const auto it = std::find(branch.header.begin(), branch.header.end(), name);
    if (it == branch.header.end()) throw std::runtime_error(fmt::format("branch.csv has no column {}", name));
    return static_cast<std::size_t>(it - branch.header.begin());
  };
  std::vector<std::string> names = {parameter, "x10", "x20", "v10", "phi"};
  for (int i = 1; i <= signature->size(); ++i) names.push_back(fmt::format("d{}", i));
  std::vector<std::size_t> columns;
  for (const std::string& n : names) columns.push_back(column(n));
  const std::size_t label_column = column("label");
  const std::size_t stable_column = column("stable");
  if (branch.rows.empty()) throw std::runtime_error("branch.csv has no point");
  double low = std::stod(branch.rows.front()[columns[0]]);
  double high = low;
  for (const auto& row : branch.rows) {
    low = std::min(low, std::stod(row[columns[0]]));
    high = std::max(high, std::stod(row[columns[0]]));
  }

  AutoFiles files;
  // The first header line holds AUTO's RL0, RL1 (the parameter range) and A0, A1.
  files.b = fmt::format("   0 {:19.10E}{:19.10E}{:19.10E}{:19.10E}\n", low, high, 0.0, 0.0);
  files.b += "   0    PT  TY  LAB ";
  for (const std::string& n : names) files.b += fmt::format("{:<19}", n);
  files.b += "\n";
  int pt = 0;
  for (const auto& row : branch.rows) {
    ++pt;
    const std::string& label = row[label_column];
    int ty = 0, lab = 0;
    if (!label.empty()) {
      const auto digits = std::find_if(label.begin(), label.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
      ty = AutoTypeCode(std::string(label.begin(), digits));
      lab = std::stoi(std::string(digits, label.end()));
    }
    const bool stable = row[stable_column] == "1";
    files.b += fmt::format("{:4d}{:6d}{:4d}{:5d}", 1, stable ? -pt : pt, ty, lab);
    for (std::size_t c : columns) files.b += fmt::format("{:19.10E}", std::stod(row[c]));
    files.b += "\n";
    if (label.empty()) continue;

    // The solution file entry of a labelled point.
    Eigen::VectorXd variables(orbit_variables::Count(signature->size()));
    for (int i = 0; i < variables.size(); ++i) {
      variables(i) = std::stod(row[column(orbit_variables::Name(signature->size(), i))]);
    }
    const Orbit orbit = orbit_variables::Unpack(*signature, variables);
    const std::vector<State> states = orbit.Sample(samples);
    constexpr int kParameters = 36;  // AUTO's NPAR
    std::vector<double> par(kParameters, 0.0);
    for (int k = 0; k < kParameterCount; ++k) par[k] = orbit.parameters[kAllParameters[k]];
    par[10] = orbit.Period();
    const int rows = samples;
    const int lines = rows + (kParameters + 6) / 7;
    // IBR NTOT ITP LAB NFPR ISW NTPL NAR NROWPR NTST NCOL NPAR
    files.s += fmt::format("{:6d}{:6d}{:6d}{:6d}{:6d}{:6d}{:8d}{:6d}{:8d}{:5d}{:5d}{:5d}\n", 1, stable ? -pt : pt, ty, lab,
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
