// The orbit-type map of a rectangle of two parameters (issue 13 item 2), assembled from a trace
// (branches/trace.hpp) in its parameter (the map's first) and a second parameter:
//   curves   through every special point of the trace's branches that BoundaryCurve gives a curve
//            of (a type change by its margin; LP, PD, SB, TR), continued both ways of the first
//            parameter across the rectangle (from a start left or right of it too: its curve may
//            cross it): each ends where the released second parameter leaves it (an UnknownBound,
//            located), at a bound of the first (or the start's, beyond), or at a codimension-two point
//            (a second margin leaving its positive side: another type boundary met); the folds of
//            a curve are its LP. Points BoundaryCurve refuses are listed with its reason.
//   regions  the rectangle cut by the curves: the curves' polylines rasterized on a raster x raster
//            grid of cells (a cell is cut where a curve passes through it: a polyline sampled every
//            quarter of a cell), and the connected components (4-neighbours) of the other cells;
//            components of fewer than min_region of the cells are slivers, dropped. Each region's
//            interior point is the centre of its cell farthest (chessboard distance) from every cut
//            cell and from the rectangle's edges.
//   content  at each interior point (a, b), every orbit of the trace there: on each branch, at
//            each pair of consecutive points whose first parameter straddles a, the nearer one (on
//            a branch that does not pass a, its end nearer a, after the others) is continued in the
//            first parameter to a, then in the second to b, and where that fails the other way
//            round (each continuation ends on its bound, exactly at the value; past changes of type,
//            so the orbit may come out not admissible: no motion of that type there; one that turns
//            back, its family folding on the way, is no failure); orbits found twice (same type,
//            OrbitDistance <= same_orbit; a [model]'s state and period relative) are one. A
//            region's label: its admissible orbit types, each stable or unstable.
//   uniform  each admissible point of the trace in a region among the region's admissible orbits
//            (type and stability): where not, a curve is missing (one that ends inside the
//            rectangle joins the regions on its sides) and the region says it is not uniform, with
//            the places that differ.
// Every loop is bounded: the curves by max_curves and max_curve_points, the content by the trace's
// points and max_content_points per continuation, the raster by raster^2. For any model: the
// paper's (MapTrace, OrbitTypeMap) and a [model]'s (BasicMapTrace<DynamicLinearOscillator>), whose
// trace holds the model.
//
//   MapTrace trace = ...;  // io/orbit_type_map_files.hpp: MapTraceOf(ReadTraceFiles(dir))
//   const OrbitTypeMap map = BuildOrbitTypeMap(trace, {"omega", "u_r", 0.5, 0.6, 0.3, 0.6}, {});
//   for (const MapRegion& r : map.regions) use(r.first, r.second, r.Label());
#pragma once

#include <string>
#include <vector>

#include "stickslip/branches/boundary_curve.hpp"
#include "stickslip/branches/orbit_continuation.hpp"
#include "stickslip/progress.hpp"

