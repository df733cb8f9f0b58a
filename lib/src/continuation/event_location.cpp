#include "event_location.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include <boost/math/tools/roots.hpp>

namespace stickslip::detail {

namespace {

// Thrown inside location when the corrector fails at a trial arclength.
struct CorrectorFailure {};

// Narrows [*lo, *hi] by bisection while g is +inf ("none yet") at *lo, so that an interpolating
// solver may take over: the bracket then has finite values of opposite signs at both ends, or (g
// jumping from +inf straight to a negative value) is narrower than the tolerance at the jump, or
// has met a zero (*lo = *hi, *gb = 0).
template <typename G>
void BisectPastInfinity(G g_at, const EventLocationOptions& options, double* ga, double* gb, double* lo, double* hi) {
  while (std::isinf(*ga) && *hi - *lo > options.tolerance) {
    const double mid = 0.5 * (*lo + *hi);
    if (mid <= *lo || mid >= *hi) return;  // no double between them
    const double g_mid = g_at(mid);
    if (std::isnan(g_mid)) throw CorrectorFailure{};
    if (g_mid == 0.0) {
      *lo = *hi = mid;
      *gb = 0.0;
      return;
    }
    if (g_mid > 0.0) {
      *lo = mid;
      *ga = g_mid;
    } else {
      *hi = mid;
      *gb = g_mid;
    }
  }
}

// Narrows [*lo, *hi] = [0, ds] onto the zero; throws CorrectorFailure, leaving the bracket
// reached so far.
template <typename G>
void Bracket(const Event& event, G g_at, double ga, double gb, const EventLocationOptions& options, double* lo,
             double* hi) {
  if (event.sign_only) {
    double g_lo = ga;
    while (*hi - *lo > options.tolerance) {
      const double mid = 0.5 * (*lo + *hi);
      if (mid <= *lo || mid >= *hi) break;  // no double between them
      const double g_mid = g_at(mid);
      if (g_mid * g_lo > 0.0) {
        *lo = mid;
        g_lo = g_mid;
      } else {
        *hi = mid;
      }
    }
    return;
  }
  if (gb == 0.0) return;  // the zero is at b
  if (std::isinf(ga)) BisectPastInfinity(g_at, options, &ga, &gb, lo, hi);
  if (std::isfinite(ga) && gb != 0.0) {
    std::uintmax_t iterations = static_cast<std::uintmax_t>(options.max_iterations);
    const double tol = options.tolerance;
    std::tie(*lo, *hi) = boost::math::tools::toms748_solve(
        g_at, *lo, *hi, ga, gb, [tol](double x, double y) { return std::abs(y - x) <= tol; }, iterations);
  }
}

}  // namespace

std::optional<Located> Locate(const Event& event, const Sample& a, const Sample& b, double ds, double ga, double gb,
                              ArclengthCorrector& corrector, const EventLocationOptions& options) {
  // The narrowest bracket of the sign change that the trial points reached, and the function's
  // values at its ends: all that is known of the function next to the change where the corrector
  // fails before the bracket is narrowed to the tolerance.
  struct {
    double lo, g_lo, hi, g_hi;
  } reached{0.0, ga, ds, gb};
  auto g_at = [&](double s) {
    std::optional<Sample> p = corrector.Corrected(a, s, Attempt::kLocationTrial);
    if (!p) throw CorrectorFailure{};
    const double g = event.g(*p);
    if (g * ga > 0.0 && s > reached.lo) {
      reached.lo = s;
      reached.g_lo = g;
    } else if (g * ga <= 0.0 && s < reached.hi) {
      reached.hi = s;
      reached.g_hi = g;
    }
    return g;
  };
  Located l{0.0, &event, b, 0.0, ga, true, 0.0};
  double lo = 0.0, hi = ds;
  try {
    Bracket(event, g_at, ga, gb, options, &lo, &hi);
  } catch (const CorrectorFailure&) {
    l.located = false;
  }
  if (gb == 0.0) lo = hi = ds;  // the zero is at b
  l.bracket = hi - lo;
  // An event that could not be located is recorded at the step's end, b, and ordered there:
  // ordered at an interpolated arclength it could come before an end located inside the step,
  // and its point, beyond that end, would be reported (a BP at u_s < 0 past section 4.2's end).
  l.s = ds;
  if (l.located) {
    // A sign is located where it has changed; a continuous function in the bracket's middle.
    const double s = event.sign_only ? hi : 0.5 * (lo + hi);
    if (s != ds) {
      if (std::optional<Sample> p = corrector.Corrected(a, s, Attempt::kLocated)) {
        l.s = s;
        l.sample = std::move(*p);
      } else {
        l.located = false;
      }
    }
  }
  l.value = event.g(l.sample);
  // A sign change through a pole is no zero: next to the change the function is large, not small
  // (larger than at one end of the step at least; a pole next to one end leaves a value below the
  // other, as at a start on a grazing, where det(M + I) = -3.6e29 and the "located" PD had 2.3e9).
  // Next to the change is the located point, or, where the corrector failed inside the bracket (as
  // it may at the pole itself), the nearer in value of the narrowest bracket's ends: a zero is
  // approached by values that shrink, a pole by values that grow.
  if (event.may_have_poles && !event.sign_only) {
    const double next_to_change = l.located ? std::abs(l.value) : std::min(std::abs(reached.g_lo), std::abs(reached.g_hi));
    if (next_to_change > std::min(std::abs(ga), std::abs(gb))) return std::nullopt;
  }
  return l;
}

std::vector<std::vector<Located>> DetectAndLocate(const std::vector<Event>& events, const Sample& a, const Sample& b,
                                                  double ds, ArclengthCorrector& corrector,
                                                  const EventLocationOptions& options) {
  std::vector<Located> located;
  for (const Event& e : events) {
    const double ga = e.g(a);
    const double gb = e.g(b);
    if (!ChangesSign(e, ga, gb)) continue;
    if (std::optional<Located> l = Locate(e, a, b, ds, ga, gb, corrector, options)) located.push_back(std::move(*l));
  }
  std::sort(located.begin(), located.end(), [](const Located& x, const Located& y) { return x.s < y.s; });
  const double same_point = options.same_point * options.tolerance;
  std::vector<std::vector<Located>> points;
  for (std::size_t k = 0; k < located.size(); ++k) {
    if (k == 0 || located[k].s - located[k - 1].s > same_point) points.emplace_back();
    points.back().push_back(std::move(located[k]));
  }
  for (std::vector<Located>& point : points) {
    std::stable_sort(point.begin(), point.end(),
                     [](const Located& x, const Located& y) { return x.event->priority < y.event->priority; });
  }
  return points;
}

}  // namespace stickslip::detail
