#include "stickslip/io/map_file.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <system_error>
#include <map>
#include <optional>
#include <string_view>
#include <tuple>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "csv_table.hpp"
#include "stickslip/invalid_input.hpp"

namespace stickslip {

namespace {

constexpr const char* kColumnsBefore = "i,j,ni,nj";
constexpr const char* kColumnsAfter =
    "section_phase,run,attractors,attractor,status,period,stops_per_period,sticks_per_period,starts,signature,k,x1,x2,v1,"
    "v2";

std::string Header(ParameterId first, ParameterId second) {
  return fmt::format("{},{},{},{}", kColumnsBefore, ToString(first), ToString(second), kColumnsAfter);
}

}  // namespace

bool IsBruteForceMapCsvHeader(std::string_view line) {
  const std::string before = std::string(kColumnsBefore) + ",", after = "," + std::string(kColumnsAfter);
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
        out += fmt::format("{},{},{},{},{},{},{},{:016x},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", cell.i, cell.j,
                           map.first_count, map.second_count, cell.first, cell.second, map.section_phase, map.run,
                           cell.attractors.size(), a, ToString(attractor.status), attractor.period,
                           attractor.stops_per_period, attractor.sticks_per_period, attractor.starts,
                           attractor.signature, k, x(0), x(1), x(2), x(3));
      }
    }
  }
  return out;
}