namespace stickslip {

// A special point of a trace's branch, where a curve may start.
template <OscillatorModel Model>
struct BasicMapStartPoint {
  std::string branch;         // the trace branch's name, "branch-4"
  std::string label;          // its label there, "SK3"
  std::string type;           // "SK", "LP", "TR", ...
  std::string test_function;  // "margin:reversal:1", "tangent:lambda", "floquet:torus", ...
  OrbitOfModel<Model> orbit;
};

// A branch of the trace: its orbits (every point, in order) and special points.
template <OscillatorModel Model>
struct BasicMapTraceBranch {
  std::string name;
  UnknownChoice unknowns;  // the branch's unknowns (its parameter held)
  std::vector<OrbitOfModel<Model>> orbits;
  std::vector<BasicMapStartPoint<Model>> special;
  // Per orbit, as the trace found them (empty: not known; the regions are then not checked against
  // the trace's points).
  std::vector<bool> admissible, stable;
};

template <OscillatorModel Model>
struct BasicMapTrace {
  std::string parameter;  // the trace's continued parameter: the map's first
  // The continuation options (ds, ds_min, ds_max, ...) and shooting of every curve and content
  // continuation; the range, direction, max_points and user values are the map's.
  ContinuationOptions options;
  ShootingChoice shooting = ShootingChoice::kAuto;
  double max_amplitude = kDefaultMaxAmplitude;  // the trace's: a resonance ends a curve or a content continuation
  std::vector<BasicMapTraceBranch<Model>> branches;
  Model model{};  // last, so that the paper's traces need not name it
};
using MapStartPoint = BasicMapStartPoint<Pascal2014>;
using MapTraceBranch = BasicMapTraceBranch<Pascal2014>;
using MapTrace = BasicMapTrace<Pascal2014>;

struct MapRectangle {
  std::string first;   // the trace's parameter
  std::string second;  // another parameter the model varies: chi, eta, omega, u_s, u_r for the paper's
  double first_min = 0.0, first_max = 0.0;
  double second_min = 0.0, second_max = 0.0;
  // Throws InvalidInput naming "first_min" ("second_min") unless min < max by more than 1e-8 of
  // their size (narrower, the curves' ends are not located inside), both finite, "first"
  // for a first parameter the model does not vary (ModelDescription::VariedParameter: an
  // autonomous model's forcing frequency is none) and "second" for a second one that is not or is
  // the first.
  void Validate(const ModelDescription& model, bool autonomous) const;
  void ValidateBounds() const;  // the bounds alone
};

struct OrbitTypeMapOptions {
  int raster = 200;           // cells per side of the raster the regions are cut on (16 to 2000)
  double min_region = 2e-3;   // a component of fewer than this fraction of the cells is a sliver (0 to 0.5)
  int max_curves = 200;       // curves (each direction one) at most (1 to 10000)
  int max_curve_points = 600;    // points per curve (2 to 100000)
  int max_content_points = 400;  // points per continuation to an interior point (2 to 100000)
  // Two orbits of one type within this (OrbitDistance; a [model]'s state relative to its size, its
  // period relative) are one (0 to 1).
  double same_orbit = 1e-6;
  // Called after each start of curves (two steps: both ways) and each region's content (one step),
  // unit "steps", done increasing; the total is known once the regions are (before: the curves'
  // steps + 1). Empty: no reports.
  ProgressCallback progress = {};

