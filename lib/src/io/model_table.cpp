// toml++ through toml_table.hpp, first: it undefines NDEBUG before anything includes <cassert>.
#include "toml_table.hpp"

#include "stickslip/io/model_table.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <optional>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "stickslip/io/matrix_market.hpp"

namespace stickslip {

using toml_reading::ParseToml;
using toml_reading::TableReader;
using toml_reading::Where;

namespace {

using Locations = std::map<std::string, std::string>;

// The masses' names as the file writes them: names = [...], or m1 ... mn.
std::vector<std::string> MassNames(const Chain& chain) {
  if (!chain.names.empty()) return chain.names;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < chain.masses.size(); ++i) names.push_back(fmt::format("m{}", i + 1));
  return names;
}

// The index of `name` among the masses (kGround for "ground" where allowed), or a RunFileError at
// the node.
int MassIndex(TableReader& r, const toml::node& node, std::string_view key, const std::vector<std::string>& names,
              bool ground) {
  const std::string name = node.is_string() ? node.as_string()->get() : std::string();
  if (ground && name == "ground") return kGround;
  const auto it = std::find(names.begin(), names.end(), name);
  if (!node.is_string() || it == names.end()) {
    r.Fail(node, key, fmt::format("= {} is invalid: valid {}{}", node.is_string() ? "'" + name + "'" : "a non-string",
                                  ground ? "'ground' or " : "", fmt::format("one of '{}'", fmt::join(names, "', '"))));
  }
  return static_cast<int>(it - names.begin());
}

// springs or dampers: an array of { between = [a, b], <coefficient> = value }.
std::vector<ChainLink> ReadLinks(TableReader& model, std::string_view key, const char* coefficient,
                                 const std::vector<std::string>& names, std::string_view path, Locations* locations) {
  std::vector<ChainLink> links;
  const toml::node* n = model.Get(key);
  if (!n) return links;
  if (!n->is_array()) model.Fail(*n, key, fmt::format("must be an array of {{ between = [a, b], {} = value }}", coefficient));
  for (const toml::node& e : *n->as_array()) {
    const std::string item = fmt::format("{}[{}]", key, links.size());
    if (!e.is_table()) model.Fail(e, item, fmt::format("must be {{ between = [a, b], {} = value }}", coefficient));
    TableReader link(*e.as_table(), fmt::format("model.{}.", item), path, locations);
    const toml::node* between = link.Get("between");
    if (!between) link.Missing("between", "give the two ends: two masses, or a mass and 'ground'");
    if (!between->is_array() || between->as_array()->size() != 2) {
      link.Fail(*between, "between", "must be an array of two names: two masses, or a mass and 'ground'");
    }
    ChainLink l;
    l.from = MassIndex(link, *between->as_array()->get(0), "between", names, true);
    l.to = MassIndex(link, *between->as_array()->get(1), "between", names, true);
    if (l.from == l.to) link.Fail(*between, "between", "must name two different ends");
    link.Number(coefficient, &l.value, true);
    if (l.value < 0.0) link.Fail(*link.Get(coefficient), coefficient, fmt::format("= {} is invalid: valid >= 0", l.value));
    link.RejectUnknown();
    links.push_back(l);
  }
  return links;
}

void ReadChain(TableReader& model, std::string_view path, Locations* locations, ModelTable* table) {
  Chain& chain = table->chain;
  model.Numbers("masses", &chain.masses);
  if (!model.Get("masses")) model.Missing("masses", "give the masses, one number each (> 0)");
  if (chain.masses.empty() || chain.masses.size() > static_cast<std::size_t>(kMaxLinearOscillatorCoordinates)) {
    model.Fail(*model.Get("masses"), "masses",
               fmt::format("holds {} masses: valid 1 to {}", chain.masses.size(), kMaxLinearOscillatorCoordinates));
  }
  model.Strings("names", &chain.names);
  if (!chain.names.empty() && chain.names.size() != chain.masses.size()) {
    model.Fail(*model.Get("names"), "names",
               fmt::format("has {} names: valid one per mass, {}", chain.names.size(), chain.masses.size()));
  }
  if (std::find(chain.names.begin(), chain.names.end(), "ground") != chain.names.end()) {
    model.Fail(*model.Get("names"), "names", "holds 'ground': valid names of masses ('ground' is the frame)");
  }
  const std::vector<std::string> names = MassNames(chain);
  chain.springs = ReadLinks(model, "springs", "k", names, path, locations);
  chain.dampers = ReadLinks(model, "dampers", "c", names, path, locations);
  if (const toml::node* forcing = model.Get("forcing")) {
    if (!forcing->is_table()) model.Fail(*forcing, "forcing", "must be a table of mass = amplitude");
    chain.forcing.assign(chain.masses.size(), 0.0);
    TableReader f(*forcing->as_table(), "model.forcing.", path, locations);
    for (const auto& [name, value] : *forcing->as_table()) {
      const auto mass = std::find(names.begin(), names.end(), name.str());
      if (mass == names.end()) {
        f.Fail(value, name.str(), fmt::format("is not a mass: valid one of '{}'", fmt::join(names, "', '")));
      }
      f.Number(name.str(), &chain.forcing[mass - names.begin()]);
    }
  }
  std::string contact;
  model.String("contact", &contact, true);
  chain.contact = MassIndex(model, *model.Get("contact"), "contact", names, false);
  chain.name = "chain";
}

void ReadMatrices(TableReader& model, ModelTable* table) {
  ModelMatrixFiles& m = table->matrices;
  model.String("mass", &m.mass, true);
  model.String("stiffness", &m.stiffness, true);
  model.String("damping", &m.damping);
  model.String("forcing", &m.forcing);
  model.Strings("coordinates", &m.coordinates);
  model.String("contact", &m.contact, true);
}

// units = { length = "mm", time = "ms", force = "N" }: each optional, SI where left out.
void ReadUnits(TableReader& model, std::string_view path, Locations* locations, ModelUnits* units) {
  const toml::node* node = model.Get("units");
  if (!node) return;
  if (!node->is_table()) model.Fail(*node, "units", "must be a table: units = { length = \"mm\", time = \"s\", force = \"N\" }");
  TableReader u(*node->as_table(), "model.units.", path, locations);
  u.String("length", &units->length);
  u.String("time", &units->time);
  u.String("force", &units->force);
  u.RejectUnknown();
}

}  // namespace

