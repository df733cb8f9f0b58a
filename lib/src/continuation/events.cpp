#include "events.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stickslip::detail {

std::vector<Event> MakeEvents(const ContinuationOptions& o, const std::vector<TestFunctionInfo>& monitored) {
  std::vector<Event> events;
  const int lambda = o.parameter_index;
  if (o.detect_folds) {
    // Where the branch runs at constant lambda, the fold function is rounding noise around zero.
    events.push_back({.type = "LP", .name = "tangent:lambda",
                      .g = [lambda](const Sample& s) { return s.tangent(lambda); },
                      .noise = o.location.fold_noise, .priority = 1});
  }
  if (o.detect_branch_points) {
    events.push_back({.type = "BP", .name = "det-bordered",
                      .g = [](const Sample& s) { return double(s.det_sign); }, .sign_only = true, .priority = 2});
  }
  for (const UserValue& uz : o.user_values) {
    events.push_back({.type = "UZ", .name = uz.name,
                      .g = [uz](const Sample& s) { return s.u(uz.index) - uz.value; }, .priority = 3});
  }
  for (int k = 0; k < static_cast<int>(monitored.size()); ++k) {
    const TestFunctionInfo& info = monitored[k];
    events.push_back({.type = info.type, .name = info.name, .g = [k](const Sample& s) { return s.tests(k); },
                      .terminal = info.domain_boundary || (info.terminal && !o.continue_past_terminal),
                      .may_have_poles = info.may_have_poles,
                      .positive_side = info.positive_side});
  }
  events.push_back({.type = "EP", .name = "lambda_max",
                    .g = [&o, lambda](const Sample& s) { return o.lambda_max - s.u(lambda); }, .bound = true,
                    .bound_index = lambda, .bound_name = o.parameter_name, .priority = 4});
  events.push_back({.type = "EP", .name = "lambda_min",
                    .g = [&o, lambda](const Sample& s) { return s.u(lambda) - o.lambda_min; }, .bound = true,
                    .bound_index = lambda, .bound_name = o.parameter_name, .priority = 4});
  for (const UnknownBound& b : o.unknown_bounds) {
    const int k = b.index;
    if (std::isfinite(b.max)) {
      events.push_back({.type = "EP", .name = b.name + "_max", .g = [k, max = b.max](const Sample& s) { return max - s.u(k); },
                        .bound = true, .bound_index = k, .bound_name = b.name, .priority = 4});
    }
    if (std::isfinite(b.min)) {
      events.push_back({.type = "EP", .name = b.name + "_min", .g = [k, min = b.min](const Sample& s) { return s.u(k) - min; },
                        .bound = true, .bound_index = k, .bound_name = b.name, .priority = 4});
    }
  }
  return events;
}

bool ChangesSign(const Event& event, double ga, double gb) {
  // +inf is "none yet" (a margin's interior minimum that does not exist); from there only a
  // negative value is a change. Any other infinity is no sign change (a pole's side, say).
  if (std::isinf(ga) || std::isinf(gb)) return ga == std::numeric_limits<double>::infinity() && gb < 0.0;
  if (std::isnan(ga) || std::isnan(gb) || ga * gb > 0.0 || ga == 0.0) return false;
  return std::max(std::abs(ga), std::abs(gb)) >= event.noise;
}

}  // namespace stickslip::detail