BruteForceMap ReadBruteForceMapCsv(std::string_view text, const std::string& name) {
  const detail::CsvTable table(text, name);
  const std::vector<std::string>& header = table.header();
  std::optional<ParameterId> first, second;
  if (header.size() == 21) {
    first = ParameterFromString(header[4]);
    second = ParameterFromString(header[5]);
  }
  if (!first || !second || fmt::format("{}", fmt::join(header, ",")) != Header(*first, *second)) {
    throw table.HeaderError(fmt::format("the header is invalid: valid {}", Header(ParameterId::kOmega, ParameterId::kStaticFriction)));
  }
  BruteForceMap map{*first, *second, 0, 0, 0.0, 0, {}};
  const auto column = [&](const char* c) { return table.Column(c); };
  const int ci = 0, cj = 1, cni = 2, cnj = 3, cfirst = 4, csecond = 5;
  const int cphase = column("section_phase"), crun = column("run"), ccount = column("attractors"), cindex = column("attractor"),
            cstatus = column("status"), cperiod = column("period"), cstops = column("stops_per_period"),
            csticks = column("sticks_per_period"), cstarts = column("starts"), csignature = column("signature"),
            ck = column("k"), cx = column("x1");
  for (int row = 0; row < table.rows(); ++row) {
    const int i = table.Integer(row, ci), j = table.Integer(row, cj);
    const int ni = table.Integer(row, cni), nj = table.Integer(row, cnj);
    const double phase = table.FiniteNumber(row, cphase);
    const std::string& run = table.Text(row, crun);
    std::uint64_t fingerprint = 0;
    const auto [end, error] = std::from_chars(run.data(), run.data() + run.size(), fingerprint, 16);
    if (run.size() != 16 || error != std::errc() || end != run.data() + run.size()) {
      throw table.Error(row, crun, "is invalid: valid 16 hexadecimal digits");
    }
    if (row == 0) {
      map.first_count = ni;
      map.second_count = nj;
      map.section_phase = phase;
      map.run = fingerprint;
    }
    for (const int c : {cni, cnj}) {
      if (!(table.Integer(row, c) >= 1 && table.Integer(row, c) <= BruteForceMapOptions::kMaxSteps + 1)) {
        throw table.Error(row, c, fmt::format("is invalid: valid 1 to {} cells", BruteForceMapOptions::kMaxSteps + 1));
      }
    }
    if (ni != map.first_count) throw table.Error(row, cni, fmt::format("differs from the first row's {}", map.first_count));
    if (nj != map.second_count) throw table.Error(row, cnj, fmt::format("differs from the first row's {}", map.second_count));
    if (phase != map.section_phase) throw table.Error(row, cphase, "differs from the first row's");
    if (fingerprint != map.run) throw table.Error(row, crun, "differs from the first row's");
    if (!(i >= 0 && i < ni)) throw table.Error(row, ci, fmt::format("is invalid: valid 0 <= i < ni = {}", ni));
    if (!(j >= 0 && j < nj)) throw table.Error(row, cj, fmt::format("is invalid: valid 0 <= j < nj = {}", nj));
    const bool new_cell = map.cells.empty() || map.cells.back().i != i || map.cells.back().j != j;
    if (new_cell) {
      if (!map.cells.empty() && std::pair{j, i} <= std::pair{map.cells.back().j, map.cells.back().i}) {
        throw table.Error(row, "the cell comes after a later one or twice: valid cells by j then i, each once");
      }
      if (!map.cells.empty() &&
          map.cells.back().attractors.size() != static_cast<std::size_t>(table.Integer(row - 1, ccount))) {
        throw table.Error(row - 1, ccount, "is not the number of attractors the cell lists");
      }
      map.cells.push_back({i, j, table.FiniteNumber(row, cfirst), table.FiniteNumber(row, csecond), {}});
    }
    // A cell's rows agree on its attractor count, an attractor's rows on all but k and the state
    // (rows of one cell, and of one attractor, are consecutive): else the file is not one a
    // writer wrote, and would be written back otherwise.
    if (!new_cell && table.Text(row, ccount) != table.Text(row - 1, ccount)) {
      throw table.Error(row, ccount, "differs from the cell's first row");
    }
    MapCell& cell = map.cells.back();
    if (table.FiniteNumber(row, cfirst) != cell.first) throw table.Error(row, cfirst, "differs from the cell's first row");
    if (table.FiniteNumber(row, csecond) != cell.second) throw table.Error(row, csecond, "differs from the cell's first row");
    const int index = table.Integer(row, cindex);
    const int k = table.Integer(row, ck);
    const bool new_attractor = cell.attractors.empty() || index != static_cast<int>(cell.attractors.size()) - 1;
    if (new_attractor) {
      if (index != static_cast<int>(cell.attractors.size())) {
        throw table.Error(row, cindex, fmt::format("is invalid: valid {} (attractors are numbered from 0)", cell.attractors.size()));
      }
      Attractor a;
      if (!FromString(table.Text(row, cstatus), &a.status)) {
        throw table.Error(row, cstatus, "is invalid: valid periodic, not-settled, incomplete");
      }
      a.period = table.Integer(row, cperiod);
      a.stops_per_period = table.FiniteNumber(row, cstops);
      a.sticks_per_period = table.FiniteNumber(row, csticks);
      a.starts = table.Integer(row, cstarts);
      a.signature = table.Text(row, csignature);
      const bool periodic = a.status == AttractorStatus::kPeriodic;
      if (periodic ? a.period < 1 : a.period != 0) {
        throw table.Error(row, cperiod, periodic ? "is invalid: valid period >= 1" : "is invalid: valid 0 unless periodic");
      }
      if (a.starts < 1) throw table.Error(row, cstarts, "is invalid: valid starts >= 1");
      cell.attractors.push_back(std::move(a));
    }
    if (!new_attractor) {
      for (const int c : {cstatus, cperiod, cstops, csticks, cstarts, csignature}) {
        if (table.Text(row, c) != table.Text(row - 1, c)) throw table.Error(row, c, "differs from the attractor's first row");
      }
    }
    Attractor& a = cell.attractors.back();
    const int points = a.status == AttractorStatus::kPeriodic ? a.period : 1;
    if (k != static_cast<int>(a.section.size()) || k >= points) {
      throw table.Error(row, ck, fmt::format("is invalid: valid {} (k = 0..{} in order)", a.section.size(), points - 1));
    }
    State x;
    for (int c = 0; c < 4; ++c) x(c) = table.Number(row, cx + c);
    a.section.push_back(x);
  }
  if (!map.cells.empty()) {
    const int last = table.rows() - 1;
    if (map.cells.back().attractors.size() != static_cast<std::size_t>(table.Integer(last, ccount))) {
      throw table.Error(last, ccount, "is not the number of attractors the cell lists");
    }
  }
  for (const MapCell& cell : map.cells) {
    for (const Attractor& a : cell.attractors) {
      const std::size_t points = a.status == AttractorStatus::kPeriodic ? a.period : 1;
      if (a.section.size() != points) {
        throw InvalidInput::WithMessage(
            name, fmt::format("{}: cell ({}, {}) lists {} section point(s) of an attractor of period {}: valid {}",
                              name, cell.i, cell.j, a.section.size(), a.period, points));
      }
    }
  }
  return map;
}