ModelTable ParseModelTable(std::string_view content, std::string_view path) {
  const toml::table root = ParseToml(content, path);
  const toml::node* node = root.get("model");
  if (node == nullptr) {
    std::map<std::string, std::string> locations;
    TableReader(root, "", path, &locations).Missing("model", "give a [model] table (kind = \"chain\" or \"matrices\")");
  }
  ModelTable table;
  Locations* locations = &table.locations;
  if (!node->is_table()) TableReader(root, "", path, locations).Fail(*node, "model", "must be a table");
  TableReader model(*node->as_table(), "model.", path, locations);
  table.path = std::string(path);
  table.location = Where(path, *node);
  model.String("kind", &table.kind, true);
  if (table.kind == "chain") {
    // Read before the keys that name masses.
    ReadChain(model, path, locations, &table);
  } else if (table.kind == "matrices") {
    ReadMatrices(model, &table);
  } else {
    model.Fail(*model.Get("kind"), "kind", fmt::format("= '{}' is invalid: valid \"chain\" or \"matrices\"", table.kind));
  }
  model.Number("friction_slope", &table.friction_slope);
  ReadUnits(model, path, locations, &table.units);
  model.Values("parameters", &table.parameters);
  model.Values("start", &table.start);
  model.RejectUnknown();
  return table;
}

ModelTable ReadModelTable(const std::filesystem::path& path) {
  std::error_code error;
  if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error)) {
    throw RunFileError(fmt::format("{}: cannot read the run file: not a regular file", path.string()));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw RunFileError(fmt::format("{}: cannot read the run file", path.string()));
  std::string content;
  char buffer[4096];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    content.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (content.size() > kMaxRunFileBytes) break;  // refused by the screen, with the limit named
  }
  return ParseModelTable(content, path.string());
}

