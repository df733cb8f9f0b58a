#include "stickslip/branches/orbit_type_map.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <optional>
#include <set>

#include <fmt/format.h>

#include "stickslip/branches/boundary_curve.hpp"
#include "stickslip/branches/type_switch.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/verification.hpp"

namespace stickslip {

namespace {

// The value of the parameter named `name` (one the model varies, MapRectangle::Validate).
template <OscillatorModel Model>
double ValueOf(const Model& model, const OrbitOfModel<Model>& orbit, const std::string& name) {
  if constexpr (std::is_same_v<Model, Pascal2014>) {
    return orbit.parameters[*ParameterFromString(name)];
  } else {
    return Model::ParameterAt(orbit.parameters, *model.Description().ParameterIndex(name));
  }
}

// How far two orbits are apart (OrbitDistance): the paper's scaled variables as they are, a
// [model]'s start state relative to the orbit's size and its period relative (its numbers are in
// its units: a micrometre apart may be the whole orbit), its phase in radians.
template <OscillatorModel Model>
double Distance(const Model& model, const OrbitOfModel<Model>& a, const OrbitOfModel<Model>& b) {
  if constexpr (std::is_same_v<Model, Pascal2014>) {
    return OrbitDistance(a, b);
  } else {
    const double period = PeriodOf(model, a);
    return std::max({(a.start - b.start).template lpNorm<Eigen::Infinity>() / OrbitSize(model, a), std::abs(a.phi - b.phi),
                     std::abs(PeriodOf(model, b) - period) / period});
  }
}

// A column's value at a point, by name; NaN where the branch has no such column.
template <OscillatorModel Model>
double Column(const BasicOrbitBranch<Model>& branch, std::size_t point, std::string_view name) {
  for (const PointColumn& c : branch.columns) {
    if (c.name != name) continue;
    const BranchPoint& p = branch.branch.points[point];
    return c.monitored ? p.tests(c.index) : p.recorded(c.index);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

// Every margin positive (or undefined) but the ones in `defining`.
template <OscillatorModel Model>
bool AdmissibleApartFrom(const BasicOrbitBranch<Model>& branch, std::size_t point, const std::vector<std::string>& defining) {
  for (const PointColumn& c : branch.columns) {
    if (!c.name.starts_with(orbit_columns::kMarginPrefix)) continue;
    if (std::find(defining.begin(), defining.end(), c.name) != defining.end()) continue;
    const double v = Column(branch, point, c.name);
    if (v < 0.0) return false;
  }
  return true;
}

// The position of `name` among the continued unknowns of `setup` (its free variables, in order).
template <OscillatorModel Model>
int UnknownPosition(const BasicOrbitContinuationSetup<Model>& setup, const std::string& name) {
  const OrbitVariableSet variables = VariableSetOf(setup.model, setup.start.signature);
  const std::vector<int> free = FreeIndices(variables, setup.unknowns);
  const int index = *variables.layout.IndexOf(name);
  return static_cast<int>(std::find(free.begin(), free.end(), index) - free.begin());
}

// A continuation from `orbit` in `parameter` with the trace's options.
template <OscillatorModel Model>
BasicOrbitContinuationSetup<Model> SetupAt(const BasicMapTrace<Model>& trace, const OrbitOfModel<Model>& orbit,
                                           const UnknownChoice& unknowns, const std::string& parameter) {
  return BasicOrbitContinuationSetup<Model>{orbit,         unknowns, parameter,           trace.shooting,
                                            LinearSolverType::kKlu, trace.options, {}, {}, {},
                                            trace.max_amplitude,    kDefaultResonanceApproach, trace.model};
}

// The progress steps of the curves: two per special point of the trace (both ways).
template <OscillatorModel Model>
int StartSteps(const BasicMapTrace<Model>& trace) {
  int total = 0;
  for (const BasicMapTraceBranch<Model>& b : trace.branches) total += 2 * static_cast<int>(b.special.size());
  return total;
}

void Report(const OrbitTypeMapOptions& options, double done, double total, const char* unit) {
  if (options.progress) options.progress({done, total, unit, std::numeric_limits<double>::quiet_NaN()});
}

// The branch of a continuation to a target value of its parameter, or why it did not get there.
template <OscillatorModel Model>
struct Reached {
  std::optional<BasicOrbitBranch<Model>> branch;  // ending exactly on the target
  std::string why;
  bool turned_back = false;  // not there: it ended back on its start's value (its family folds on the way)
};

// The branch of `setup` from its start to `target` of its parameter, ending exactly there (the
// range's bound).
template <OscillatorModel Model>
Reached<Model> ContinueTo(BasicOrbitContinuationSetup<Model> setup, double target, int max_points) {
  const double from = ValueOf(setup.model, setup.start, setup.parameter);
  if (from == target) {
    setup.options.max_points = 1;
    setup.options.lambda_min = -std::numeric_limits<double>::infinity();
    setup.options.lambda_max = std::numeric_limits<double>::infinity();
  } else {
    setup.options.lambda_min = std::min(from, target);
    setup.options.lambda_max = std::max(from, target);
    setup.options.direction = target > from ? 1 : -1;
    setup.options.max_points = max_points;
  }
  setup.options.user_values.clear();
  setup.options.unknown_bounds.clear();
  setup.options.continue_past_terminal = true;
  setup.options.detect_folds = false;
  setup.options.detect_branch_points = false;
  setup.options.progress = {};
  BasicOrbitBranch<Model> branch;
  try {
    branch = ContinueOrbit(setup);
  } catch (const InvalidInput& e) {  // a start the continuation refuses: a failure of this one only
    return {std::nullopt, fmt::format("{} from {} to {}: {}", setup.parameter, from, target, e.what())};
  }
  // The engine puts the last point on the bound to rounding (ContinuationOptions::bound_tolerance).
  const auto ends_on = [&branch](double value) {
    return !branch.branch.points.empty() &&
           std::abs(branch.branch.points.back().lambda - value) <= 1e-12 * (1.0 + std::abs(value));
  };
  if (!ends_on(target)) {
    return {std::nullopt,
            fmt::format("{} from {} to {}: {} ({})", setup.parameter, from, target, ToString(branch.branch.end),
                        branch.branch.end_message),
            branch.branch.end == BranchEnd::kParameterBound && branch.branch.points.size() > 1 && ends_on(from)};
  }
  return {std::move(branch), {}};
}

// The trace must pass through the rectangle, at a value of the second parameter it holds: the
// curves start at its special points there, the regions' orbits are continued from its points.
template <OscillatorModel Model>
void CheckTraceInRectangle(const BasicMapTrace<Model>& trace, const MapRectangle& r) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::optional<double> held;
  for (const BasicMapTraceBranch<Model>& b : trace.branches) {
    for (const OrbitOfModel<Model>& o : b.orbits) {
      lo = std::min(lo, ValueOf(trace.model, o, r.first));
      hi = std::max(hi, ValueOf(trace.model, o, r.first));
      const double second = ValueOf(trace.model, o, r.second);
      if (!held) held = second;
      if (second != *held) {
        throw InvalidInput("second", r.second, fmt::format("a parameter the trace holds (its {} runs from {} to {} on {})",
                                                           r.second, *held, second, b.name));
      }
    }
  }
  if (!held) throw InvalidInput("trace", fmt::format("{} branches without points", trace.branches.size()), "a trace with points");
  const std::string on = fmt::format("(the trace's {} = {}: the curves start on it)", r.second, *held);
  if (r.second_min > *held) throw InvalidInput("second_min", r.second_min, fmt::format("<= {} {}", *held, on));
  if (r.second_max < *held) throw InvalidInput("second_max", r.second_max, fmt::format(">= {} {}", *held, on));
  const std::string range = fmt::format("(the trace's {} runs from {} to {})", r.first, lo, hi);
  if (r.first_min > hi) throw InvalidInput("first_min", r.first_min, fmt::format("<= {} {}", hi, range));
  if (r.first_max < lo) throw InvalidInput("first_max", r.first_max, fmt::format(">= {} {}", lo, range));
}

}  // namespace

void MapRectangle::Validate(const ModelDescription& model, bool autonomous) const {
  model.VariedParameter("first", first, autonomous);
  if (second == first) throw InvalidInput("second", "'" + second + "'", fmt::format("a parameter other than {}", first));
  model.VariedParameter("second", second, autonomous);
  ValidateBounds();
}

// A side narrower than this, relative to its values, is below what the curves' ends are located to.
constexpr double kNarrowestSide = 1e-8;

void MapRectangle::ValidateBounds() const {
  const auto check = [](const char* field, double min, double max, const char* max_name) {
    if (!(std::isfinite(min) && std::isfinite(max) && min < max)) {
      throw InvalidInput(field, min, fmt::format("finite, < {} ({})", max_name, max));
    }
    if (!(max - min > kNarrowestSide * std::max(std::abs(min), std::abs(max)))) {
      throw InvalidInput(field, min, fmt::format("< {} ({}) by more than {:g} of their size", max_name, max, kNarrowestSide));
    }
  };
  check("first_min", first_min, first_max, "first_max");
  check("second_min", second_min, second_max, "second_max");
}

void OrbitTypeMapOptions::Validate() const {
  if (raster < 16 || raster > 2000) throw InvalidInput("raster", raster, "16 <= raster <= 2000");
  if (!(min_region >= 0.0 && min_region <= 0.5)) throw InvalidInput("min_region", min_region, "0 <= min_region <= 0.5");
  if (max_curves < 1 || max_curves > 10000) throw InvalidInput("max_curves", max_curves, "1 <= max_curves <= 10000");
  if (max_curve_points < 2 || max_curve_points > 100000) {
    throw InvalidInput("max_curve_points", max_curve_points, "2 <= max_curve_points <= 100000");
  }
  if (max_content_points < 2 || max_content_points > 100000) {
    throw InvalidInput("max_content_points", max_content_points, "2 <= max_content_points <= 100000");
  }
  if (!(same_orbit >= 0.0 && same_orbit <= 1.0)) throw InvalidInput("same_orbit", same_orbit, "0 <= same_orbit <= 1");
}

namespace {

// "slip- stick (stable)": an orbit's type with its stability, as labels list it.
std::string TypeWithStability(const std::string& signature, bool stable) {
  return fmt::format("{} ({})", signature, stable ? "stable" : "unstable");
}

// The admissible orbits' types with their stability, sorted: a region's label, and what the trace's
// points are compared with.
template <OscillatorModel Model>
std::set<std::string> AdmissibleTypes(const std::vector<BasicMapOrbit<Model>>& orbits) {
  std::set<std::string> types;
  for (const BasicMapOrbit<Model>& o : orbits) {
    if (o.admissible) types.insert(TypeWithStability(o.signature, o.stable));
  }
  return types;
}

}  // namespace

template <OscillatorModel Model>
std::string BasicMapRegion<Model>::Label() const {
  const std::set<std::string> parts = AdmissibleTypes(orbits);
  // A continuation of the trace's orbits that failed leaves the content incomplete: said, so that a
  // region is not called motionless for want of a solve.
  const std::string incomplete =
      failures.empty() ? "" : fmt::format(" ({} continuation(s) of the trace's orbits did not reach it)", failures.size());
  // The map knows the trace's orbits only: another motion may well be there, of another type or of
  // another family of the same type (a brute force tells).
  std::string label;
  if (parts.empty()) {
    label = failures.empty() ? "none of the trace's orbits" : "unknown: none of the trace's orbits found" + incomplete;
  } else {
    label = fmt::format("{}", fmt::join(parts, "; ")) + incomplete;
  }
  if (differing == 0) return label;
  return fmt::format("not uniform: {} at its interior point, {} place(s) differ", label, differing);
}

template <OscillatorModel Model>
std::vector<std::string> BasicMapRegion<Model>::StableTypes() const {
  std::set<std::string> types;
  for (const BasicMapOrbit<Model>& o : orbits) {
    if (o.admissible && o.stable) types.insert(o.signature);
  }
  return {types.begin(), types.end()};
}

template <OscillatorModel Model>
int BasicOrbitTypeMap<Model>::RegionAt(double first, double second) const {
  const MapRectangle& r = rectangle;
  const int n = options.raster;
  const double u = (first - r.first_min) / (r.first_max - r.first_min);
  const double v = (second - r.second_min) / (r.second_max - r.second_min);
  if (!(u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0)) return kCut;
  const int i = std::min(n - 1, static_cast<int>(u * n));
  const int j = std::min(n - 1, static_cast<int>(v * n));
  return cells[static_cast<std::size_t>(j) * n + i];
}

template <OscillatorModel Model>
BasicOrbitTypeMap<Model> CutIntoRegions(const MapRectangle& rectangle,
                                        const std::vector<std::vector<std::pair<double, double>>>& polylines,
                                        const OrbitTypeMapOptions& options) {
  using Map = BasicOrbitTypeMap<Model>;
  rectangle.ValidateBounds();
  options.Validate();
  Map map;
  map.rectangle = rectangle;
  map.options = options;
  map.options.progress = {};
  const int n = options.raster;
  const auto at = [n](int i, int j) { return static_cast<std::size_t>(j) * n + i; };
  std::vector<int> cells(static_cast<std::size_t>(n) * n, 0);  // 0 free, kCut on a curve
  const double w = rectangle.first_max - rectangle.first_min, h = rectangle.second_max - rectangle.second_min;
  const auto mark = [&](double u, double v) {
    if (!(u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0)) return;
    cells[at(std::min(n - 1, static_cast<int>(u * n)), std::min(n - 1, static_cast<int>(v * n)))] = Map::kCut;
  };
  for (const auto& line : polylines) {
    for (std::size_t k = 0; k < line.size(); ++k) {
      const double u1 = (line[k].first - rectangle.first_min) / w, v1 = (line[k].second - rectangle.second_min) / h;
      mark(u1, v1);
      if (k + 1 == line.size()) break;
      const double u2 = (line[k + 1].first - rectangle.first_min) / w, v2 = (line[k + 1].second - rectangle.second_min) / h;
      if (!(std::isfinite(u1) && std::isfinite(v1) && std::isfinite(u2) && std::isfinite(v2))) continue;
      // Sampled every quarter of a cell, at most 4 n per unit of the rectangle (a segment leaving it is clipped).
      const double length = std::max(std::abs(u2 - u1), std::abs(v2 - v1));
      const int samples = static_cast<int>(std::ceil(std::min(length, 2.0) * 4.0 * n));
      for (int s = 1; s <= samples; ++s) {
        const double t = static_cast<double>(s) / samples;
        mark(u1 + t * (u2 - u1), v1 + t * (v2 - v1));
      }
    }
  }
  // Chessboard distance from the cut cells and the edges (two passes).
  std::vector<int> distance(cells.size());
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      distance[at(i, j)] = cells[at(i, j)] == Map::kCut ? 0 : std::min({i + 1, j + 1, n - i, n - j});
    }
  }
  for (int pass = 0; pass < 2; ++pass) {
    for (int step = 0; step < n * n; ++step) {
      const int index = pass == 0 ? step : n * n - 1 - step;
      const int i = index % n, j = index / n;
      for (int dj = -1; dj <= 1; ++dj) {
        for (int di = -1; di <= 1; ++di) {
          const int ii = i + di, jj = j + dj;
          if (ii < 0 || jj < 0 || ii >= n || jj >= n) continue;
          distance[at(i, j)] = std::min(distance[at(i, j)], distance[at(ii, jj)] + 1);
        }
      }
    }
  }
  // Components (4-neighbours), in raster order of their first cell.
  std::vector<int> component(cells.size(), -1);
  std::vector<std::vector<int>> members;
  for (int start = 0; start < n * n; ++start) {
    if (cells[start] == Map::kCut || component[start] >= 0) continue;
    const int c = static_cast<int>(members.size());
    members.emplace_back();
    std::deque<int> queue{start};
    component[start] = c;
    while (!queue.empty()) {
      const int index = queue.front();
      queue.pop_front();
      members[c].push_back(index);
      const int i = index % n, j = index / n;
      for (const auto& [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const int ii = i + di, jj = j + dj;
        if (ii < 0 || jj < 0 || ii >= n || jj >= n) continue;
        const int next = static_cast<int>(at(ii, jj));
        if (cells[next] == Map::kCut || component[next] >= 0) continue;
        component[next] = c;
        queue.push_back(next);
      }
    }
  }
  map.cells.assign(cells.size(), Map::kCut);
  const double smallest = options.min_region * n * n;
  for (const std::vector<int>& cs : members) {
    if (static_cast<double>(cs.size()) < smallest || cs.empty()) {
      for (int index : cs) map.cells[index] = Map::kSliver;
      continue;
    }
    BasicMapRegion<Model> region;
    region.id = static_cast<int>(map.regions.size()) + 1;
    region.cells = static_cast<int>(cs.size());
    int best = *std::min_element(cs.begin(), cs.end());
    for (int index : cs) {
      if (distance[index] > distance[best] || (distance[index] == distance[best] && index < best)) best = index;
    }
    region.clearance = distance[best];
    region.first = rectangle.first_min + (best % n + 0.5) / n * w;
    region.second = rectangle.second_min + (best / n + 0.5) / n * h;
    for (int index : cs) map.cells[index] = static_cast<int>(map.regions.size());
    map.regions.push_back(std::move(region));
  }
  return map;
}

namespace {

// Per point of the curve `c` (its branch continued): admissible apart from the conditions that
// define it, stable, and its two parameters.
template <OscillatorModel Model>
void DescribePoints(const Model& model, const MapRectangle& r, const std::vector<std::string>& defining,
                    BasicMapCurve<Model>& c) {
  for (std::size_t k = 0; k < c.branch.orbits.size(); ++k) {
    c.admissible.push_back(AdmissibleApartFrom(c.branch, k, defining));
    c.stable.push_back(Column(c.branch, k, orbit_columns::kStable) == 1.0);
    c.first.push_back(ValueOf(model, c.branch.orbits[k], r.first));
    c.second.push_back(ValueOf(model, c.branch.orbits[k], r.second));
  }
}

// The curves through the trace's special points (both ways each), and the points refused.
template <OscillatorModel Model>
struct ContinuedCurves {
  std::vector<BasicMapCurve<Model>> curves;
  std::vector<MapSkippedStart> skipped;
};
template <OscillatorModel Model>
ContinuedCurves<Model> ContinueCurves(const BasicMapTrace<Model>& trace, const MapRectangle& r,
                                      const OrbitTypeMapOptions& options) {
  ContinuedCurves<Model> continued;
  std::vector<std::pair<std::string, OrbitOfModel<Model>>> started;  // (condition, orbit): a point met twice is one start
  const int total = StartSteps(trace);
  int done = 0;
  for (const BasicMapTraceBranch<Model>& b : trace.branches) {
    for (const BasicMapStartPoint<Model>& p : b.special) {
      done += 2;
      if (p.type == "EP" || p.type == "UZ") continue;  // the ends of a branch, user values: no condition
      const std::string from = fmt::format("{}:{}", b.name, p.label);
      const std::string condition = CurveCondition(p.type, p.test_function);
      const bool again = std::any_of(started.begin(), started.end(), [&](const auto& s) {
        return s.first == condition && Distance(trace.model, s.second, p.orbit) <= options.same_orbit;
      });
      if (again) continue;
      started.emplace_back(condition, p.orbit);
      // (Its second parameter is the trace's, inside the rectangle: CheckTraceInRectangle.)
      const double first = ValueOf(trace.model, p.orbit, r.first);
      const BasicOrbitContinuationSetup<Model> branch_setup = SetupAt(trace, p.orbit, b.unknowns, trace.parameter);
      std::optional<BasicOrbitContinuationSetup<Model>> made;
      try {
        made = BoundaryCurve(BasicCurveStart<Model>{.orbit = p.orbit, .condition = condition, .parameter = trace.parameter,
                                                    .unknowns = b.unknowns},
                             branch_setup, r.second);
      } catch (const InvalidInput& e) {
        continued.skipped.push_back({from, condition, e.what()});
        continue;
      }
      BasicOrbitContinuationSetup<Model>& curve = *made;
      std::vector<std::string> defining = curve.unwatched;
      if (curve.condition) {
        const std::vector<std::string> more = curve.condition->Defining();
        defining.insert(defining.end(), more.begin(), more.end());
      }
      ContinuationOptions& o = curve.options;
      // A start left or right of the rectangle is continued from there: its curve may cross it.
      o.lambda_min = std::min(r.first_min, first);
      o.lambda_max = std::max(r.first_max, first);
      o.max_points = options.max_curve_points;
      o.user_values.clear();
      o.progress = {};
      o.unknown_bounds = {{.index = UnknownPosition(curve, r.second), .min = r.second_min, .max = r.second_max, .name = r.second}};
      for (int direction : {-1, 1}) {
        if (static_cast<int>(continued.curves.size()) >= options.max_curves) {
          continued.skipped.push_back({from, condition, fmt::format("max_curves = {} reached", options.max_curves)});
          break;
        }
        o.direction = direction;
        BasicMapCurve<Model> c;
        c.id = static_cast<int>(continued.curves.size()) + 1;
        c.kind = condition;
        c.from = from;
        c.direction = direction;
        try {
          c.branch = ContinueOrbit(curve);
        } catch (const InvalidInput& e) {  // a curve the continuation refuses gives none, the map goes on
          continued.skipped.push_back({from, condition, e.what()});
          break;
        }
        DescribePoints(trace.model, r, defining, c);
        continued.curves.push_back(std::move(c));
      }
      Report(options, done, total + 1.0, "steps");
    }
  }
  return continued;
}

// A point of a branch the content at first = a is continued from.
struct ContentStart {
  std::size_t point = 0;
  bool straddles = true;  // the branch passes a there: its continuation must reach the point
};

// The points of `branch` the content at first = a is continued from: of each pair of consecutive
// points whose first parameter straddles a, the nearer one; on a branch that does not reach a (a
// type that ends short of it in the first parameter, whose orbits may be motions there at another
// value of the second), its end nearer a, whose continuation may well end on the way.
template <OscillatorModel Model>
std::vector<ContentStart> ContentStarts(const Model& model, const BasicMapTraceBranch<Model>& branch,
                                        const std::string& first, double a) {
  std::vector<ContentStart> starts;
  for (std::size_t k = 0; k + 1 < branch.orbits.size(); ++k) {
    const double p = ValueOf(model, branch.orbits[k], first), q = ValueOf(model, branch.orbits[k + 1], first);
    if (!((p - a) * (q - a) <= 0.0) || p == q) continue;
    starts.push_back({std::abs(p - a) <= std::abs(q - a) ? k : k + 1});
  }
  if (starts.empty() && !branch.orbits.empty()) {
    const std::size_t last = branch.orbits.size() - 1;
    const double p = ValueOf(model, branch.orbits.front(), first), q = ValueOf(model, branch.orbits[last], first);
    starts.push_back({std::abs(p - a) <= std::abs(q - a) ? 0 : last, false});
  }
  return starts;
}

}  // namespace

namespace {

// The orbit at the end of `there` among `orbits`, unless one of its type is there already (within
// `same_orbit`: the same motion found from another trace point).
template <OscillatorModel Model>
void AddOrbit(const Model& model, const BasicOrbitBranch<Model>& there, const std::string& from, double same_orbit,
              std::vector<BasicMapOrbit<Model>>& orbits) {
  const std::size_t last = there.orbits.size() - 1;
  BasicMapOrbit<Model> orbit{.signature = there.orbits[last].signature.ToString(),
                             .admissible = Column(there, last, orbit_columns::kAdmissible) == 1.0,
                             .stable = Column(there, last, orbit_columns::kStable) == 1.0,
                             .from = from,
                             .orbit = there.orbits[last]};
  const bool known = std::any_of(orbits.begin(), orbits.end(), [&](const BasicMapOrbit<Model>& o) {
    return o.signature == orbit.signature && Distance(model, o.orbit, orbit.orbit) <= same_orbit;
  });
  if (!known) orbits.push_back(std::move(orbit));
}

// The branch of `setup` from its start to (a, b): in the first parameter, then in the second; with
// `second_first`, the other way round (where the first way meets a fold of the orbit's family on the
// trace's line, the second may pass beside it).
template <OscillatorModel Model>
Reached<Model> ContinueToPoint(BasicOrbitContinuationSetup<Model> setup, const MapRectangle& r, double a, double b,
                               bool second_first, int max_points) {
  const std::pair<const std::string*, double> first{&r.first, a}, second{&r.second, b};
  Reached<Model> reached;
  for (const auto& [name, target] : second_first ? std::array{second, first} : std::array{first, second}) {
    setup.parameter = *name;
    reached = ContinueTo(setup, target, max_points);
    if (!reached.branch) return reached;
    setup.start = reached.branch->orbits.back();
  }
  return reached;
}

}  // namespace

template <OscillatorModel Model>
BasicMapOrbitsAt<Model> OrbitsAt(const BasicMapTrace<Model>& trace, const MapRectangle& r, double a, double b,
                                 const OrbitTypeMapOptions& options) {
  // The branches that pass a first, then the others' ends: an orbit found twice keeps the first
  // finding, the one continued the shorter way; every start the first way, then every start the
  // second way.
  std::vector<std::pair<const BasicMapTraceBranch<Model>*, ContentStart>> starts;
  for (const BasicMapTraceBranch<Model>& branch : trace.branches) {
    for (const ContentStart& start : ContentStarts(trace.model, branch, r.first, a)) starts.emplace_back(&branch, start);
  }
  std::stable_partition(starts.begin(), starts.end(), [](const auto& s) { return s.second.straddles; });
  BasicMapOrbitsAt<Model> found;
  std::vector<bool> there(starts.size(), false), folds(starts.size(), false);
  std::vector<std::optional<Reached<Model>>> failed(starts.size());  // the first way's failure
  for (bool second_first : {false, true}) {
    for (std::size_t k = 0; k < starts.size(); ++k) {
      const auto& [branch, start] = starts[k];
      if (there[k]) continue;  // got there the first way
      Reached<Model> reached = ContinueToPoint(SetupAt(trace, branch->orbits[start.point], branch->unknowns, r.first), r,
                                               a, b, second_first, options.max_content_points);
      if (!reached.branch) {
        // One that turns back (its family folds on the way) found that the family does not reach
        // the point that way: no failure of the computation.
        folds[k] = folds[k] || reached.turned_back;
        if (!second_first) failed[k] = std::move(reached);
        continue;
      }
      there[k] = true;
      const std::string from = fmt::format("{} pt {}", branch->name, start.point + 1);
      AddOrbit(trace.model, *reached.branch, from, options.same_orbit, found.orbits);
    }
  }
  for (std::size_t k = 0; k < starts.size(); ++k) {
    if (there[k] || folds[k] || !failed[k]) continue;
    const auto& [branch, start] = starts[k];
    found.failures.push_back(
        fmt::format("{} pt {}{}: {}", branch->name, start.point + 1, start.straddles ? "" : " (its end)", failed[k]->why));
  }
  return found;
}

namespace {

// Whether a continuation from `branch` to the region's interior point failed: its orbits' absence
// there says nothing.
template <OscillatorModel Model>
bool FailedFrom(const BasicMapRegion<Model>& region, const std::string& branch) {
  const auto from = [&](const std::string& failure) { return failure.starts_with(branch + " pt "); };
  return std::any_of(region.failures.begin(), region.failures.end(), from);
}

template <OscillatorModel Model>
void NoteDiffering(BasicMapRegion<Model>& region, std::string where) {
  constexpr std::size_t kListed = 5;
  ++region.differing;
  if (region.elsewhere.size() < kListed) region.elsewhere.push_back(std::move(where));
}

// Each admissible point of the trace inside a region must be among the region's admissible orbits
// (but where its branch's continuation to the interior point failed).
template <OscillatorModel Model>
void CompareTracePoints(const BasicMapTrace<Model>& trace, BasicOrbitTypeMap<Model>& map) {
  const MapRectangle& r = map.rectangle;
  std::vector<std::set<std::string>> types;
  for (const BasicMapRegion<Model>& region : map.regions) types.push_back(AdmissibleTypes(region.orbits));
  for (const BasicMapTraceBranch<Model>& b : trace.branches) {
    if (b.admissible.size() != b.orbits.size() || b.stable.size() != b.orbits.size()) continue;
    for (std::size_t k = 0; k < b.orbits.size(); ++k) {
      const double first = ValueOf(trace.model, b.orbits[k], r.first), second = ValueOf(trace.model, b.orbits[k], r.second);
      const int index = map.RegionAt(first, second);
      if (index < 0 || !b.admissible[k]) continue;
      BasicMapRegion<Model>& region = map.regions[static_cast<std::size_t>(index)];
      if (FailedFrom(region, b.name)) continue;
      const std::string type = TypeWithStability(b.orbits[k].signature.ToString(), b.stable[k]);
      if (types[static_cast<std::size_t>(index)].contains(type)) continue;
      NoteDiffering(region, fmt::format("{} pt {} at ({}, {}) = ({:.6g}, {:.6g}): {}", b.name, k + 1, r.first, r.second, first,
                                        second, type));
    }
  }
}

}  // namespace

template <OscillatorModel Model>
BasicOrbitTypeMap<Model> BuildOrbitTypeMap(const BasicMapTrace<Model>& trace, const MapRectangle& rectangle,
                                           const OrbitTypeMapOptions& options) {
  rectangle.Validate(trace.model.Description(), trace.model.Autonomous());
  options.Validate();
  if (rectangle.first != trace.parameter) {
    throw InvalidInput("first", rectangle.first, fmt::format("the trace's parameter, {}", trace.parameter));
  }
  CheckTraceInRectangle(trace, rectangle);
  ContinuedCurves<Model> curves = ContinueCurves(trace, rectangle, options);
  std::vector<std::vector<std::pair<double, double>>> polylines;
  for (const BasicMapCurve<Model>& c : curves.curves) {
    std::vector<std::pair<double, double>> line;
    for (std::size_t k = 0; k < c.first.size(); ++k) line.emplace_back(c.first[k], c.second[k]);
    polylines.push_back(std::move(line));
  }
  BasicOrbitTypeMap<Model> map = CutIntoRegions<Model>(rectangle, polylines, options);
  map.curves = std::move(curves.curves);
  map.skipped = std::move(curves.skipped);
  for (std::size_t k = 0; k < map.regions.size(); ++k) {
    BasicMapRegion<Model>& region = map.regions[k];
    BasicMapOrbitsAt<Model> content = OrbitsAt(trace, rectangle, region.first, region.second, options);
    region.orbits = std::move(content.orbits);
    region.failures = std::move(content.failures);
    const double starts = StartSteps(trace);
    Report(options, starts + static_cast<double>(k + 1), starts + static_cast<double>(map.regions.size()), "steps");
  }
  CompareTracePoints(trace, map);
  return map;
}

template struct BasicMapRegion<Pascal2014>;
template struct BasicOrbitTypeMap<Pascal2014>;
template BasicOrbitTypeMap<Pascal2014> CutIntoRegions(const MapRectangle&, const std::vector<std::vector<std::pair<double, double>>>&,
                                            const OrbitTypeMapOptions&);
template BasicOrbitTypeMap<Pascal2014> BuildOrbitTypeMap(const BasicMapTrace<Pascal2014>&, const MapRectangle&, const OrbitTypeMapOptions&);
template BasicMapOrbitsAt<Pascal2014> OrbitsAt(const BasicMapTrace<Pascal2014>&, const MapRectangle&, double, double,
                                     const OrbitTypeMapOptions&);

template struct BasicMapRegion<DynamicLinearOscillator>;
template struct BasicOrbitTypeMap<DynamicLinearOscillator>;
template BasicOrbitTypeMap<DynamicLinearOscillator> CutIntoRegions(const MapRectangle&, const std::vector<std::vector<std::pair<double, double>>>&,
                                            const OrbitTypeMapOptions&);
template BasicOrbitTypeMap<DynamicLinearOscillator> BuildOrbitTypeMap(const BasicMapTrace<DynamicLinearOscillator>&, const MapRectangle&, const OrbitTypeMapOptions&);
template BasicMapOrbitsAt<DynamicLinearOscillator> OrbitsAt(const BasicMapTrace<DynamicLinearOscillator>&, const MapRectangle&, double, double,
                                     const OrbitTypeMapOptions&);

}  // namespace stickslip
