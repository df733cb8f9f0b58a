// How far a long computation has got (a simulation, a sweep, a continuation), reported through
// a callback in its options struct, empty by default: the library draws nothing and keeps no
// global state; a front end may draw a progress line from it (tools/progress_line.hpp).
//
//   SweepOptions o;
//   o.progress = [](const Progress& p) { std::fprintf(stderr, "\r%g of %g", p.done, p.total); };
#pragma once

#include <functional>
#include <limits>

namespace stickslip {

struct Progress {
  double done = 0.0;   // work done so far, in `unit`s; never decreases within one computation
  // The work asked for, >= done. Where the work may end early (a branch at a bound before its
  // max_points) it is an upper bound, and done/total an underestimate of the fraction done.
  double total = 0.0;
  const char* unit = "";  // what done and total count: "periods", "points", ...
  // Where the work stands, if it has such a value (the continuation parameter); NaN if not.
  double value = std::numeric_limits<double>::quiet_NaN();
};

// Called as the work advances, from the thread doing it. A computation running on several
// threads (the sweep) calls it one call at a time, with `done` increasing, so the callback
// needs no lock of its own; it must return quickly (it is called often: throttle the drawing).
using ProgressCallback = std::function<void(const Progress&)>;

}  // namespace stickslip
