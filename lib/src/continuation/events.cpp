#include "events.hpp"

#include <algorithm>
#include <cmath>

namespace stickslip::detail {

std::vector<Event> MakeEvents(const ContinuationOptions& o, const std::vector<TestFunctionInfo>& monitored) {
  std::vector<Event> events;
  const int lambda = o.parameter_index;
  if (o.detect_folds) {
    // Where the branch runs at constant lambda, the fold function is rounding noise around zero.
    events.push_back({"LP", "tangent:lambda", [lambda](const Sample& s) { return s.tangent(lambda); }, false, false,
                      false, o.location.fold_noise, 1});
  }
  if (o.detect_branch_points) {
    events.push_back({"BP", "det-bordered", [](const Sample& s) { return double(s.det_sign); }, true, false, false,
                      0.0, 2});
  }
  for (const UserValue& uz : o.user_values) {
    events.push_back({"UZ", uz.name, [uz](const Sample& s) { return s.u(uz.index) - uz.value; }, false, false, false,
                      0.0, 3});
  }
  for (int k = 0; k < static_cast<int>(monitored.size()); ++k) {
    const TestFunctionInfo& info = monitored[k];
    if (!info.detect) continue;
    events.push_back({info.type, info.name, [k](const Sample& s) { return s.tests(k); }, false,
                      info.terminal && !o.continue_past_terminal});
  }
  events.push_back({"EP", "lambda_max", [&o, lambda](const Sample& s) { return o.lambda_max - s.u(lambda); }, false,
                    false, true, 0.0, 4});
  events.push_back({"EP", "lambda_min", [&o, lambda](const Sample& s) { return s.u(lambda) - o.lambda_min; }, false,
                    false, true, 0.0, 4});
  return events;
}

bool ChangesSign(const Event& event, double ga, double gb) {
  if (!std::isfinite(ga) || !std::isfinite(gb) || ga * gb > 0.0 || ga == 0.0) return false;
  return std::max(std::abs(ga), std::abs(gb)) >= event.noise;
}

}  // namespace stickslip::detail
