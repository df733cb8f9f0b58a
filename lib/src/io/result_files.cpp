#include "stickslip/io/result_files.hpp"

#include <algorithm>
#include <array>
#include <filesystem>
#include <cctype>
#include <cmath>
#include <functional>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "csv_table.hpp"
#include "result_directory.hpp"
#include "stickslip/branches/orbit_monitor.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/atomic_file.hpp"
#include "stickslip/io/trace_files.hpp"
#include "stickslip/orbits/orbit_measures.hpp"

namespace stickslip {

namespace {

namespace fs = std::filesystem;
namespace ov = orbit_variables;
using detail::CsvTable;
using detail::KeyError;
using detail::ReadTextFile;
// Keys stay in the order they are written in.
using Json = nlohmann::ordered_json;

constexpr const char* kBranchFile = "branch.csv";
constexpr const char* kSpecialPointsFile = "special-points.csv";
constexpr const char* kSummaryFile = "summary.json";

// The columns of a point after its margins and multipliers: the stability, admissible, the
// measures (orbit_columns::MeasureNames), the step; and those a special point adds.
using orbit_columns::kMarginPrefix;
constexpr std::array<const char*, 5> kStabilityColumns = {orbit_columns::kStable, orbit_columns::kFoldTest,
                                                          orbit_columns::kFlipTest, orbit_columns::kTorusTest,
                                                          orbit_columns::kSymmetryTest};
constexpr std::array<const char*, 2> kStepColumns = {"newton_iterations", "step_size"};
constexpr std::array<const char*, 3> kSpecialColumns = {"type", "test_function", "located"};

std::string MultiplierColumn(std::size_t k, const char* part) {
  return orbit_columns::Multiplier(static_cast<int>(k), part);
}

// summary.json's text keys, before and after "points" and "special_points".
struct TextKey {
  const char* key;
  std::string StoredSummary::*field;
};
constexpr std::array<TextKey, 6> kLeadingKeys = {{{"run_file", &StoredSummary::run_file},
                                                  {"stickslip_version", &StoredSummary::stickslip_version},
                                                  {"output", &StoredSummary::output},
                                                  {"signature", &StoredSummary::signature},
                                                  {"parameter", &StoredSummary::parameter},
                                                  {"shooting", &StoredSummary::shooting}}};
constexpr std::array<TextKey, 2> kTrailingKeys = {{{"termination", &StoredSummary::termination},
                                                   {"message", &StoredSummary::message}}};
constexpr const char* kPointsKey = "points";
// Only in the summary of a model other than the paper's: the files of every run before models
// existed (and of every run of the paper's model since) read as they were written.
constexpr const char* kModelKey = "model";
constexpr const char* kSpecialPointsKey = "special_points";
// A [model]'s units (absent from the runs made before units could be declared: SI).
constexpr const char* kUnitsKey = "units";

std::map<std::string, std::size_t> CountsByType(const std::vector<StoredSpecialPoint>& special_points) {
  std::map<std::string, std::size_t> counts;
  for (const StoredSpecialPoint& s : special_points) ++counts[s.type];
  return counts;
}

// ---- Writing

std::string Number(double v) { return fmt::format("{}", v); }
const char* Flag(bool b) { return b ? "1" : "0"; }

std::string Row(const StoredPoint& p) {
  std::vector<std::string> fields = {std::to_string(p.pt), p.label};
  for (const auto& [name, value] : p.solution) fields.push_back(Number(value));
  for (const auto& [name, value] : p.margins) fields.push_back(Number(value));
  for (const std::complex<double>& mu : p.multipliers) {
    fields.push_back(Number(mu.real()));
    fields.push_back(Number(mu.imag()));
  }
  fields.push_back(Flag(p.stable));
  for (double v : {p.fold_test, p.flip_test, p.torus_test, p.symmetry_test}) fields.push_back(Number(v));
  fields.push_back(Flag(p.admissible));
  for (const auto& [name, value] : p.measures) fields.push_back(Number(value));
  fields.push_back(std::to_string(p.newton_iterations));
  fields.push_back(Number(p.step_size));
  return fmt::format("{}", fmt::join(fields, ","));
}

std::string FormatSummary(const StoredRun& run) {
  Json json = Json::object();
  for (const TextKey& k : kLeadingKeys) json[k.key] = run.summary.*k.field;
  if (!run.summary.model.empty()) json[kModelKey] = run.summary.model;
  if (!run.summary.units.Scaled()) {
    for (const auto& [key, unit] : ModelUnits::kNamed) json[kUnitsKey][key] = run.summary.units.*unit;
  }
  json[kPointsKey] = run.branch.size();
  json[kSpecialPointsKey] = Json::object();
  for (const auto& [type, count] : CountsByType(run.special_points)) json[kSpecialPointsKey][type] = count;
  for (const TextKey& k : kTrailingKeys) json[k.key] = run.summary.*k.field;
  // Bytes that are not UTF-8 (a run file's path may hold any) become U+FFFD instead of failing.
  return json.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

// ---- Reading

// summary.json as written by FormatSummary, with its counts.
struct Summary {
  StoredSummary fields;
  std::size_t points = 0;
  std::map<std::string, std::size_t> special_points;
};

std::size_t Count(const Json& value, const fs::path& file, const std::string& key) {
  if (!value.is_number_unsigned()) {
    throw KeyError(file, key, fmt::format("= {} is invalid: valid a count (an integer >= 0)", value.dump()));
  }
  return value.get<std::size_t>();
}

// A [model] run's units: SI where summary.json has none (written before they could be declared).
ModelUnits UnitsOf(const Json& json, const fs::path& file) {
  const auto units = json.find(kUnitsKey);
  if (units == json.end()) return SiUnits();
  const auto invalid = [&] {
    return KeyError(file, kUnitsKey,
                    fmt::format("= {} is invalid: valid an object of strings: length, time, force", units->dump()));
  };
  if (!units->is_object() || units->size() != ModelUnits::kNamed.size()) throw invalid();
  ModelUnits out;
  for (const auto& [key, unit] : ModelUnits::kNamed) {
    const auto value = units->find(key);
    if (value == units->end() || !value->is_string()) throw invalid();
    out.*unit = value->get<std::string>();
  }
  try {
    CheckUnits(out);
  } catch (const InvalidInput& e) {
    throw InvalidInput::WithMessage(e.field(), fmt::format("{}: {}", file.string(), e.what()));
  }
  return out;
}

Summary ParseSummary(const std::string& text, const fs::path& file) {
  const Json json = detail::ParseJsonObject(text, file);
  Summary summary;
  std::vector<std::string> known = {kModelKey, kUnitsKey, kPointsKey, kSpecialPointsKey};
  auto required = [&](const std::string& key) -> const Json& {
    const auto it = json.find(key);
    if (it == json.end()) throw KeyError(file, key, "is missing");
    return *it;
  };
  for (const auto& keys : {std::span<const TextKey>(kLeadingKeys), std::span<const TextKey>(kTrailingKeys)}) {
    for (const TextKey& k : keys) {
      const Json& value = required(k.key);
      if (!value.is_string()) throw KeyError(file, k.key, fmt::format("= {} is invalid: valid a string", value.dump()));
      summary.fields.*k.field = value.get<std::string>();
      known.push_back(k.key);
    }
  }
  if (const auto model = json.find(kModelKey); model != json.end()) {
    if (!model->is_string() || model->get<std::string>() != kLinearOscillatorModel) {
      throw KeyError(file, kModelKey, fmt::format("= {} is invalid: valid \"{}\" (or no key, for the paper's model)",
                                                  model->dump(), kLinearOscillatorModel));
    }
    summary.fields.model = model->get<std::string>();
    summary.fields.units = UnitsOf(json, file);
  } else if (json.contains(kUnitsKey)) {
    throw KeyError(file, kUnitsKey, "is invalid: valid only in a [model]'s run (the paper's model is scaled)");
  }
  summary.points = Count(required(kPointsKey), file, kPointsKey);
  const Json& special = required(kSpecialPointsKey);
  if (!special.is_object()) {
    throw KeyError(file, kSpecialPointsKey,
                   fmt::format("= {} is invalid: valid an object of counts by type", special.dump()));
  }
  for (const auto& [type, count] : special.items()) {
    summary.special_points[type] = Count(count, file, fmt::format("{}.{}", kSpecialPointsKey, type));
  }
  for (const auto& [key, value] : json.items()) {
    if (std::find(known.begin(), known.end(), key) == known.end()) {
      throw KeyError(file, key, fmt::format("is unknown: valid {}", fmt::join(known, ", ")));
    }
  }
  return summary;
}

// The column of a measure a file written before it existed lacks (orbit_columns::AddedLater).
constexpr int kAbsent = -1;

// Where each field of a StoredPoint is in a table.
struct ColumnIndices {
  int pt = 0;
  int label = 0;
  std::vector<std::pair<int, int>> variables;    // the paper's: (column, orbit_variables index)
  std::vector<int> solution;                     // another model's: its variables' columns, in order
  std::vector<int> margins;
  std::vector<std::pair<int, int>> multipliers;  // (real part, imaginary part)
  std::array<int, kStabilityColumns.size()> stability{};
  int admissible = 0;
  std::vector<std::pair<std::string, int>> measures;  // (name, column); kAbsent for a measure added later
  std::array<int, kStepColumns.size()> step{};
  std::array<int, kSpecialColumns.size()> special{};  // special-points.csv only
};

// The names of the measures whose columns the table lacks.
std::vector<std::string> AbsentMeasures(const ColumnIndices& c) {
  std::vector<std::string> absent;
  for (const auto& [name, column] : c.measures) {
    if (column == kAbsent) absent.push_back(name);
  }
  return absent;
}

// The paper's variables and measures, each by its name.
void FindPaperColumns(const CsvTable& table, const Signature& signature, const std::function<int(const std::string&)>& column,
                      ColumnIndices& c) {
  for (int i = 0; i < ov::Count(signature.size()); ++i) c.variables.emplace_back(column(ov::Name(signature.size(), i)), i);
  const OrbitMeasures measures{};
  orbit_columns::ForEachMeasure(measures, [&](const char* name, const auto&) {
    c.measures.emplace_back(name, orbit_columns::AddedLater(name) && table.Find(name) < 0 ? kAbsent : column(name));
  });
  // The measures added later come together: a file has all of them or none.
  const std::vector<std::string> absent = AbsentMeasures(c);
  for (const auto& [name, index] : c.measures) {
    if (orbit_columns::AddedLater(name) && !absent.empty() && index != kAbsent) {
      throw table.HeaderError(fmt::format("column '{}' is missing", absent.front()));
    }
  }
}

// Another model's variables, the columns between label and the margins, and its measures, those
// between admissible and the step's: the model names them (orbit_layout.hpp, MeasureNames).
void FindModelColumns(const CsvTable& table, const std::function<int(const std::string&)>& column, ColumnIndices& c) {
  const std::vector<std::string>& header = table.header();
  const auto first_margin = std::find_if(header.begin(), header.end(), [](const std::string& name) {
    return name.starts_with(kMarginPrefix) || name.starts_with("floquet:") || name == orbit_columns::kStable;
  });
  for (auto name = header.begin() + std::min<std::size_t>(2, header.size()); name < first_margin; ++name) {
    c.solution.push_back(column(*name));
  }
  const auto admissible = std::find(header.begin(), header.end(), orbit_columns::kAdmissible);
  const auto step = std::find(header.begin(), header.end(), kStepColumns.front());
  for (auto name = admissible + (admissible != header.end()); name < step; ++name) c.measures.emplace_back(*name, column(*name));
  // The measures MeasureNames gives any model: the coordinates' amplitudes and the contact's
  // peak-to-peak, then the same five as the paper's.
  const std::vector<std::string> tail = {orbit_columns::kStickFraction, orbit_columns::kStops, orbit_columns::kSticks,
                                         orbit_columns::kFrictionWork, orbit_columns::kEquivalentDamping};
  bool valid = c.measures.size() > tail.size();
  for (std::size_t k = 0; valid && k < c.measures.size(); ++k) {
    const std::string& name = c.measures[k].first;
    const std::size_t from_tail = c.measures.size() - tail.size();
    valid = k >= from_tail ? name == tail[k - from_tail] : name.starts_with("amplitude:") || name.starts_with("peak-to-peak:");
  }
  if (!valid) {
    throw table.HeaderError(fmt::format("the measure columns are invalid: valid amplitude:<coordinate> ..., "
                                        "peak-to-peak:<contact>, then {} after admissible", fmt::join(tail, ", ")));
  }
}

// Throws InvalidInput if a column is missing, unknown or repeated.
ColumnIndices FindColumns(const CsvTable& table, const Signature& signature, bool paper_model, bool special_points) {
  std::vector<bool> used(table.header().size(), false);
  const std::function<int(const std::string&)> column = [&](const std::string& name) {
    const int c = table.Column(name);
    used[c] = true;
    return c;
  };
  ColumnIndices c;
  c.pt = column("pt");
  c.label = column("label");
  if (paper_model) {
    FindPaperColumns(table, signature, column, c);
  } else {
    FindModelColumns(table, column, c);
  }
  for (std::size_t k = 0; k < table.header().size(); ++k) {
    if (table.header()[k].starts_with(kMarginPrefix)) c.margins.push_back(column(table.header()[k]));
  }
  for (std::size_t k = 1; table.Find(MultiplierColumn(k, "re")) >= 0; ++k) {
    c.multipliers.emplace_back(column(MultiplierColumn(k, "re")), column(MultiplierColumn(k, "im")));
  }
  for (std::size_t k = 0; k < kStabilityColumns.size(); ++k) c.stability[k] = column(kStabilityColumns[k]);
  c.admissible = column(orbit_columns::kAdmissible);
  for (std::size_t k = 0; k < kStepColumns.size(); ++k) c.step[k] = column(kStepColumns[k]);
  for (std::size_t k = 0; special_points && k < kSpecialColumns.size(); ++k) c.special[k] = column(kSpecialColumns[k]);
  for (std::size_t k = 0; k < used.size(); ++k) {
    if (!used[k]) throw table.HeaderError(fmt::format("column '{}' is unknown or repeated", table.header()[k]));
  }
  return c;
}

// A measure from its column (column_kinds.hpp): a count as a whole number >= 0, the stick
// fraction 0 to 1 where admissible, the friction work and the equivalent damping a finite number
// or nan, any other a number >= 0; nan from a column the file lacks (a measure added later).
double ReadMeasure(const CsvTable& t, int row, const std::string& name, int column, bool admissible) {
  if (column == kAbsent) return std::numeric_limits<double>::quiet_NaN();
  if (name == orbit_columns::kStops || name == orbit_columns::kSticks) {
    return t.Integer(row, column, 0, std::numeric_limits<int>::max());
  }
  return t.Value(row, column, name == orbit_columns::kStickFraction ? detail::Fraction(admissible)
                              : orbit_columns::AddedLater(name)     ? detail::FrictionMeasure()
                                                                    : detail::NonNegative());
}

// The row's orbit of the paper's model, each variable by its kind: the parameters in their ranges
// on a branch, the state and phase finite, then each duration within the period that omega gives.
Orbit ParseOrbit(const CsvTable& t, int row, const ColumnIndices& c, const Signature& signature, bool admissible) {
  const int n = signature.size();
  const int first_parameter = ov::FirstParameter(n);
  Eigen::VectorXd variables = Eigen::VectorXd::Zero(ov::Count(n));
  for (const auto& [column, index] : c.variables) {
    if (index >= first_parameter) {
      variables(index) = t.Value(row, column, detail::BranchParameter(kAllParameters[index - first_parameter]));
    } else if (index < ov::Duration(0)) {
      variables(index) = t.Value(row, column, detail::Finite());
    }
  }
  Orbit orbit = ov::Unpack(signature, variables);
  for (const auto& [column, index] : c.variables) {
    if (index < ov::Duration(0) || index >= ov::Duration(n)) continue;
    const detail::ValidValues valid = detail::Duration(t.header()[column], orbit.Period(), admissible);
    orbit.durations[index - ov::Duration(0)] = t.Value(row, column, valid);
  }
  return orbit;
}

// Another model's variables as its columns must stand for the files' readers (trace.csv, a
// period, the model's orbit): the continued parameter among them, then phi, the start state and
// d1..dn last, in order.
void CheckModelVariables(const CsvTable& table, const ColumnIndices& c, const Signature& signature,
                         const std::string& parameter, const fs::path& summary_file) {
  std::vector<std::string> names;
  for (int column : c.solution) names.push_back(table.header()[column]);
  const int n = signature.size();
  const auto phi = std::find(names.begin(), names.end(), "phi");
  for (int i = 0; i < n; ++i) {
    const std::size_t at = names.size() - n + i;
    if (names.size() < static_cast<std::size_t>(n) + 1 || names[at] != fmt::format("d{}", i + 1) ||
        phi == names.end() || phi >= names.begin() + static_cast<std::ptrdiff_t>(names.size() - n)) {
      throw table.HeaderError(fmt::format("the orbit's variables {} are invalid: valid its parameters, phi, its start "
                                          "state, then d1..d{} in order",
                                          fmt::join(names, ","), n));
    }
  }
  if (std::find(names.begin(), names.end(), parameter) == names.end()) {
    throw KeyError(summary_file, "parameter",
                   fmt::format("= '{}' is not a column of the tables: valid one of the orbit's variables, {}", parameter,
                               fmt::join(names, ", ")));
  }
}

// The row's variables: the paper's by their kinds (ParseOrbit); another model's finite (its
// ranges are its file's, which the run's files do not hold), but what holds for every linear
// oscillator with a Coulomb contact where the row is admissible: the kinetic level F_k > 0 (its
// sliding-friction margin), the static level F_s >= F_k, each duration within the period.
NamedValues ParseSolution(const CsvTable& t, int row, const ColumnIndices& c, const Signature& signature, bool admissible) {
  if (!c.variables.empty()) return SolutionColumns(ParseOrbit(t, row, c, signature, admissible));
  StoredPoint point;
  for (int column : c.solution) {
    const std::string& name = t.header()[column];
    point.solution.emplace_back(name, t.Value(row, column, name == "omega" ? detail::ValidValues{.min = std::nextafter(0.0, 1.0), .text = "omega > 0"}
                                                                          : detail::Finite()));
  }
  if (!admissible) return point.solution;
  // The durations are the last columns (CheckModelVariables); F_k stands before F_s.
  const std::size_t first_duration = c.solution.size() - signature.size();
  std::optional<double> kinetic;
  for (std::size_t k = 0; k < c.solution.size(); ++k) {
    const int column = c.solution[k];
    const std::string& name = t.header()[column];
    if (k >= first_duration) {
      t.Value(row, column, detail::Duration(name, StoredPeriod(signature, point), true));
    } else if (name == "F_k") {
      kinetic = t.Value(row, column, {.min = std::nextafter(0.0, 1.0), .text = "F_k > 0 where admissible"});
    } else if (name == "F_s" && kinetic) {
      t.Value(row, column, {.min = *kinetic * (1.0 - 1e-12), .text = fmt::format("F_s >= F_k = {} where admissible", *kinetic)});
    }
  }
  return point.solution;
}

// Every column by its kind (column_kinds.hpp); the non-finite values only where the format has them.
StoredPoint ParsePoint(const CsvTable& t, int row, const ColumnIndices& c, const Signature& signature) {
  const bool admissible = t.Flag(row, c.admissible);
  StoredPoint p{.pt = t.Integer(row, c.pt, 1, std::numeric_limits<int>::max()),
                .label = t.Text(row, c.label),
                .solution = ParseSolution(t, row, c, signature, admissible)};
  for (int column : c.margins) {
    p.margins.emplace_back(t.header()[column].substr(kMarginPrefix.size()), t.Value(row, column, detail::Margin()));
  }
  const detail::ValidValues floquet = detail::FloquetValue();
  for (const auto& [re, im] : c.multipliers) p.multipliers.emplace_back(t.Value(row, re, floquet), t.Value(row, im, floquet));
  p.stable = t.Flag(row, c.stability[0]);
  const detail::ValidValues product = detail::FloquetProduct();
  p.fold_test = t.Value(row, c.stability[1], product);
  p.flip_test = t.Value(row, c.stability[2], product);
  p.torus_test = t.Value(row, c.stability[3], product);
  p.symmetry_test = t.Value(row, c.stability[4], detail::SymmetryTest(signature.antisymmetric()));
  p.admissible = admissible;
  for (const auto& [name, column] : c.measures) p.measures.emplace_back(name, ReadMeasure(t, row, name, column, admissible));
  p.newton_iterations = t.Integer(row, c.step[0], 0, std::numeric_limits<int>::max());
  p.step_size = t.Value(row, c.step[1], detail::NonNegative());
  return p;
}

std::string DescribeCounts(const std::map<std::string, std::size_t>& counts) {
  std::vector<std::string> parts;
  for (const auto& [type, count] : counts) parts.push_back(fmt::format("{} {}", type, count));
  return parts.empty() ? "none" : fmt::format("{}", fmt::join(parts, ", "));
}


// Whether `directory` can be created, found by creating what is missing of it and removing that
// again; the error of the first directory that could not be.
std::error_code TryCreateDirectories(const fs::path& directory) {
  std::vector<fs::path> missing;
  std::error_code ignored;
  for (fs::path p = directory; !p.empty() && !fs::exists(p, ignored); p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;  // a root that is not there
  }
  std::error_code error;
  std::vector<fs::path> created;
  for (auto p = missing.rbegin(); p != missing.rend() && !error; ++p) {
    if (fs::create_directory(*p, error)) created.push_back(*p);
  }
  for (auto p = created.rbegin(); p != created.rend(); ++p) fs::remove(*p, ignored);
  return error;
}

}  // namespace

std::vector<std::string> ColumnNames(const StoredPoint& p) {
  std::vector<std::string> columns = {"pt", "label"};
  for (const auto& [name, value] : p.solution) columns.push_back(name);
  for (const auto& [name, value] : p.margins) columns.push_back(std::string(kMarginPrefix) + name);
  for (std::size_t k = 1; k <= p.multipliers.size(); ++k) {
    columns.push_back(MultiplierColumn(k, "re"));
    columns.push_back(MultiplierColumn(k, "im"));
  }
  columns.insert(columns.end(), kStabilityColumns.begin(), kStabilityColumns.end());
  columns.push_back(orbit_columns::kAdmissible);
  for (const auto& [name, value] : p.measures) columns.push_back(name);
  columns.insert(columns.end(), kStepColumns.begin(), kStepColumns.end());
  return columns;
}

RunFiles FormatRunFiles(const StoredRun& run) {
  if (run.branch.empty()) throw std::invalid_argument("FormatRunFiles: the run has no branch point");
  const std::vector<std::string> header = ColumnNames(run.branch.front());
  auto check = [&](const StoredPoint& p) {
    if (ColumnNames(p) != header) {
      throw std::invalid_argument(fmt::format("FormatRunFiles: point {} has other columns than point 1", p.pt));
    }
  };
  RunFiles files;
  files.branch_csv = fmt::format("{}\n", fmt::join(header, ","));
  for (const StoredPoint& p : run.branch) {
    check(p);
    files.branch_csv += Row(p) + "\n";
  }
  files.special_points_csv = fmt::format("{},{}\n", fmt::join(header, ","), fmt::join(kSpecialColumns, ","));
  for (const StoredSpecialPoint& s : run.special_points) {
    check(s.point);
    files.special_points_csv += fmt::format("{},{},{},{}\n", Row(s.point), s.type, s.test_function, Flag(s.located));
  }
  files.summary_json = FormatSummary(run);
  return files;
}

namespace {

// The summary's signature, and the check that its parameter is a variable of such an orbit.
Signature SummarySignature(const Summary& summary, const fs::path& summary_file) {
  const Signature signature = [&] {
    try {
      return Signature::Parse(summary.fields.signature);
    } catch (const InvalidInput& e) {
      throw KeyError(summary_file, "signature", fmt::format("= '{}' is invalid: {}", summary.fields.signature, e.what()));
    }
  }();
  if (summary.fields.model.empty() && !ov::IndexOf(signature.size(), summary.fields.parameter)) {
    std::vector<std::string> names;
    for (int i = 0; i < ov::Count(signature.size()); ++i) names.push_back(ov::Name(signature.size(), i));
    throw KeyError(summary_file, "parameter", fmt::format("= '{}' is invalid: valid a variable of the orbit, {}",
                                                          summary.fields.parameter, fmt::join(names, ", ")));
  }
  return signature;
}

// special-points.csv, whose point columns are branch.csv's (those of `run`, read first).
std::vector<StoredSpecialPoint> ParseSpecialPoints(const std::string& text, const fs::path& directory,
                                                   const Signature& signature, const StoredRun& run) {
  const bool paper_model = run.summary.model.empty();
  const CsvTable special(text, directory / kSpecialPointsFile);
  const ColumnIndices special_columns = FindColumns(special, signature, paper_model, true);
  if (!paper_model) CheckModelVariables(special, special_columns, signature, run.summary.parameter, directory / kSummaryFile);
  constexpr std::string_view kSameColumns = "the point columns differ from branch.csv's: valid the same, then type, "
                                            "test_function, located";
  if (AbsentMeasures(special_columns) != run.absent_measures) throw special.HeaderError(kSameColumns);
  const std::vector<std::string> header = ColumnNames(run.branch.front());
  std::vector<StoredSpecialPoint> points;
  for (int row = 0; row < special.rows(); ++row) {
    StoredPoint point = ParsePoint(special, row, special_columns, signature);
    if (ColumnNames(point) != header) throw special.HeaderError(kSameColumns);
    const auto same = [&point](const StoredSpecialPoint& s) { return s.point.label == point.label; };
    if (std::any_of(points.begin(), points.end(), same)) {  // a restart would pick one
      throw KeyError(directory / kSpecialPointsFile, "label",
                     fmt::format("= '{}' (row {}) is invalid: an earlier row has it: valid each label once", point.label,
                                 row + 2));
    }
    const std::array<int, 3>& c = special_columns.special;
    points.push_back({std::move(point), special.Text(row, c[0]), special.Text(row, c[1]), special.Flag(row, c[2])});
  }
  return points;
}

}  // namespace

StoredRun ParseRunFiles(const RunFiles& files, const fs::path& directory) {
  const fs::path summary_file = directory / kSummaryFile;
  Summary summary = ParseSummary(files.summary_json, summary_file);
  const Signature signature = SummarySignature(summary, summary_file);
  const bool paper_model = summary.fields.model.empty();
  StoredRun run{std::move(summary.fields), {}, {}};
  const CsvTable branch(files.branch_csv, directory / kBranchFile);
  const ColumnIndices branch_columns = FindColumns(branch, signature, paper_model, false);
  if (!paper_model) CheckModelVariables(branch, branch_columns, signature, run.summary.parameter, summary_file);
  for (int row = 0; row < branch.rows(); ++row) run.branch.push_back(ParsePoint(branch, row, branch_columns, signature));
  run.absent_measures = AbsentMeasures(branch_columns);
  if (run.branch.empty()) throw branch.HeaderError("has no point: valid at least the start of the branch");
  run.special_points = ParseSpecialPoints(files.special_points_csv, directory, signature, run);
  if (summary.points != run.branch.size()) {
    throw KeyError(summary_file, kPointsKey,
                   fmt::format("= {} differs from the {} rows of {}", summary.points, run.branch.size(), kBranchFile));
  }
  const std::map<std::string, std::size_t> counts = CountsByType(run.special_points);
  if (summary.special_points != counts) {
    throw KeyError(summary_file, kSpecialPointsKey,
                   fmt::format("({}) differs from the rows of {} ({})", DescribeCounts(summary.special_points),
                               kSpecialPointsFile, DescribeCounts(counts)));
  }
  return run;
}

namespace detail {

bool IsRunFileName(std::string_view name) {
  return name == kBranchFile || name == kSpecialPointsFile || name == kSummaryFile;
}

}  // namespace detail

void CheckOutputDirectory(const fs::path& results_root, const std::string& output) {
  auto results_error = [&](const std::string& why) {
    return InvalidInput::WithMessage(
        "results", fmt::format("results = '{}' is invalid: {}: valid a directory, or a path where one can be created",
                               results_root.string(), why));
  };
  if (results_root.empty()) throw results_error("it is empty");
  // Before the probe below, which would touch the trace's directory.
  if (IsPartOfTrace(results_root, output)) {
    throw InvalidInput::WithMessage(
        "output", fmt::format("output = '{}' is invalid: '{}' is a part of the trace '{}': valid a name a trace does not "
                              "write (not trace.csv, trace.json, branch-<k> or branch-<k>-<label>)",
                              output, (results_root / output).string(), results_root.string()));
  }
  std::error_code error;
  const fs::file_status root = fs::status(results_root, error);
  if (fs::exists(root) && !fs::is_directory(root)) throw results_error("it is not a directory");
  if (!fs::exists(root)) {
    if (const std::error_code failed = TryCreateDirectories(results_root)) {
      throw results_error(fmt::format("it cannot be created ({})", failed.message()));
    }
    return;  // then it holds no output yet
  }
  if (const std::error_code failed = CanCreateFileIn(results_root)) {
    throw results_error(fmt::format("no file can be created in it ({})", failed.message()));
  }

  const fs::path target = results_root / output;
  const fs::file_status status = fs::symlink_status(target, error);
  if (status.type() == fs::file_type::not_found) return;
  auto refuse = [&](const std::string& why) {
    return InvalidInput::WithMessage(
        "output", fmt::format("output = '{}' is invalid: '{}' {}: valid a new name or the directory of a stickslip run "
                              "(with its summary.json)",
                              output, target.string(), why));
  };
  if (error) throw refuse(fmt::format("cannot be examined ({})", error.message()));
  if (fs::is_symlink(status)) throw refuse("is a symbolic link");
  if (!fs::is_directory(status)) throw refuse("is not a directory");
  try {
    ParseSummary(ReadTextFile(target / kSummaryFile), target / kSummaryFile);
  } catch (const InvalidInput& e) {
    throw refuse(fmt::format("holds no stickslip run ({})", e.what()));
  }
}

std::vector<std::string> WriteRunFiles(const fs::path& results_root, const StoredRun& run) {
  const RunFiles files = FormatRunFiles(run);
  const std::string& output = run.summary.output;
  CheckOutputDirectory(results_root, output);
  return detail::ReplaceDirectory(
      results_root, output,
      [&](const fs::path& directory) {
        WriteFileAtomically(directory / kBranchFile, files.branch_csv);
        WriteFileAtomically(directory / kSpecialPointsFile, files.special_points_csv);
        WriteFileAtomically(directory / kSummaryFile, files.summary_json);
      },
      detail::IsRunEntry, detail::IsRunEntry);
}

StoredRun ReadRunFiles(const fs::path& run_directory) {
  const RunFiles files{ReadTextFile(run_directory / kBranchFile), ReadTextFile(run_directory / kSpecialPointsFile),
                       ReadTextFile(run_directory / kSummaryFile)};
  return ParseRunFiles(files, run_directory);
}

StoredSummary ReadRunSummary(const fs::path& run_directory) {
  return ParseSummary(ReadTextFile(run_directory / kSummaryFile), run_directory / kSummaryFile).fields;
}

const StoredSpecialPoint& SpecialPointLabelled(const StoredRun& run, const std::string& label,
                                               const fs::path& run_directory) {
  std::vector<std::string> labels;
  for (const StoredSpecialPoint& s : run.special_points) {
    if (s.point.label == label) return s;
    labels.push_back(s.point.label);
  }
  throw InvalidInput::WithMessage(
      "label", fmt::format("label '{}' is not in '{}': valid labels {}", label,
                           (run_directory / kSpecialPointsFile).string(), fmt::join(labels, ", ")));
}

LabelledPoint ReadLabelledPoint(const fs::path& results_root, const std::string& run, const std::string& label) {
  if (!IsRunName(run)) {
    throw InvalidInput::WithMessage("run", fmt::format("run '{}' is invalid: valid {}", run, kRunNameRule));
  }
  const StoredRun stored = ReadRunFiles(results_root / run);
  if (!stored.summary.model.empty()) {
    throw InvalidInput::WithMessage(
        "run", fmt::format("'{}' holds a run of a {} (a run file's [model]): valid here a run of the paper's "
                           "oscillator (the command line's solve, continue and trace, and Python's trace() and "
                           "continue_orbit(), take a [model]'s label)",
                           (results_root / run).string(), stored.summary.model));
  }
  const StoredSpecialPoint& s = SpecialPointLabelled(stored, label, results_root / run);
  return {stored.summary.signature, s.point.solution, s.type, s.test_function};
}

}  // namespace stickslip
