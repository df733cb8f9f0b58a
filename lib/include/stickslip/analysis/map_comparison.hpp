// The orbit-type map (branches/orbit_type_map.hpp) against a brute-force map of the same two
// parameters (analysis/brute_force_map.hpp), cell by cell (issue 13's test): in every cell of the
// brute-force grid farther than `clearance` grid steps from every curve of the map (distance in
// grid steps, Euclidean, to the curves' polylines) and inside one of its regions, the stable
// attractors the simulation found (periodic of period 1: their orbit types) against the stable
// orbit types the map assigns to the cell's region (its admissible, stable orbits). A cell agrees
// when the two sets are equal; the brute force's other motions (period > 1, not settled, periodic
// without an orbit type: a permanent stick) are listed with the cell, and explain a stable orbit of
// the map that the brute force did not find (its starts ended on them). Types are compared up to a cyclic shift of their segments (the
// simulation reads a period from its own origin). Each disagreement is explained where a reason is
// known:
//   period-k motion      the brute force found a motion of period k > 1: the map holds period-1 orbits
//   no orbit type        a periodic motion without a stop or stick exit in a period (a permanent
//                        stick): no trace's orbit
//   not settled          a run did not settle on a periodic section
//   not on the trace     a stable type found that no branch of the trace has: the map cannot know it
//   region not uniform   the trace's orbits solved at the cell itself (OrbitsAt, with `trace`) are
//                        stable as the brute force finds them, unlike at the region's interior point:
//                        a boundary between them that the map lacks (a curve it could not continue)
//   not found            a stable orbit of the map the brute force's starts did not reach, explained
//                        where some start ended on another motion (another basin), unexplained
//                        where all ended on the types found
// and "unexplained" otherwise (the map's content or the region's cut is wrong there).
#pragma once

#include <string>
#include <vector>

#include "stickslip/analysis/brute_force_map.hpp"
#include "stickslip/branches/orbit_type_map.hpp"

namespace stickslip {

struct MapComparisonOptions {
  double clearance = 2.0;  // grid steps a compared cell keeps from every curve (0 to 1e3)
  void Validate() const;   // throws InvalidInput naming "clearance"
};

struct MapCellComparison {
  int i = 0, j = 0;
  double first = 0.0, second = 0.0;
  int region = 0;                      // the map's region id
  std::vector<std::string> found;      // stable period-1 types of the brute force, sorted
  std::vector<std::string> expected;   // the region's stable types, sorted
  std::vector<std::string> others;     // the brute force's other attractors: "period 2 (slip- ...)", "not-settled"
  std::vector<std::string> at_cell;    // the trace's stable types solved at the cell itself (with a trace), sorted
  bool agrees = false;
  std::string explanation;             // "; "-joined reasons, "" where it agrees
  bool explained = false;              // every difference has a reason
};

struct MapComparison {
  int cells = 0;       // of the brute-force map
  int compared = 0;    // far enough from the curves and inside a region
  int agreeing = 0;
  // Of the agreeing cells, those where both find a stable period-1 orbit (the others agree that
  // there is none).
  int agreeing_stable = 0;
  std::vector<MapCellComparison> disagreements;  // by j then i
  double Agreement() const { return compared > 0 ? static_cast<double>(agreeing) / compared : 0.0; }
  int Explained() const;  // disagreements with a reason for every difference
};

// The orbit type up to a cyclic shift: the listed segments rotated to the lexicographically least
// order (a " / antisymmetric" or other suffix after the segments kept).
std::string CanonicalOrbitType(const std::string& signature);

// Throws InvalidInput naming "brute force" unless `brute` can be compared with a map of
// `rectangle`: a map over its two parameters (first and second), whole (every cell of its grid: a
// shard compares only some rows, and its grid steps are not the cells' spacing), with a cell in the
// rectangle. Callers check it before the map's work.
void CheckComparable(const BruteForceMap& brute, const MapRectangle& rectangle);

// Throws InvalidInput as CheckComparable.
// `trace`, where not null, is the map's: the disagreeing cells' contents are solved there.
MapComparison CompareWithBruteForce(const OrbitTypeMap& map, const MapTrace* trace, const std::vector<std::string>& trace_types,
                                    const BruteForceMap& brute, const MapComparisonOptions& options = {});

}  // namespace stickslip
