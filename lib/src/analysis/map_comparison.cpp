#include "stickslip/analysis/map_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {

namespace {

// Distance of p from the segment a-b (plane coordinates).
double SegmentDistance(double px, double py, double ax, double ay, double bx, double by) {
  const double dx = bx - ax, dy = by - ay;
  const double length2 = dx * dx + dy * dy;
  const double t = length2 > 0.0 ? std::clamp(((px - ax) * dx + (py - ay) * dy) / length2, 0.0, 1.0) : 0.0;
  return std::hypot(px - ax - t * dx, py - ay - t * dy);
}

double Step(const BruteForceMap& brute, bool first, const MapRectangle& r) {
  const int count = first ? brute.first_count : brute.second_count;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const MapCell& c : brute.cells) {
    lo = std::min(lo, first ? c.first : c.second);
    hi = std::max(hi, first ? c.first : c.second);
  }
  if (count > 1 && hi > lo) return (hi - lo) / (count - 1);
  return first ? r.first_max - r.first_min : r.second_max - r.second_min;
}

}  // namespace

void MapComparisonOptions::Validate() const {
  if (!(clearance >= 0.0 && clearance <= 1e3)) throw InvalidInput("clearance", clearance, "0 <= clearance <= 1e3");
}

int MapComparison::Explained() const {
  return static_cast<int>(std::count_if(disagreements.begin(), disagreements.end(),
                                        [](const MapCellComparison& d) { return d.explained; }));
}

std::string CanonicalOrbitType(const std::string& signature) {
  const std::size_t slash = signature.find(" /");
  const std::string head = signature.substr(0, slash);
  const std::string tail = slash == std::string::npos ? "" : signature.substr(slash);
  std::vector<std::string> tokens;
  std::istringstream in(head);
  for (std::string t; in >> t;) tokens.push_back(t);
  std::vector<std::string> best = tokens;
  for (std::size_t k = 1; k < tokens.size(); ++k) {
    std::vector<std::string> rotated(tokens.begin() + k, tokens.end());
    rotated.insert(rotated.end(), tokens.begin(), tokens.begin() + k);
    best = std::min(best, rotated);
  }
  return fmt::format("{}{}", fmt::join(best, " "), tail);
}

void CheckComparable(const BruteForceMap& brute, const MapRectangle& r) {
  const std::string over = fmt::format("({}, {})", ToString(brute.first), ToString(brute.second));
  if (over != fmt::format("({}, {})", r.first, r.second)) {
    throw InvalidInput("brute force", over, fmt::format("a map over ({}, {})", r.first, r.second));
  }
  const std::size_t whole = static_cast<std::size_t>(brute.first_count) * static_cast<std::size_t>(brute.second_count);
  if (brute.cells.size() != whole) {
    throw InvalidInput("brute force", fmt::format("{} cells of {} x {}", brute.cells.size(), brute.first_count, brute.second_count),
                       "a whole map, every cell of its grid (shards merged by stickslip map-sweep --merge)");
  }
  const bool inside = std::any_of(brute.cells.begin(), brute.cells.end(), [&](const MapCell& c) {
    return c.first >= r.first_min && c.first <= r.first_max && c.second >= r.second_min && c.second <= r.second_max;
  });
  if (!inside) {
    throw InvalidInput("brute force", fmt::format("{} cells", brute.cells.size()),
                       fmt::format("a map with cells in the rectangle {} in [{}, {}], {} in [{}, {}]", r.first, r.first_min,
                                   r.first_max, r.second, r.second_min, r.second_max));
  }
}

namespace {

// The distance, in grid steps (h1, h2), from a cell to the nearest point of the map's curves.
double NearestCurve(const MapCell& cell, const OrbitTypeMap& map, double h1, double h2) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const MapCurve& c : map.curves) {
    for (std::size_t k = 0; k < c.first.size(); ++k) {
      const std::size_t next = std::min(k + 1, c.first.size() - 1);
      nearest = std::min(nearest, SegmentDistance(cell.first / h1, cell.second / h2, c.first[k] / h1, c.second[k] / h2,
                                                  c.first[next] / h1, c.second[next] / h2));
    }
  }
  return nearest;
}

// A cell against its region: the period-1 orbit types the brute force found there, the others it
// found (listed in words), and the region's stable types.
MapCellComparison CellAgainstRegion(const MapCell& cell, const MapRegion& region) {
  MapCellComparison cmp;
  cmp.i = cell.i;
  cmp.j = cell.j;
  cmp.first = cell.first;
  cmp.second = cell.second;
  cmp.region = region.id;
  std::set<std::string> found, expected;
  for (const Attractor& a : cell.attractors) {
    if (a.status == AttractorStatus::kPeriodic && a.signature.empty()) {
      cmp.others.push_back(fmt::format("period {} without an orbit type", a.period));
    } else if (a.status == AttractorStatus::kPeriodic && a.period == 1) {
      found.insert(CanonicalOrbitType(a.signature));
    } else if (a.status == AttractorStatus::kPeriodic) {
      cmp.others.push_back(fmt::format("period {} ({})", a.period, a.signature));
    } else {
      cmp.others.emplace_back(ToString(a.status));
    }
  }
  for (const std::string& t : region.StableTypes()) expected.insert(CanonicalOrbitType(t));
  cmp.found.assign(found.begin(), found.end());
  cmp.expected.assign(expected.begin(), expected.end());
  return cmp;
}

