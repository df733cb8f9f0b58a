#include "stickslip/analysis/brute_force_map.hpp"

#include <cmath>
#include <mutex>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "stickslip/analysis/motion_type.hpp"
#include "stickslip/analysis/settled_motion.hpp"
#include "stickslip/analysis/sweep.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/model/transient.hpp"
#include "stickslip/numerics/fingerprint.hpp"
#include "stickslip/numerics/parallel_for.hpp"

namespace stickslip {

double GridValueAt(double from, double to, int steps, int index) {
  if (index == steps) return to;
  return steps == 0 ? from : from + (static_cast<double>(index) / steps) * (to - from);
}

double MapAxis::ValueAt(int index) const { return GridValueAt(from, to, steps, index); }

const char* ToString(AttractorStatus status) {
  switch (status) {
    case AttractorStatus::kPeriodic: return "periodic";
    case AttractorStatus::kNotSettled: return "not-settled";
    case AttractorStatus::kIncomplete: break;
  }
  return "incomplete";
}

std::optional<AttractorStatus> AttractorStatusFromString(std::string_view text) {
  for (AttractorStatus s : {AttractorStatus::kPeriodic, AttractorStatus::kNotSettled, AttractorStatus::kIncomplete}) {
    if (text == ToString(s)) return s;
  }
  return std::nullopt;
}

bool RowInShard(int j, int shard, int shards) { return j % shards == shard - 1; }

namespace {

void CheckWhole(const char* field, long long value, long long low, long long high) {
  if (value < low || value > high) {
    throw InvalidInput(field, std::to_string(value), fmt::format("{} <= {} <= {}", low, field, high));
  }
}

Parameters CellParameters(const Parameters& base, const BruteForceMapOptions& o, int i, int j) {
  Parameters p = base;
  p[o.first.parameter] = o.first.ValueAt(i);
  p[o.second.parameter] = o.second.ValueAt(j);
  return p;
}

// One run of a cell: what an attractor needs of it.
struct Run {
  bool done = false;
  AttractorStatus status = AttractorStatus::kNotSettled;
  int period = 0;
  double stops_per_period = 0.0;
  double sticks_per_period = 0.0;
  std::string signature;
  std::vector<State> section;  // all recorded section points (periodic), else the last state
  State last = State::Zero();
  double settling = 0.0;  // SettledMotion::settling: how far the section may still be from its orbit
};

Run SimulateRun(const Parameters& p, const State& start, double phi, const BruteForceMapOptions& o) {
  const SettleOptions settle{o.transient_periods, o.recorded_periods, o.periodicity_tolerance,
                             o.max_events_per_simulation};
  SettledMotion motion = SimulateSettled(p, start, phi, settle);
  Run run;
  run.done = true;
  run.last = motion.last;
  if (!motion.Completed()) {
    run.status = AttractorStatus::kIncomplete;
    run.section = {motion.last};
    return run;
  }
  run.stops_per_period = motion.stops_per_period;
  run.sticks_per_period = motion.sticks_per_period;
  if (motion.period == 0) {
    run.section = {motion.last};
    return run;
  }
  run.status = AttractorStatus::kPeriodic;
  run.period = motion.period;
  run.settling = motion.settling;
  // Antisymmetry over one period of k T (the record holds recorded_periods >= 2 k periods).
  MotionTypeOptions reading;
  reading.periodicity_tolerance = o.periodicity_tolerance;
  reading.confirmations = 1;
  const MotionType type = ReadMotionType(motion.record, motion.period, 2.0 * std::numbers::pi / p.omega, reading);
  if (type.signature) run.signature = type.signature->ToString();
  motion.section.resize(motion.period);
  run.section = std::move(motion.section);
  return run;
}

// The same periodic section orbit: the same period and, under some cyclic shift, every point
// within the tolerance.
bool SameOrbit(const std::vector<State>& a, const std::vector<State>& b, double tolerance) {
  const int n = static_cast<int>(a.size());
  if (n != static_cast<int>(b.size())) return false;
  for (int shift = 0; shift < n; ++shift) {
    bool same = true;
    for (int k = 0; k < n && same; ++k) {
      same = (a[k] - b[(k + shift) % n]).lpNorm<Eigen::Infinity>() <= tolerance;
    }
    if (same) return true;
  }
  return false;
}

// The cell's runs, in start order, as attractors. Two runs are one attractor when their sections
// agree to the tolerance, widened by the distance each may still be from the orbit it contracts
// onto (0 unless its period was reduced: two runs that approach one slowly converging orbit from
// different sides are not yet within the tolerance of each other).
std::vector<Attractor> Deduplicate(std::vector<Run>& runs, double tolerance) {
  std::vector<Attractor> attractors;
  std::vector<double> settling;  // of each attractor's first run
  for (Run& run : runs) {
    if (!run.done) continue;
    Attractor* same = nullptr;
    for (std::size_t a = 0; a < attractors.size() && same == nullptr; ++a) {
      const double within = tolerance + settling[a] + run.settling;
      const bool match = attractors[a].status == run.status &&
                         (run.status != AttractorStatus::kPeriodic || SameOrbit(attractors[a].section, run.section, within));
      if (match) same = &attractors[a];
    }
    if (same) {
      ++same->starts;
      continue;
    }
    settling.push_back(run.settling);
    attractors.push_back({run.status, run.period, run.stops_per_period, run.sticks_per_period,
                          std::move(run.signature), 1, std::move(run.section)});
  }
  return attractors;
}

}  // namespace

void BruteForceMapOptions::Validate(const Parameters& base) const {
  for (const auto& [name, axis] : {std::pair{"first", &first}, std::pair{"second", &second}}) {
    CheckWhole(fmt::format("{}.steps", name).c_str(), axis->steps, 0, kMaxSteps);
  }
  if (first.parameter == second.parameter) {
    throw InvalidInput("second.parameter", fmt::format("'{}'", ToString(second.parameter)),
                       fmt::format("a parameter other than first.parameter '{}'", ToString(first.parameter)));
  }
  CheckWhole("transient_periods", transient_periods, 0, kMaxTransientPeriods);
  CheckWhole("recorded_periods", recorded_periods, 2, kMaxRecordedPeriods);
  CheckWhole("scattered_starts", scattered_starts, 0, kMaxScatteredStarts);
  if (!(scatter >= 0.0 && scatter <= 1e6)) throw InvalidInput("scatter", scatter, "0 <= scatter <= 1e6");
  const std::vector<std::string>& state_names = Pascal2014{}.Description().initial_state;
  for (int i = 0; i < centre.size(); ++i) {
    if (auto invalid = ValidateStateValue(state_names[i], centre(i))) throw *invalid;
  }
  if (!(periodicity_tolerance >= kMinTolerance && periodicity_tolerance <= kMaxTolerance)) {
    throw InvalidInput("periodicity_tolerance", periodicity_tolerance,
                       fmt::format("{} <= periodicity_tolerance <= {}", kMinTolerance, kMaxTolerance));
  }
  CheckWhole("max_events_per_simulation", max_events_per_simulation, 1, 100000000);
  CheckWhole("shards", shards, 1, kMaxShards);
  CheckWhole("shard", shard, 1, shards);
  CheckWhole("threads", threads, 0, 1024);
  // The rows j = shard - 1, shard - 1 + shards, ... below second.Count().
  const long long rows_in_shard = second.Count() >= shard ? (second.Count() - shard) / shards + 1 : 0;
  const long long runs = rows_in_shard * first.Count() * (2 + scattered_starts);
  if (runs > kMaxRuns) {
    throw InvalidInput("grid",
                       fmt::format("{} runs ({} rows of {} cells, {} runs a cell)", runs, rows_in_shard, first.Count(),
                                   2 + scattered_starts),
                       fmt::format("at most {} runs in one shard (fewer cells or starts, or more shards)", kMaxRuns));
  }
  // Every cell, not only the corners: u_r >= u_s and the natural frequencies depend on both.
  for (int j = 0; j < second.Count(); ++j) {
    for (int i = 0; i < first.Count(); ++i) {
      if (const auto invalid = stickslip::Validate(CellParameters(base, *this, i, j))) {
        throw InvalidInput::WithMessage(
            "grid", fmt::format("grid cell (i, j) = ({}, {}) at {} = {}, {} = {} is invalid: {}", i, j,
                                ToString(first.parameter), first.ValueAt(i), ToString(second.parameter),
                                second.ValueAt(j), invalid->what()));
      }
    }
  }
}

std::uint64_t MapRunFingerprint(const Parameters& base, double phi_section, const BruteForceMapOptions& o) {
  Fingerprint hash;
  const auto add = [&hash](std::uint64_t value) { hash.Add(value); };
  const auto add_number = [&hash](double value) { hash.AddNumber(value); };
  for (const ParameterId id : kAllParameters) add_number(base[id]);
  add_number(phi_section);
  for (const MapAxis* axis : {&o.first, &o.second}) {
    add(static_cast<std::uint64_t>(axis->parameter));
    add_number(axis->from);
    add_number(axis->to);
    add(static_cast<std::uint64_t>(axis->steps));
  }
  for (const long long count : {o.transient_periods, o.recorded_periods, o.scattered_starts, o.max_events_per_simulation}) {
    add(static_cast<std::uint64_t>(count));
  }
  for (int k = 0; k < 4; ++k) add_number(o.centre(k));
  add_number(o.scatter);
  add(o.seed);
  add_number(o.periodicity_tolerance);
  return hash.Value();
}

BruteForceMap ComputeBruteForceMap(const Parameters& base, double phi_section, const BruteForceMapOptions& o) {
  o.Validate(base);
  if (auto invalid = ValidateStateValue("phi", phi_section)) throw *invalid;
  BruteForceMap map{o.first.parameter, o.second.parameter, o.first.Count(),   o.second.Count(),
                    phi_section,       MapRunFingerprint(base, phi_section, o), {}};
  std::vector<int> rows;
  for (int j = 0; j < o.second.Count(); ++j) {
    if (RowInShard(j, o.shard, o.shards)) rows.push_back(j);
  }
  const int n = o.first.Count();
  // Starts: 0 rest, 1 the neighbour, 2.. the centre and the states scattered around it.
  const std::vector<State> scattered = ScatteredStarts(o.centre, o.scatter, o.scattered_starts, o.seed);
  const int per_cell = 2 + o.scattered_starts;
  // runs[r][i][start]: each work item fills its own slots.
  std::vector<std::vector<std::vector<Run>>> runs(rows.size(), std::vector<std::vector<Run>>(n, std::vector<Run>(per_cell)));

  // Progress: a cell is finished when all its runs are (cell 0's neighbour run is its rest run).
  std::mutex progress_mutex;
  std::vector<std::vector<int>> remaining(rows.size(), std::vector<int>(n, per_cell));
  for (auto& row : remaining) row[0] = per_cell - 1;
  long cells_done = 0;
  const double total_cells = static_cast<double>(rows.size()) * n;
  auto run_done = [&](int r, int i) {
    if (!o.progress) return;
    std::lock_guard<std::mutex> lock(progress_mutex);
    if (--remaining[r][i] == 0) o.progress({static_cast<double>(++cells_done), total_cells, "cells"});
  };

  // Work items: first the rows' neighbour chains (the longest items), then every other run.
  const int rows_count = static_cast<int>(rows.size());
  const int independent_per_row = (n - 1) + n * o.scattered_starts;  // rest of cells i >= 1, scattered
  const int items = rows_count + rows_count * independent_per_row;
  ParallelFor(items, o.threads, [&](int item) {
    if (item < rows_count) {
      const int r = item;
      const int j = rows[r];
      runs[r][0][0] = SimulateRun(CellParameters(base, o, 0, j), State::Zero(), phi_section, o);
      run_done(r, 0);
      State x = runs[r][0][0].last;
      for (int i = 1; i < n; ++i) {
        runs[r][i][1] = SimulateRun(CellParameters(base, o, i, j), x, phi_section, o);
        x = runs[r][i][1].last;
        run_done(r, i);
      }
      return;
    }
    const int index = item - rows_count;
    const int r = index / independent_per_row;
    const int within = index % independent_per_row;
    const int j = rows[r];
    if (within < n - 1) {
      const int i = within + 1;
      runs[r][i][0] = SimulateRun(CellParameters(base, o, i, j), State::Zero(), phi_section, o);
      run_done(r, i);
      return;
    }
    const int i = (within - (n - 1)) / o.scattered_starts;
    const int s = (within - (n - 1)) % o.scattered_starts;
    runs[r][i][2 + s] = SimulateRun(CellParameters(base, o, i, j), scattered[s], phi_section, o);
    run_done(r, i);
  });

  for (int r = 0; r < rows_count; ++r) {
    const int j = rows[r];
    for (int i = 0; i < n; ++i) {
      map.cells.push_back({i, j, o.first.ValueAt(i), o.second.ValueAt(j), Deduplicate(runs[r][i], o.periodicity_tolerance)});
    }
  }
  return map;
}

}  // namespace stickslip
