#include "stickslip/io/map_file.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <limits>
#include <system_error>
#include <map>
#include <optional>
#include <string_view>
#include <tuple>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "csv_table.hpp"
#include "stickslip/analysis/model_brute_force_map.hpp"
#include "stickslip/branches/orbit_monitor.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/signature.hpp"

namespace stickslip {

namespace {

constexpr const char* kColumnsBefore = "i,j,ni,nj";
// The columns from the section phase to an attractor's start count, in both maps.
constexpr const char* kAttractorColumns =
    "section_phase,run,attractors,attractor,status,period,stops_per_period,sticks_per_period,starts";
// The paper's map's after them: the signature and the state.
constexpr const char* kPaperColumnsAfter = "signature,k,x1,x2,v1,v2";

std::string Header(ParameterId first, ParameterId second) {
  return fmt::format("{},{},{},{},{}", kColumnsBefore, ToString(first), ToString(second), kAttractorColumns, kPaperColumnsAfter);
}

std::string Header(const ModelBruteForceMap& map) {
  return fmt::format("{},{},{},{},{},k,{}", kColumnsBefore, map.first, map.second, kAttractorColumns,
                     orbit_columns::AmplitudeOf(map.contact), fmt::join(map.state_columns, ","));
}

// A row's columns from i to starts.
template <typename Map, typename Cell, typename Attractor>
std::string RowStart(const Map& map, const Cell& cell, std::size_t index, const Attractor& a) {
  return fmt::format("{},{},{},{},{},{},{},{:016x},{},{},{},{},{},{},{}", cell.i, cell.j, map.first_count,
                     map.second_count, cell.first, cell.second, map.section_phase, map.run, cell.attractors.size(), index,
                     ToString(a.status), a.period, a.stops_per_period, a.sticks_per_period, a.starts);
}

// The model's header: the leading and attractor columns, a name, the amplitude and k, then the
// state's names (at least one).
bool IsModelMapHeader(std::string_view line) {
  const std::string before = std::string(kColumnsBefore) + ",", middle = "," + std::string(kAttractorColumns) + ",amplitude:";
  const std::size_t at = line.find(middle);
  if (!line.starts_with(before) || at == std::string_view::npos) return false;
  const std::string_view names = line.substr(before.size(), at - before.size());
  const std::size_t comma = names.find(',');
  const std::string_view rest = line.substr(at + middle.size());
  const std::size_t k = rest.find(",k,");
  return comma != std::string_view::npos && comma > 0 && comma + 1 < names.size() &&
         names.find(',', comma + 1) == std::string_view::npos && k != std::string_view::npos && k > 0 &&
         k + 3 < rest.size();
}

}  // namespace

bool IsBruteForceMapCsvHeader(std::string_view line) {
  if (IsModelMapHeader(line)) return true;
  const std::string before = std::string(kColumnsBefore) + ",",
                    after = "," + std::string(kAttractorColumns) + "," + kPaperColumnsAfter;
  if (line.size() < before.size() + after.size() || !line.starts_with(before) || !line.ends_with(after)) return false;
  const std::string_view pair = line.substr(before.size(), line.size() - before.size() - after.size());
  const std::size_t comma = pair.find(',');
  if (comma == std::string_view::npos) return false;
  return ParameterFromString(pair.substr(0, comma)) && ParameterFromString(pair.substr(comma + 1));
}

std::string BruteForceMapCsv(const BruteForceMap& map) {
  std::string out = Header(map.first, map.second) + "\n";
  for (const MapCell& cell : map.cells) {
    for (std::size_t a = 0; a < cell.attractors.size(); ++a) {
      const Attractor& attractor = cell.attractors[a];
      for (std::size_t k = 0; k < attractor.section.size(); ++k) {
        const State& x = attractor.section[k];
        out += fmt::format("{},{},{},{},{},{},{}\n", RowStart(map, cell, a, attractor), attractor.signature, k, x(0),
                           x(1), x(2), x(3));
      }
    }
  }
  return out;
}

std::string BruteForceMapCsv(const ModelBruteForceMap& map) {
  std::string out = Header(map) + "\n";
  for (const ModelMapCell& cell : map.cells) {
    for (std::size_t a = 0; a < cell.attractors.size(); ++a) {
      const ModelAttractor& attractor = cell.attractors[a];
      for (std::size_t k = 0; k < attractor.section.size(); ++k) {
        out += fmt::format("{},{},{},{}\n", RowStart(map, cell, a, attractor), attractor.contact_amplitude, k,
                           fmt::join(attractor.section[k], ","));
      }
    }
  }
  return out;
}

namespace {

using detail::CsvTable;

// Where the fields of a row are; i, j, ni, nj and the two parameters are the first six columns,
// `own` the attractor's column after starts (the paper's signature, a model's amplitude), the state
// from x to the last.
struct MapColumns {
  explicit MapColumns(const CsvTable& t)
      : phase(t.Column("section_phase")), run(t.Column("run")), count(t.Column("attractors")),
        index(t.Column("attractor")), status(t.Column("status")), period(t.Column("period")),
        stops(t.Column("stops_per_period")), sticks(t.Column("sticks_per_period")), starts(t.Column("starts")),
        own(starts + 1), k(t.Column("k")), x(k + 1), components(static_cast<int>(t.header().size()) - x) {}
  static constexpr int i = 0, j = 1, ni = 2, nj = 3, first = 4, second = 5;
  int phase, run, count, index, status, period, stops, sticks, starts, own, k, x, components;
};

std::pair<ParameterId, ParameterId> MapParameters(const CsvTable& table) {
  const std::vector<std::string>& header = table.header();
  std::optional<ParameterId> first, second;
  if (header.size() == 21) {
    first = ParameterFromString(header[4]);
    second = ParameterFromString(header[5]);
  }
  if (!first || !second || fmt::format("{}", fmt::join(header, ",")) != Header(*first, *second)) {
    const BruteForceMap by_default;  // the header of the default axes as the example
    throw table.HeaderError(fmt::format("the header is invalid: valid {}", Header(by_default.first, by_default.second)));
  }
  return {*first, *second};
}

// A model's map as its header names it: the parameters, the contact and the state's columns.
ModelBruteForceMap ModelMapOf(const CsvTable& table) {
  const std::vector<std::string>& header = table.header();
  const std::string line = fmt::format("{}", fmt::join(header, ","));
  const std::string_view amplitude = header.size() > 16 ? std::string_view(header[15]) : std::string_view();
  if (!IsModelMapHeader(line) || header.size() < 18 || header[16] != "k" || !amplitude.starts_with("amplitude:")) {
    throw table.HeaderError(fmt::format("the header is invalid: valid {},omega,F_s,{},amplitude:<coordinate>,k,<state>",
                                        kColumnsBefore, kAttractorColumns));
  }
  ModelBruteForceMap map{.first = header[4], .second = header[5], .contact = std::string(amplitude.substr(10))};
  map.state_columns.assign(header.begin() + 17, header.end());
  // As a model's description names them: (q, q') of n coordinates, the contact on the last; every
  // name once in the header.
  const std::size_t n = map.state_columns.size() / 2;
  std::vector<std::string> names = header;
  std::sort(names.begin(), names.end());
  if (map.state_columns.size() % 2 != 0 || map.contact != map.state_columns[n - 1] ||
      std::adjacent_find(names.begin(), names.end()) != names.end() ||
      std::any_of(names.begin(), names.end(), [](const std::string& name) { return name.empty(); })) {
    throw table.HeaderError(
        "the header is invalid: valid the state's 2n columns after k (n coordinates, the contact's the last, then "
        "their velocities), every column's name once and none empty");
  }
  return map;
}

std::uint64_t ReadRun(const CsvTable& t, int row, int column) {
  const std::string& run = t.Text(row, column);
  std::uint64_t fingerprint = 0;
  const auto [end, error] = std::from_chars(run.data(), run.data() + run.size(), fingerprint, 16);
  if (run.size() != 16 || error != std::errc() || end != run.data() + run.size()) {
    throw t.Error(row, column, "is invalid: valid 16 hexadecimal digits");
  }
  return fingerprint;
}

// The grid's columns (ni, nj, section_phase, run): valid, and in every row as in the first.
template <typename Map>
void ReadGrid(const CsvTable& t, int row, const MapColumns& c, Map* map) {
  const int max_cells = BruteForceMapOptions::kMaxSteps + 1;
  const int ni = t.Integer(row, c.ni, 1, max_cells), nj = t.Integer(row, c.nj, 1, max_cells);
  const double phase = t.Value(row, c.phase, detail::Finite());
  const std::uint64_t fingerprint = ReadRun(t, row, c.run);
  if (row == 0) {
    map->first_count = ni;
    map->second_count = nj;
    map->section_phase = phase;
    map->run = fingerprint;
  }
  if (ni != map->first_count) throw t.Error(row, c.ni, fmt::format("differs from the first row's {}", map->first_count));
  if (nj != map->second_count) throw t.Error(row, c.nj, fmt::format("differs from the first row's {}", map->second_count));
  if (phase != map->section_phase) throw t.Error(row, c.phase, "differs from the first row's");
  if (fingerprint != map->run) throw t.Error(row, c.run, "differs from the first row's");
}

// The valid values of a map's parameters: the paper model's ranges; a model's are its own, checked
// where it is read with its run file.
detail::ValidValues AxisValues(ParameterId id) { return detail::ModelParameter(id); }
detail::ValidValues AxisValues(const std::string&) { return detail::Finite(); }

// The row's cell: a new one after the last (cells by j then i, each once), or the last again.
template <typename Map>
auto& ReadCell(const CsvTable& t, int row, const MapColumns& c, Map* map) {
  const int i = t.Integer(row, c.i, 0, map->first_count - 1), j = t.Integer(row, c.j, 0, map->second_count - 1);
  const double first = t.Value(row, c.first, AxisValues(map->first));
  const double second = t.Value(row, c.second, AxisValues(map->second));
  const bool new_cell = map->cells.empty() || map->cells.back().i != i || map->cells.back().j != j;
  if (new_cell) {
    if (!map->cells.empty() && std::pair{j, i} <= std::pair{map->cells.back().j, map->cells.back().i}) {
      throw t.Error(row, "the cell comes after a later one or twice: valid cells by j then i, each once");
    }
    if (!map->cells.empty() && map->cells.back().attractors.size() != static_cast<std::size_t>(t.Integer(row - 1, c.count))) {
      throw t.Error(row - 1, c.count, "is not the number of attractors the cell lists");
    }
    map->cells.push_back({i, j, first, second, {}});
  }
  // A cell's rows agree on its attractor count, an attractor's rows on all but k and the state
  // (rows of one cell, and of one attractor, are consecutive): else the file is not one a
  // writer wrote, and would be written back otherwise.
  if (!new_cell && t.Text(row, c.count) != t.Text(row - 1, c.count)) throw t.Error(row, c.count, "differs from the cell's first row");
  auto& cell = map->cells.back();
  if (first != cell.first) throw t.Error(row, c.first, "differs from the cell's first row");
  if (second != cell.second) throw t.Error(row, c.second, "differs from the cell's first row");
  return cell;
}

// The attractor's own column: the paper's signature (parsed), a model's contact amplitude.
void ReadOwn(const CsvTable& t, int row, const MapColumns& c, Attractor& a) {
  a.signature = t.Text(row, c.own);
  if (a.signature.empty()) return;
  try {
    Signature::Parse(a.signature);
  } catch (const InvalidInput& e) {
    throw t.Error(row, c.own, fmt::format("is invalid: {}", e.what()));
  }
}
void ReadOwn(const CsvTable& t, int row, const MapColumns& c, ModelAttractor& a) {
  a.contact_amplitude = t.Value(row, c.own, detail::SettledAmplitude());
}

// An attractor's columns, each by its kind.
template <typename Attractor>
Attractor ReadAttractor(const CsvTable& t, int row, const MapColumns& c) {
  Attractor a;
  const std::optional<AttractorStatus> status = AttractorStatusFromString(t.Text(row, c.status));
  if (!status) throw t.Error(row, c.status, "is invalid: valid periodic, not-settled, incomplete");
  a.status = *status;
  const bool periodic = a.status == AttractorStatus::kPeriodic;
  a.period = t.Integer(row, c.period);
  if (periodic ? a.period < 1 : a.period != 0) {
    throw t.Error(row, c.period, periodic ? "is invalid: valid period >= 1" : "is invalid: valid 0 unless periodic");
  }
  a.stops_per_period = t.Value(row, c.stops, detail::NonNegative());
  a.sticks_per_period = t.Value(row, c.sticks, detail::NonNegative());
  a.starts = t.Integer(row, c.starts, 1, std::numeric_limits<int>::max());
  ReadOwn(t, row, c, a);
  return a;
}

// The row's attractor: a new one (numbered from 0) or the last again, unchanged.
template <typename Cell>
auto& ReadRowAttractor(const CsvTable& t, int row, const MapColumns& c, Cell& cell) {
  using Attractor = typename decltype(cell.attractors)::value_type;
  const int index = t.Integer(row, c.index);
  if (!cell.attractors.empty() && index == static_cast<int>(cell.attractors.size()) - 1) {
    for (const int column : {c.status, c.period, c.stops, c.sticks, c.starts, c.own}) {
      if (t.Text(row, column) != t.Text(row - 1, column)) throw t.Error(row, column, "differs from the attractor's first row");
    }
    return cell.attractors.back();
  }
  if (index != static_cast<int>(cell.attractors.size())) {
    throw t.Error(row, c.index, fmt::format("is invalid: valid {} (attractors are numbered from 0)", cell.attractors.size()));
  }
  cell.attractors.push_back(ReadAttractor<Attractor>(t, row, c));
  return cell.attractors.back();
}

// The row's section point, k = 0, 1, ... in order; each component finite.
template <typename Attractor>
void ReadSectionPoint(const CsvTable& t, int row, const MapColumns& c, Attractor& a) {
  const int points = a.status == AttractorStatus::kPeriodic ? a.period : 1;
  const int k = t.Integer(row, c.k);
  if (k != static_cast<int>(a.section.size()) || k >= points) {
    throw t.Error(row, c.k, fmt::format("is invalid: valid {} (k = 0..{} in order)", a.section.size(), points - 1));
  }
  auto x = decltype(a.section)::value_type::Zero(c.components).eval();
  for (int component = 0; component < c.components; ++component) {
    x(component) = t.Value(row, c.x + component, detail::Finite());
  }
  a.section.push_back(x);
}

// Every cell's last attractor count, and every attractor's number of section points.
template <typename Map>
void CheckCounts(const CsvTable& t, const Map& map, const std::string& name, const MapColumns& c) {
  if (!map.cells.empty() && map.cells.back().attractors.size() != static_cast<std::size_t>(t.Integer(t.rows() - 1, c.count))) {
    throw t.Error(t.rows() - 1, c.count, "is not the number of attractors the cell lists");
  }
  for (const auto& cell : map.cells) {
    for (const auto& a : cell.attractors) {
      const std::size_t points = a.status == AttractorStatus::kPeriodic ? a.period : 1;
      if (a.section.size() != points) {
        throw InvalidInput::WithMessage(
            name, fmt::format("{}: cell ({}, {}) lists {} section point(s) of an attractor of period {}: valid {}",
                              name, cell.i, cell.j, a.section.size(), a.period, points));
      }
    }
  }
}

// Every cell of one i has one value of the first parameter, of one j one of the second: a grid.
template <typename Map>
void CheckGridValues(const Map& map, const std::string& name) {
  std::map<int, double> first, second;
  for (const auto& cell : map.cells) {
    for (const auto& [values, index, value, axis] :
         {std::tuple{&first, cell.i, cell.first, "i"}, std::tuple{&second, cell.j, cell.second, "j"}}) {
      const auto [known, added] = values->try_emplace(index, value);
      if (added || known->second == value) continue;
      throw InvalidInput::WithMessage(
          name, fmt::format("{}: cell ({}, {}) has {} = {} at {} = {}, another cell {}: valid one value per {}", name,
                            cell.i, cell.j, axis == std::string_view("i") ? AxisName(map.first) : AxisName(map.second),
                            value, axis, index, known->second, axis));
    }
  }
}

// The rows of `table` into `map` (its names set from the header).
template <typename Map>
Map ReadMapRows(const CsvTable& table, Map map, const std::string& name) {
  const MapColumns columns(table);
  for (int row = 0; row < table.rows(); ++row) {
    ReadGrid(table, row, columns, &map);
    auto& cell = ReadCell(table, row, columns, &map);
    ReadSectionPoint(table, row, columns, ReadRowAttractor(table, row, columns, cell));
  }
  CheckCounts(table, map, name, columns);
  CheckGridValues(map, name);
  return map;
}

}  // namespace

BruteForceMap ReadBruteForceMapCsv(std::string_view text, const std::string& name) {
  const CsvTable table(text, name);
  const auto [first, second] = MapParameters(table);
  return ReadMapRows(table, BruteForceMap{first, second, 0, 0, 0.0, 0, {}}, name);
}

ModelBruteForceMap ReadModelBruteForceMapCsv(std::string_view text, const std::string& name) {
  const CsvTable table(text, name);
  return ReadMapRows(table, ModelMapOf(table), name);
}

void CheckBruteForceMapCsv(std::string_view text, const std::string& name) {
  if (IsModelBruteForceMapCsv(text)) {
    ReadModelBruteForceMapCsv(text, name);
  } else {
    ReadBruteForceMapCsv(text, name);
  }
}

bool IsModelBruteForceMapCsv(std::string_view text) {
  return IsModelMapHeader(text.substr(0, text.find('\n')));
}

namespace {


// The map's parameters and what its rows hold (the same in every shard), as a message says them.
std::string KindOf(const BruteForceMap& map) { return fmt::format("{} and {}", ToString(map.first), ToString(map.second)); }
std::string KindOf(const ModelBruteForceMap& map) {
  return fmt::format("{} and {} (contact {}, state {})", map.first, map.second, map.contact, fmt::join(map.state_columns, ", "));
}

InvalidInput NoMerge(const std::string& what) {
  return InvalidInput::WithMessage("merge", fmt::format("merge: {}: valid the shards of one map, every cell once", what));
}

// The first shard with cells, whose grid every shard with cells shares; all shards of one kind.
template <typename Map>
std::size_t GridShard(const std::vector<Map>& shards, const std::vector<std::string>& names) {
  if (shards.empty()) throw NoMerge("no shard given");
  std::optional<std::size_t> grid;
  for (std::size_t s = 0; s < shards.size(); ++s) {
    const Map& m = shards[s];
    if (KindOf(m) != KindOf(shards[0])) {
      throw NoMerge(fmt::format("'{}' maps {}, '{}' {}", names[s], KindOf(m), names[0], KindOf(shards[0])));
    }
    if (m.cells.empty()) continue;
    if (!grid) {
      grid = s;
      continue;
    }
    const Map& g = shards[*grid];
    if (m.first_count != g.first_count || m.second_count != g.second_count || m.section_phase != g.section_phase) {
      throw NoMerge(fmt::format("'{}' has a grid of {} x {} cells at section phase {}, '{}' {} x {} at {}", names[s],
                                m.first_count, m.second_count, m.section_phase, names[*grid], g.first_count,
                                g.second_count, g.section_phase));
    }
  }
  if (!grid) throw NoMerge("no shard holds a cell");
  return *grid;
}

// Each cell by its (j, i), from the one shard that holds it; each value of i (of j) the same in
// every shard.
template <typename Map>
auto CellsByPosition(const std::vector<Map>& shards, const std::vector<std::string>& names, const Map& grid) {
  std::map<std::pair<int, int>, std::pair<const typename decltype(grid.cells)::value_type*, std::size_t>> cells;
  std::map<int, std::pair<double, std::size_t>> first_values, second_values;
  for (std::size_t s = 0; s < shards.size(); ++s) {
    for (const auto& cell : shards[s].cells) {
      for (const auto& [values, index, value, axis] :
           {std::tuple{&first_values, cell.i, cell.first, "i"}, std::tuple{&second_values, cell.j, cell.second, "j"}}) {
        const auto [v, added] = values->try_emplace(index, value, s);
        if (!added && v->second.first != value) {
          throw NoMerge(fmt::format("'{}' has {} = {} at {} = {}, '{}' {}", names[s], axis, index,
                                    axis == std::string_view("i") ? AxisName(grid.first) : AxisName(grid.second), value,
                                    names[v->second.second], v->second.first));
        }
      }
      const auto [it, inserted] = cells.try_emplace({cell.j, cell.i}, &cell, s);
      if (!inserted) {
        throw NoMerge(fmt::format("cell (i, j) = ({}, {}) is in '{}' and in '{}'", cell.i, cell.j, names[it->second.second], names[s]));
      }
    }
  }
  return cells;
}

template <typename Map>
Map MergeMaps(const std::vector<Map>& shards, const std::vector<std::string>& names) {
  const std::size_t grid_shard = GridShard(shards, names);
  const Map& grid = shards[grid_shard];
  const auto cells = CellsByPosition(shards, names, grid);
  // Last, so that a grid of other values or a cell twice is named as such: the fingerprint holds the axes too.
  for (std::size_t s = 0; s < shards.size(); ++s) {
    const Map& m = shards[s];
    if (!m.cells.empty() && m.run != grid.run) {
      throw NoMerge(fmt::format("'{}' is of run {:016x}, '{}' of run {:016x} (other data, axes, starts or options)", names[s],
                                m.run, names[grid_shard], grid.run));
    }
  }
  Map merged = grid;
  merged.cells.clear();
  for (int j = 0; j < merged.second_count; ++j) {
    for (int i = 0; i < merged.first_count; ++i) {
      const auto it = cells.find({j, i});
      if (it == cells.end()) throw NoMerge(fmt::format("cell (i, j) = ({}, {}) is in no shard", i, j));
      merged.cells.push_back(*it->second.first);
    }
  }
  return merged;
}

}  // namespace

BruteForceMap MergeBruteForceMaps(const std::vector<BruteForceMap>& shards, const std::vector<std::string>& names) {
  return MergeMaps(shards, names);
}

ModelBruteForceMap MergeBruteForceMaps(const std::vector<ModelBruteForceMap>& shards, const std::vector<std::string>& names) {
  return MergeMaps(shards, names);
}

}  // namespace stickslip