  void Validate() const;  // throws InvalidInput naming the first field out of its range
};

// A curve of codimension-one points in the rectangle, from one start, one way of the first parameter.
template <OscillatorModel Model>
struct BasicMapCurve {
  int id = 0;              // 1, 2, ... in the order computed
  std::string kind;        // its condition: "LP", "PD", "margin:reversal:1", ...
  std::string from;        // the start: "branch-4:SK3"
  int direction = 1;       // the first parameter's way at the start
  BasicOrbitBranch<Model> branch;  // the curve as any branch (its special points: LP, codimension-two, EP)
  // Per point: admissible apart from the conditions that define the curve (its unwatched columns),
  // and stable.
  std::vector<bool> admissible;
  std::vector<bool> stable;
  std::vector<double> first, second;  // the two parameters per point
};

// A special point of the trace that gives no curve, and why.
struct MapSkippedStart {
  std::string from;       // "branch-2:GR2"
  std::string condition;  // what BoundaryCurve was asked for
  std::string reason;
};

// An orbit found at a region's interior point.
template <OscillatorModel Model>
struct BasicMapOrbit {
  std::string signature;
  bool admissible = false;
  bool stable = false;
  std::string from;  // "branch-3 pt 12": the trace point it was continued from
  OrbitOfModel<Model> orbit;
};

template <OscillatorModel Model>
struct BasicMapRegion {
  int id = 0;           // 1, 2, ... in raster order of their first cell
  int cells = 0;        // raster cells
  double first = 0.0;   // the interior point
  double second = 0.0;
  int clearance = 0;    // its distance from the nearest cut cell or edge, in cells
  std::vector<BasicMapOrbit<Model>> orbits;  // every orbit found there, deduplicated, in the order found
  std::vector<std::string> failures;  // continuations that did not reach the point (where, why)
  // Points of the trace in the region whose orbit (admissible, its type and stability) is not
  // among the region's admissible orbits (those whose branch's continuation to the interior point
  // failed aside): a curve the map lacks (one ending inside the rectangle leaves the regions on its
  // sides joined), the region is not uniform. `differing` counts them, `elsewhere` says where (the
  // first five).
  int differing = 0;
  std::vector<std::string> elsewhere;
  // "slip- stick (stable); slip- slip+ stick slip+ (unstable)": the admissible orbits; "none of the
  // trace's orbits" (another motion may be there, of their types too); with failures, how many
  // continuations did not reach the point ("unknown: ..." if none did); "not uniform: ... at its
  // interior point, N place(s) differ" where places differ.
  std::string Label() const;
  // The admissible stable orbits' types, sorted.
  std::vector<std::string> StableTypes() const;
};

template <OscillatorModel Model>
struct BasicOrbitTypeMap {
  MapRectangle rectangle;
  OrbitTypeMapOptions options;  // progress cleared
  std::vector<BasicMapCurve<Model>> curves;
  std::vector<MapSkippedStart> skipped;
  std::vector<BasicMapRegion<Model>> regions;
  // Per raster cell (row-major: cell (i, j) at j * raster + i, i along the first parameter): its
  // region's index in `regions`, kCut where a curve passes, kSliver in a dropped component.
  std::vector<int> cells;
  static constexpr int kCut = -1;
  static constexpr int kSliver = -2;
  // The region index (into `regions`) at a point of the rectangle, or kCut / kSliver / kCut for a
  // point outside it.
  int RegionAt(double first, double second) const;
};

// Every orbit of the trace at a point of the rectangle, and the continuations that did not get there.
template <OscillatorModel Model>
struct BasicMapOrbitsAt {
  std::vector<BasicMapOrbit<Model>> orbits;  // deduplicated, in the order found
  std::vector<std::string> failures;         // "branch-3 pt 12: why"
};

using MapCurve = BasicMapCurve<Pascal2014>;
using MapOrbit = BasicMapOrbit<Pascal2014>;
using MapRegion = BasicMapRegion<Pascal2014>;
using OrbitTypeMap = BasicOrbitTypeMap<Pascal2014>;
using MapOrbitsAt = BasicMapOrbitsAt<Pascal2014>;

// The regions of the rectangle cut by `polylines` (each a list of (first, second) points): the
// raster, the components, the interior points; no content. The pure geometry of BuildOrbitTypeMap,
// apart for testing on known arrangements. Throws InvalidInput as MapRectangle::Validate, for the
// bounds only, and OrbitTypeMapOptions::Validate.
template <OscillatorModel Model = Pascal2014>
BasicOrbitTypeMap<Model> CutIntoRegions(const MapRectangle& rectangle,
                                        const std::vector<std::vector<std::pair<double, double>>>& polylines,
                                        const OrbitTypeMapOptions& options);

// The map. Throws InvalidInput for an invalid rectangle or options, naming "first" when the
// rectangle's first parameter is not the trace's, "second" when the trace does not hold the second
// one fixed, and the bound (first_min, ...) that leaves the trace outside the rectangle (its value
// of the second parameter, or its whole range of the first).
template <OscillatorModel Model>
BasicOrbitTypeMap<Model> BuildOrbitTypeMap(const BasicMapTrace<Model>& trace, const MapRectangle& rectangle,
                                           const OrbitTypeMapOptions& options = {});

// Every orbit of the trace at (first, second) of the rectangle's parameters, as a region's content
// is found (above).
template <OscillatorModel Model>
BasicMapOrbitsAt<Model> OrbitsAt(const BasicMapTrace<Model>& trace, const MapRectangle& rectangle, double first,
                                 double second, const OrbitTypeMapOptions& options);

// Compiled for the paper's model and a [model]'s (orbit_type_map.cpp).
extern template struct BasicMapRegion<Pascal2014>;
extern template struct BasicOrbitTypeMap<Pascal2014>;
extern template BasicOrbitTypeMap<Pascal2014> CutIntoRegions(const MapRectangle&, const std::vector<std::vector<std::pair<double, double>>>&,
                                                   const OrbitTypeMapOptions&);
extern template BasicOrbitTypeMap<Pascal2014> BuildOrbitTypeMap(const BasicMapTrace<Pascal2014>&, const MapRectangle&,
                                                      const OrbitTypeMapOptions&);
extern template BasicMapOrbitsAt<Pascal2014> OrbitsAt(const BasicMapTrace<Pascal2014>&, const MapRectangle&, double, double,
                                            const OrbitTypeMapOptions&);

extern template struct BasicMapRegion<DynamicLinearOscillator>;
extern template struct BasicOrbitTypeMap<DynamicLinearOscillator>;
extern template BasicOrbitTypeMap<DynamicLinearOscillator> CutIntoRegions(const MapRectangle&, const std::vector<std::vector<std::pair<double, double>>>&,
                                                   const OrbitTypeMapOptions&);
extern template BasicOrbitTypeMap<DynamicLinearOscillator> BuildOrbitTypeMap(const BasicMapTrace<DynamicLinearOscillator>&, const MapRectangle&,
                                                      const OrbitTypeMapOptions&);
extern template BasicMapOrbitsAt<DynamicLinearOscillator> OrbitsAt(const BasicMapTrace<DynamicLinearOscillator>&, const MapRectangle&, double, double,
                                            const OrbitTypeMapOptions&);

}  // namespace stickslip