namespace {

// The matrices in the files' order, each read and sized as the mass matrix is (n x n, the forcing
// n x 1); no damping or forcing file: zero.
LinearOscillatorData ReadMatrices(const ModelTable& table) {
  const ModelMatrixFiles& files = table.matrices;
  const std::filesystem::path folder = std::filesystem::path(table.path).parent_path();
  const auto read = [&](const std::string& file, const char* field) {
    try {
      return ReadMatrixMarket(folder / file, field);
    } catch (const InvalidInput& e) {
      throw e.Renamed(std::string("model.") + field);
    }
  };
  LinearOscillatorData data;
  data.name = "matrices";
  data.mass = read(files.mass, "mass");
  const Eigen::Index n = data.mass.rows();
  if (n != data.mass.cols() || n > kMaxLinearOscillatorCoordinates) {
    throw InvalidInput("model.mass", fmt::format("a {} x {} matrix", n, data.mass.cols()),
                       fmt::format("a square matrix of 1 to {} rows", kMaxLinearOscillatorCoordinates));
  }
  const auto sized = [&](const std::string& file, const char* field, Eigen::Index columns) {
    Eigen::MatrixXd m = read(file, field);
    if (m.rows() != n || m.cols() != columns) {
      throw InvalidInput(std::string("model.") + field, fmt::format("a {} x {} matrix", m.rows(), m.cols()),
                         fmt::format("a {} x {} matrix, as the mass matrix is {} x {}", n, columns, n, n));
    }
    return m;
  };
  data.stiffness = sized(files.stiffness, "stiffness", n);
  data.damping = files.damping.empty() ? Eigen::MatrixXd::Zero(n, n) : sized(files.damping, "damping", n);
  data.forcing = files.forcing.empty() ? Eigen::VectorXd::Zero(n) : Eigen::VectorXd(sized(files.forcing, "forcing", 1).col(0));
  return data;
}

// The matrices' oscillator, its contact's coordinate put last (the linear oscillator's convention)
// with every coordinate keeping its name.
LinearOscillatorData MatrixData(const ModelTable& table) {
  LinearOscillatorData data = ReadMatrices(table);
  const Eigen::Index n = data.mass.rows();
  std::vector<std::string> names = table.matrices.coordinates;
  if (names.empty()) {
    for (Eigen::Index j = 0; j < n; ++j) names.push_back(fmt::format("x{}", j + 1));
  }
  CheckCoordinateNames(names, n, "model.coordinates");
  const auto contact = std::find(names.begin(), names.end(), table.matrices.contact);
  if (contact == names.end()) {
    throw InvalidInput("model.contact", "'" + table.matrices.contact + "'",
                       fmt::format("one of the coordinates '{}'", fmt::join(names, "', '")));
  }
  // The permutation that moves the contact's coordinate last, the others keeping their order.
  Eigen::VectorXi order(n);
  for (Eigen::Index j = 0, next = 0; j < n; ++j) {
    if (j != contact - names.begin()) order(next++) = static_cast<int>(j);
  }
  order(n - 1) = static_cast<int>(contact - names.begin());
  const auto permuted = [&](const Eigen::MatrixXd& a) { return Eigen::MatrixXd(a(order, order)); };
  data.mass = permuted(data.mass);
  data.stiffness = permuted(data.stiffness);
  data.damping = permuted(data.damping);
  data.forcing = Eigen::VectorXd(data.forcing(order));
  for (Eigen::Index j = 0; j < n; ++j) data.coordinates.push_back(names[order(j)]);
  return data;
}

}  // namespace

// Where `key` is in the run file: its own place, else its nearest enclosing key's ("model.springs"
// for "model.springs[2]"), else the [model] table's.
std::string LocationOf(const ModelTable& table, std::string key) {
  while (!key.empty()) {
    if (const auto it = table.locations.find(key); it != table.locations.end()) return it->second;
    const std::size_t cut = key.find_last_of(".[");
    key = cut == std::string::npos ? std::string() : key.substr(0, cut);
  }
  return table.location;
}

// An error of the key it names, placed where the key is.
RunFileError AtKey(const ModelTable& table, const InvalidInput& e) {
  return RunFileError(fmt::format("{}: {}", LocationOf(table, e.field()), e.what()), e.field());
}

// The run file's key of a field of the model layer: masses[1] is model.masses[1]; in a chain the
// matrices it assembles are its masses, springs and dampers, its coordinates their names.
std::string KeyOf(const ModelTable& table, const std::string& field) {
  if (field.starts_with("model.")) return field;
  if (table.kind == "chain") {
    for (const auto& [matrix, key] : {std::pair{"mass", "masses"}, std::pair{"stiffness", "springs"},
                                      std::pair{"damping", "dampers"}, std::pair{"coordinates", "names"}}) {
      if (field == matrix) return std::string("model.") + key;
    }
  }
  return "model." + field;
}

// Errors of the model layer at the run file's keys.
template <typename Build>
auto AtModelKeys(const ModelTable& table, Build&& build) {
  try {
    return build();
  } catch (const RunFileError&) {
    throw;
  } catch (const InvalidInput& e) {
    const std::string key = KeyOf(table, e.field());
    throw AtKey(table, key == e.field() ? e : e.Renamed(key));
  }
}

