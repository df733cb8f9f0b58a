// Transients simulated in chunks: the state after them is the state of one uninterrupted
// simulation at the same time, whatever the chunk size, for both simulators.
#include "stickslip/model/transient.hpp"

#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "stickslip/model/pascal_2014/odeint_simulator.hpp"
#include "stickslip/model/pascal_2014/paper_examples.hpp"

namespace stickslip {
namespace {

// The section 6 data with a start off its orbit: a motion with sticks and reversals.
TEST(SimulateTransient, EndsInTheStateOfOneUninterruptedSimulationWhateverTheChunks) {
  const PaperExample& e = *FindPaperExample("paper-6");
  const State x0 = e.initial_state + State(0.3, -0.2, 0.1, 0.0);
  const double period = 2.0 * std::numbers::pi / e.parameters.omega;
  SimulationOptions whole;
  whole.duration = 12 * period;
  const SimulationResult reference = SimulateExact(e.parameters, x0, e.phi, whole);
  ASSERT_TRUE(reference.Completed());
  ASSERT_GT(reference.events.size(), 12u);
  for (int chunk : {1, 5, 12, 1000}) {
    TransientOptions o;
    o.periods = 12;
    o.chunk_periods = chunk;
    const Transient t = SimulateTransient(SimulateExact, e.parameters, x0, e.phi, o);
    ASSERT_TRUE(t.Completed()) << t.message;
    EXPECT_DOUBLE_EQ(t.t, 12 * period);
    EXPECT_LT((t.state - reference.segments.back().end).lpNorm<Eigen::Infinity>(), 1e-9) << chunk;
  }
  // Odeint chunked against the exact simulator whole: independent of each other.
  TransientOptions o;
  o.periods = 12;
  o.chunk_periods = 5;
  const Transient odeint = SimulateTransient(
      [](const Parameters& p, const State& x, double phi, const SimulationOptions& so) {
        return SimulateOdeint(p, x, phi, so);
      },
      e.parameters, x0, e.phi, o);
  ASSERT_TRUE(odeint.Completed()) << odeint.message;
  EXPECT_LT((odeint.state - reference.segments.back().end).lpNorm<Eigen::Infinity>(), 1e-7);
}

TEST(SimulateTransient, NoPeriodsIsTheStartItself) {
  const PaperExample& e = *FindPaperExample("paper-4.1");
  const Transient t = SimulateTransient(SimulateExact, e.parameters, e.initial_state, e.phi, {});
  EXPECT_EQ(t.state, e.initial_state);
  EXPECT_EQ(t.t, 0.0);
}

// One progress line over all chunks: done rises from 0 to the whole transient.
TEST(SimulateTransient, ReportsProgressOverTheWholeTransient) {
  const PaperExample& e = *FindPaperExample("paper-4.1");
  TransientOptions o;
  o.periods = 6;
  o.chunk_periods = 2;
  std::vector<Progress> seen;
  o.simulation.progress = [&](const Progress& p) { seen.push_back(p); };
  ASSERT_TRUE(SimulateTransient(SimulateExact, e.parameters, e.initial_state, e.phi, o).Completed());
  ASSERT_GE(seen.size(), 6u);  // two stops a period
  for (std::size_t k = 1; k < seen.size(); ++k) EXPECT_GE(seen[k].done, seen[k - 1].done);
  for (const Progress& p : seen) EXPECT_EQ(p.total, 6.0);
  EXPECT_GT(seen.back().done, 5.0);
  EXPECT_LE(seen.back().done, 6.0 + 1e-9);
}

TEST(TransientOptions, RejectPeriodsOutOfRange) {
  for (int periods : {-1, kMaxTransientPeriods + 1}) {
    TransientOptions o;
    o.periods = periods;
    try {
      o.Validate();
      ADD_FAILURE() << periods << " accepted";
    } catch (const InvalidInput& error) {
      EXPECT_EQ(error.field(), "periods");
    }
  }
  TransientOptions o;
  o.chunk_periods = 0;
  EXPECT_THROW(o.Validate(), InvalidInput);
}

}  // namespace
}  // namespace stickslip