// Where the trace's own stable types at the cell are the brute force's, the region is not uniform:
// a boundary the map lacks. Sets cmp.at_cell; true when that explains the disagreement.
bool NotUniformThere(MapCellComparison& cmp, const MapTrace& trace, const OrbitTypeMap& map) {
  std::set<std::string> here;
  for (const MapOrbit& o : OrbitsAt(trace, map.rectangle, cmp.first, cmp.second, map.options).orbits) {
    if (o.admissible && o.stable) here.insert(CanonicalOrbitType(o.signature));
  }
  cmp.at_cell.assign(here.begin(), here.end());
  if (here != std::set<std::string>(cmp.found.begin(), cmp.found.end())) return false;
  cmp.explanation = fmt::format("region not uniform: at the cell itself the trace's stable types are the brute "
                                "force's ({}): a boundary the map lacks",
                                here.empty() ? "none" : fmt::format("{}", fmt::join(here, "; ")));
  cmp.explained = true;
  return true;
}

// Why the types found and expected differ, in words, and whether anything is left unexplained.
void ExplainDisagreement(MapCellComparison& cmp, const MapRegion& region, const std::set<std::string>& on_trace) {
  const std::set<std::string> found(cmp.found.begin(), cmp.found.end()), expected(cmp.expected.begin(), cmp.expected.end());
  std::vector<std::string> reasons;
  bool unexplained = false;
  // The other motions explain a stable orbit of the map not found (the starts ended on them).
  const bool missed = std::any_of(expected.begin(), expected.end(), [&](const std::string& t) { return !found.count(t); });
  for (const std::string& other : missed ? cmp.others : std::vector<std::string>{}) {
    if (other.ends_with("without an orbit type")) {
      reasons.push_back(fmt::format("{}: no stop or stick exit in a period (a permanent stick), no orbit of a trace", other));
    } else if (other.starts_with("period")) {
      reasons.push_back(fmt::format("{} motion: the map holds period-1 orbits", other));
    } else {
      reasons.push_back(fmt::format("{}: a run did not settle", other));
    }
  }
  for (const std::string& t : found) {
    if (expected.count(t)) continue;
    if (!on_trace.count(t)) {
      reasons.push_back(fmt::format("'{}' not on the trace", t));
    } else {
      reasons.push_back(fmt::format("'{}' found, the map has it unstable, inadmissible or absent here: unexplained", t));
      unexplained = true;
    }
  }
  for (const std::string& t : expected) {
    if (found.count(t)) continue;
    reasons.push_back(fmt::format("'{}' of the map not found by the brute force's starts", t));
    if (cmp.others.empty()) unexplained = true;  // every start settled on the types found
  }
  if (!region.failures.empty()) {
    reasons.push_back(fmt::format("the region's content is incomplete: {} continuation(s) of the trace's orbits did "
                                  "not reach its interior point", region.failures.size()));
  }
  cmp.explanation = fmt::format("{}", fmt::join(reasons, "; "));
  cmp.explained = !unexplained;
}

}  // namespace

MapComparison CompareWithBruteForce(const OrbitTypeMap& map, const MapTrace* trace, const std::vector<std::string>& trace_types,
                                    const BruteForceMap& brute, const MapComparisonOptions& options) {
  options.Validate();
  CheckComparable(brute, map.rectangle);
  std::set<std::string> on_trace;
  for (const std::string& t : trace_types) on_trace.insert(CanonicalOrbitType(t));
  const double h1 = Step(brute, true, map.rectangle), h2 = Step(brute, false, map.rectangle);
  MapComparison result;
  result.cells = static_cast<int>(brute.cells.size());
  for (const MapCell& cell : brute.cells) {
    const int index = map.RegionAt(cell.first, cell.second);
    if (!(NearestCurve(cell, map, h1, h2) > options.clearance) || index < 0) continue;
    const MapRegion& region = map.regions[index];
    MapCellComparison cmp = CellAgainstRegion(cell, region);
    ++result.compared;
    if (cmp.found == cmp.expected) {
      ++result.agreeing;
      result.agreeing_stable += !cmp.found.empty();
      continue;
    }
    if (!(trace && NotUniformThere(cmp, *trace, map))) ExplainDisagreement(cmp, region, on_trace);
    result.disagreements.push_back(std::move(cmp));
  }
  return result;
}

}  // namespace stickslip