LinearOscillatorData ModelDataOf(const ModelTable& table) {
  return AtModelKeys(table, [&] {
    LinearOscillatorData data = table.kind == "chain" ? ChainData(table.chain) : MatrixData(table);
    data.friction_slope = table.friction_slope;
    data.units = table.units;
    ModesOf(data);  // checks what the matrices must be
    return data;
  });
}

DynamicLinearOscillator ModelOf(const ModelTable& table) {
  return AtModelKeys(table, [&] { return DynamicLinearOscillator(ModelDataOf(table)); });
}

namespace {

InvalidInput UnknownParameter(const ModelDescription& d, const std::string& field, double value) {
  std::vector<std::string> names;
  for (const ParameterDescription& p : d.parameters) names.push_back(p.name);
  return InvalidInput::WithMessage(field, fmt::format("{} = {} is invalid: {} is no parameter of the model: valid {}",
                                                      field, value, field, fmt::join(names, ", ")));
}

}  // namespace

std::vector<std::optional<double>> GivenParameters(const ModelDescription& d, const ModelTable& table) {
  std::vector<std::optional<double>> values(d.parameters.size());
  for (const auto& [name, value] : table.parameters) {
    const std::optional<int> k = d.ParameterIndex(name);
    if (!k) throw AtKey(table, UnknownParameter(d, "model.parameters." + name, value));
    values[*k] = value;
  }
  return values;
}

DynamicLinearOscillator::Parameters ParametersOf(const DynamicLinearOscillator& model, const ModelTable& table,
                                                 const NamedValues& set) {
  const ModelDescription& d = model.Description();
  std::vector<std::optional<double>> values = GivenParameters(d, table);
  std::vector<bool> from_set(d.parameters.size(), false);
  for (const auto& [name, value] : set) {
    const std::optional<int> k = d.ParameterIndex(name);
    if (!k) throw UnknownParameter(d, name, value);
    values[*k] = value;
    from_set[*k] = true;
  }
  if (!values[3]) values[3] = 0.0;                        // v_b: a fixed surface
  if (!values[0] && model.Autonomous()) values[0] = 1.0;  // plays no part without forcing
  DynamicLinearOscillator::Parameters p;
  for (std::size_t k = 0; k < values.size(); ++k) {
    const ParameterDescription& description = d.parameters[k];
    if (!values[k]) {
      const std::string key = "model.parameters." + description.name;
      throw AtKey(table, InvalidInput::WithMessage(key, fmt::format("{} is missing: give the {} ({}, {})", key,
                                                                     description.meaning, description.unit,
                                                                     description.range)));
    }
    DynamicLinearOscillator::ParameterAt(p, static_cast<int>(k)) = *values[k];
  }
  if (std::optional<InvalidInput> invalid = model.Validate(p)) {
    const std::optional<int> k = d.ParameterIndex(invalid->field());
    if (k && from_set[*k]) throw *invalid;
    throw AtKey(table, invalid->Renamed("model.parameters." + invalid->field()));
  }
  return p;
}

bool IsStartName(const ModelDescription& d, std::string_view name) {
  return name == "phi" || std::find(d.initial_state.begin(), d.initial_state.end(), name) != d.initial_state.end();
}

ModelStartState StartOf(const DynamicLinearOscillator& model, const ModelTable& table, const NamedValues& set) {
  const ModelDescription& d = model.Description();
  ModelStartState start{Eigen::VectorXd::Zero(model.StateSize()), 0.0};
  // The start's `name` (IsStartName) set to `value`, checked.
  const auto set_start = [&](const std::string& name, double value) {
    if (!(std::abs(value) <= kMaxModelStartValue)) {
      throw InvalidInput(name, value, fmt::format("|{}| <= {:g}", name, kMaxModelStartValue));
    }
    if (name == "phi") {
      start.phi = value;
    } else {
      start.state(std::find(d.initial_state.begin(), d.initial_state.end(), name) - d.initial_state.begin()) = value;
    }
  };
  for (const auto& [name, value] : table.start) {
    const std::string key = "model.start." + name;
    if (!IsStartName(d, name)) {
      throw AtKey(table, InvalidInput::WithMessage(
                             key, fmt::format("{} = {} is invalid: {} is not the start's: valid {} and phi", key, value,
                                              name, fmt::join(d.initial_state, ", "))));
    }
    try {
      set_start(name, value);
    } catch (const InvalidInput& e) {
      throw AtKey(table, e.Renamed(key));
    }
  }
  for (const auto& [name, value] : set) {
    if (IsStartName(d, name)) set_start(name, value);
  }
  return start;
}

}  // namespace stickslip