BruteForceMap MergeBruteForceMaps(const std::vector<BruteForceMap>& shards, const std::vector<std::string>& names) {
  auto refuse = [](const std::string& what) {
    return InvalidInput::WithMessage("merge", fmt::format("merge: {}: valid the shards of one map, every cell once", what));
  };
  if (shards.empty()) throw refuse("no shard given");
  const BruteForceMap* grid = nullptr;  // the first shard with cells
  std::size_t grid_shard = 0;
  for (std::size_t s = 0; s < shards.size(); ++s) {
    const BruteForceMap& m = shards[s];
    if (m.first != shards[0].first || m.second != shards[0].second) {
      throw refuse(fmt::format("'{}' maps {} and {}, '{}' {} and {}", names[s], ToString(m.first), ToString(m.second),
                               names[0], ToString(shards[0].first), ToString(shards[0].second)));
    }
    if (m.cells.empty()) continue;
    if (!grid) {
      grid = &m;
      grid_shard = s;
      continue;
    }
    if (m.first_count != grid->first_count || m.second_count != grid->second_count || m.section_phase != grid->section_phase) {
      throw refuse(fmt::format("'{}' has a grid of {} x {} cells at section phase {}, '{}' {} x {} at {}", names[s],
                               m.first_count, m.second_count, m.section_phase, names[grid_shard], grid->first_count,
                               grid->second_count, grid->section_phase));
    }
  }
  if (!grid) throw refuse("no shard holds a cell");
  // Each cell from one shard; each value of i (of j) the same in every shard.
  std::map<std::pair<int, int>, std::pair<const MapCell*, std::size_t>> cells;
  std::map<int, std::pair<double, std::size_t>> first_values, second_values;
  for (std::size_t s = 0; s < shards.size(); ++s) {
    for (const MapCell& cell : shards[s].cells) {
      for (const auto& [values, index, value, axis] :
           {std::tuple{&first_values, cell.i, cell.first, "i"}, std::tuple{&second_values, cell.j, cell.second, "j"}}) {
        const auto [v, added] = values->try_emplace(index, value, s);
        if (!added && v->second.first != value) {
          throw refuse(fmt::format("'{}' has {} = {} at {} = {}, '{}' {}", names[s], axis, index,
                                   axis == std::string_view("i") ? ToString(grid->first) : ToString(grid->second), value,
                                   names[v->second.second], v->second.first));
        }
      }
      const auto [it, inserted] = cells.try_emplace({cell.j, cell.i}, &cell, s);
      if (!inserted) {
        throw refuse(fmt::format("cell (i, j) = ({}, {}) is in '{}' and in '{}'", cell.i, cell.j, names[it->second.second], names[s]));
      }
    }
  }
  // Last, so that a grid of other values or a cell twice is named as such: the fingerprint holds the axes too.
  for (std::size_t s = 0; s < shards.size(); ++s) {
    const BruteForceMap& m = shards[s];
    if (!m.cells.empty() && m.run != grid->run) {
      throw refuse(fmt::format("'{}' is of run {:016x}, '{}' of run {:016x} (other data, axes, starts or options)", names[s],
                               m.run, names[grid_shard], grid->run));
    }
  }
  BruteForceMap merged{grid->first,         grid->second, grid->first_count, grid->second_count,
                       grid->section_phase, grid->run,    {}};
  for (int j = 0; j < merged.second_count; ++j) {
    for (int i = 0; i < merged.first_count; ++i) {
      const auto it = cells.find({j, i});
      if (it == cells.end()) throw refuse(fmt::format("cell (i, j) = ({}, {}) is in no shard", i, j));
      merged.cells.push_back(*it->second.first);
    }
  }
  return merged;
}

}  // namespace stickslip
