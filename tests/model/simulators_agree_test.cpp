// The exact simulator against the independent Odeint simulator on random data, starting states
// and phases (u_r > u_s, where no tangency makes the outcome a matter of rounding).
#include <random>

#include <gtest/gtest.h>

#include "stickslip/model/pascal_2014/odeint_simulator.hpp"
#include "stickslip/model/simulation.hpp"

namespace stickslip {
namespace {

TEST(SimulatorsAgree, OnRandomRunsWithDistinctFrictionLevels) {
  std::mt19937 rng(1291);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int runs = 0;
  std::size_t events = 0;
  while (runs < 60) {
    Parameters p{0.1 + 0.8 * u(rng), 0.5 + 4.5 * u(rng), 0.2 + 1.8 * u(rng), 0.01 + 0.2 * u(rng), 0.0};
    p.u_r = p.u_s * (1.1 + 2.0 * u(rng));
    if (Validate(p)) continue;
    const State x0(4 * u(rng) - 2, 4 * u(rng) - 2, 4 * u(rng) - 2, 4 * u(rng) - 2);
    const double phi = 6.28 * u(rng);
    SimulationOptions options;
    options.duration = 60.0;
    const SimulationResult exact = SimulateExact(p, x0, phi, options);
    const SimulationResult odeint = SimulateOdeint(p, x0, phi, options);
    ++runs;
    events += exact.events.size();
    ASSERT_EQ(exact.events.size(), odeint.events.size()) << "run " << runs;
    for (std::size_t i = 0; i < exact.events.size(); ++i) {
      EXPECT_EQ(exact.events[i].mode_after, odeint.events[i].mode_after) << "run " << runs;
      EXPECT_NEAR(exact.events[i].t, odeint.events[i].t, 1e-6) << "run " << runs << " event " << i;
    }
  }
  EXPECT_GT(events, 600u);  // the runs are full of stops and sticks, not idle
}

}  // namespace
}  // namespace stickslip
