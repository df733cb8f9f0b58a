// The linear oscillator with one Coulomb contact (model/linear_oscillator.hpp), against what is
// independent of its closed forms: M. Pascal's model through its own code after the paper's
// scaling (../shared/FRICTION-LITERATURE.md), the Odeint integration of M q'' + K q = g cos + F on
// random models, central differences of its flows, and its data checks.
#include "stickslip/model/linear_oscillator.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <random>
#include <vector>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "stickslip/model/exact_simulator.hpp"
#include "stickslip/model/odeint_simulation.hpp"
#include "stickslip/orbits/orbit_system.hpp"
#include "stickslip/orbits/periodicity_equations.hpp"
#include "stickslip/orbits/stability.hpp"
#include "stickslip/orbits/model_orbit_problem.hpp"
#include "support/general_models.hpp"
#include "support/pascal_in_physical_units.hpp"
#include "support/solved_presets.hpp"
#include "support/sanitized_build.hpp"
#include "support/test_names.hpp"

namespace stickslip {
namespace {

static_assert(IntegrableOscillatorModel<LinearOscillator<2>>);
static_assert(IntegrableOscillatorModel<LinearOscillator<3>>);

class PascalInPhysicalUnits : public testing::TestWithParam<const char*> {};

// The paper's orbit, converted, solves the general model's periodicity equations; Newton from a
// perturbed guess comes back to it within 1e-10 after conversion; and the Floquet multipliers
// (invariant under the scaling, a similarity of the monodromy) agree with the paper model's; at a
// fixed size and sized at run time.
template <typename Model>
void ExpectThePaperOrbitAfterItsScaling(const char* preset) {
  const Orbit paper = SolvedPreset(preset);
  const PhysicalTwoMasses physical;
  const Model model(physical.Data(paper.parameters));
  const BasicOrbit<Model> orbit = InPhysicalUnits<Model>(paper, physical);
  ASSERT_FALSE(model.Validate(orbit.parameters));
  using Equations = BasicPeriodicityEquations<Model>;
  const Equations equations(model, orbit.signature, Shooting::kSingle);
  Eigen::VectorXd residual;
  equations.Evaluate(VariablesOf(equations, orbit), &residual, nullptr);
  EXPECT_LT(residual.template lpNorm<Eigen::Infinity>(), 1e-10 * physical.Length(paper.parameters));

  std::vector<int> free(equations.Parameter(0));
  std::iota(free.begin(), free.end(), 0);
  const BasicOrbitSystem<Model> system(equations, VariablesOf(equations, orbit), free, false);
  Eigen::VectorXd guess = system.Unknowns(VariablesOf(equations, orbit));
  guess(0) *= 1.001;
  guess(equations.Phi()) += 1e-3;
  const NewtonResult solved = SolveNewton(system, guess);
  ASSERT_TRUE(solved.summary.Converged()) << solved.summary.message;
  const Eigen::VectorXd v = system.Variables(solved.solution);
  const double length = physical.Length(paper.parameters), omega = physical.Omega(paper.parameters);
  EXPECT_NEAR(v(0) / length, paper.x10, 1e-10);
  EXPECT_NEAR(v(1) / length, paper.x20, 1e-10);
  EXPECT_NEAR(v(2) / (length * omega), paper.v10, 1e-10);
  EXPECT_NEAR(std::remainder(v(equations.Phi()) - paper.phi, 2 * std::numbers::pi), 0.0, 1e-10);
  for (std::size_t i = 0; i < paper.durations.size(); ++i) {
    EXPECT_NEAR(v(equations.Duration(static_cast<int>(i))) * omega, paper.durations[i], 1e-10) << "segment " << i;
  }

  const auto general = StabilityOf(model, orbit).multipliers;
  const auto scaled = StabilityOf(paper).multipliers;
  for (std::size_t i = 0; i < scaled.size(); ++i) EXPECT_LT(std::abs(general[i] - scaled[i]), 1e-9) << "multiplier " << i;
}

TEST_P(PascalInPhysicalUnits, IsTheSameOrbitAsThePaperModelsAfterItsScaling) {
  ExpectThePaperOrbitAfterItsScaling<LinearOscillator<2>>(GetParam());
  ExpectThePaperOrbitAfterItsScaling<DynamicLinearOscillator>(GetParam());
}

INSTANTIATE_TEST_SUITE_P(PaperOrbits, PascalInPhysicalUnits, testing::Values("paper-4.1", "paper-5.1", "paper-6"),
                         PresetTestName);

// A random model of n coordinates: M = A A^T + I, K = B B^T + I (both positive definite),
// forcing on every coordinate; with `damped`, a random damping matrix, not symmetric (as friction
// coupling makes it in brake models), with a positive definite symmetric part.
LinearOscillatorData RandomMasses(std::mt19937& random, int n, bool damped = false) {
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  auto draw = [&] { return entry(random); };
  const Eigen::MatrixXd a = Eigen::MatrixXd::NullaryExpr(n, n, draw), b = Eigen::MatrixXd::NullaryExpr(n, n, draw);
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(n, n);
  LinearOscillatorData data;
  data.mass = a * a.transpose() + identity;
  data.stiffness = 2.0 * (b * b.transpose() + identity);
  data.forcing = Eigen::VectorXd::NullaryExpr(n, draw);
  if (damped) {
    const Eigen::MatrixXd c = Eigen::MatrixXd::NullaryExpr(n, n, draw);
    data.damping = 0.1 * (c * c.transpose() + identity) + 0.05 * (c - c.transpose());
    data.friction_slope = 0.2 * entry(random);  // friction rising or falling with the slip speed
  }
  return data;
}
LinearOscillatorData RandomThreeMasses(std::mt19937& random, bool damped = false) { return RandomMasses(random, 3, damped); }

// The exact simulator (the closed forms in the modal bases) and Odeint (the equations of motion
// solved with M at every step, sharing no flow or event code) agree on every stop, stick and stick
// exit over five forcing periods, from near rest, on random models of n coordinates (six trials):
// undamped or damped; forced, or (`autonomous`) unforced on a belt at a random speed, the contact
// starting with the belt's speed (self-excited stick-slip).
template <typename Model>
int ExpectExactFlowsAgreeWithOdeint(std::uint32_t seed, int n, bool damped, bool autonomous = false) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int events = 0;
  for (int trial = 0; trial < 6; ++trial) {
    LinearOscillatorData data = RandomMasses(random, n, damped);
    if (autonomous) data.forcing.setZero();
    // Damped on a belt, friction falling with the slip speed: steady sliding unstable, so the
    // motion keeps sticking (with c + alpha > 0 it may settle into sliding without a stop).
    if (autonomous && damped) data.friction_slope = -0.4 - 0.4 * unit(random);
    const Model model(data);
    const typename Model::Parameters p{0.3 + 2.0 * unit(random), 0.05 + 0.3 * unit(random), 0.0,
                                       autonomous ? 0.2 + unit(random) : 0.0};
    typename Model::Parameters q = p;
    q.F_s = p.F_k * (1.0 + unit(random));
    if (model.Validate(q)) continue;
    BasicSimulationOptions<typename Model::State> options;
    // Without forcing omega means nothing: 20 time units (a few stick-slip cycles; the unstable
    // sliding between grows the integrator's error with them).
    options.duration = autonomous ? 20.0 : 5.0 * 2.0 * std::numbers::pi / q.omega;
    typename Model::State start = FilledState(model, 0.0);
    start.head(n) = Eigen::VectorXd::NullaryExpr(n, [&] { return unit(random) - 0.5; });
    // On a belt, the contact starts carried by it: the spring forces grow until the stick ends.
    if (autonomous) start(2 * n - 1) = q.v_b;
    const double phi = 2.0 * std::numbers::pi * unit(random);
    const auto a = SimulateExact(model, q, start, phi, options);
    const auto b = SimulateOdeint(model, q, start, phi, options);
    EXPECT_TRUE(a.Completed()) << a.message;
    EXPECT_TRUE(b.Completed()) << b.message;
    EXPECT_EQ(a.events.size(), b.events.size()) << "trial " << trial;
    if (!a.Completed() || !b.Completed() || a.events.size() != b.events.size()) return 0;
    for (std::size_t i = 0; i < a.events.size(); ++i) {
      EXPECT_EQ(a.events[i].mode_after, b.events[i].mode_after) << "trial " << trial << ", event " << i;
      EXPECT_NEAR(a.events[i].t, b.events[i].t, 1e-7) << "trial " << trial << ", event " << i;
      EXPECT_LT((a.events[i].state - b.events[i].state).template lpNorm<Eigen::Infinity>(), 1e-7) << "trial " << trial;
    }
    events += static_cast<int>(a.events.size());
  }
  return events;
}

class RandomThreeMassModels : public testing::TestWithParam<bool> {};

TEST_P(RandomThreeMassModels, ExactFlowsAgreeWithOdeint) {
  const std::uint32_t seed = GetParam() ? 77 : 20261128;
  EXPECT_GT(ExpectExactFlowsAgreeWithOdeint<LinearOscillator<3>>(seed, 3, GetParam()), 20) << "the models must stop";
  EXPECT_GT(ExpectExactFlowsAgreeWithOdeint<DynamicLinearOscillator>(seed, 3, GetParam()), 20) << "sized at run time";
}

// The same on models sized at run time (DynamicLinearOscillator) of one to six coordinates,
// undamped and damped, forced, and unforced on a belt (self-excited stick-slip). The sanitized
// build (72 s here against 4 s) checks one, three and six coordinates.
TEST(DynamicLinearOscillator, ExactFlowsAgreeWithOdeintOnRandomModelsOfOneToSixCoordinates) {
  const std::vector<int> sizes = kSanitizedBuild ? std::vector<int>{1, 3, 6} : std::vector<int>{1, 2, 3, 4, 5, 6};
  for (const int n : sizes) {
    for (const bool damped : {false, true}) {
      for (const bool autonomous : {false, true}) {
        SCOPED_TRACE(fmt::format("n = {}, {}, {}", n, damped ? "damped" : "undamped", autonomous ? "on a belt" : "forced"));
        const int events = ExpectExactFlowsAgreeWithOdeint<DynamicLinearOscillator>(
            static_cast<std::uint32_t>(1000 + 4 * n + 2 * damped + autonomous), n, damped, autonomous);
        EXPECT_GT(events, 6) << "the models must stop and stick";
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Damping, RandomThreeMassModels, testing::Bool(),
                         [](const testing::TestParamInfo<bool>& case_info) { return case_info.param ? "Damped" : "Undamped"; });

// Every derivative of a flow against central differences of the flow, in each mode, on a random
// three-mass model, away from rest so that no term vanishes by symmetry; and the transition
// matrix (the flow without forcing or friction) against the flow's derivative in its start.
// Undamped, a slip's natural frequencies are sqrt of the generalised eigenvalues of K x = w^2 M x
// (Eigen's self-adjoint solver: independent of the model's first-order bases); damped, none (an
// orbit's amplitude stays bounded there).
TEST(LinearOscillator, UndampedSlipFrequenciesAreTheGeneralisedEigenvaluesOfStiffnessAndMass) {
  std::mt19937 random(17);
  for (int trial = 0; trial < 5; ++trial) {
    const LinearOscillatorData data = RandomThreeMasses(random);
    const LinearOscillator<3> model(data);
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(data.stiffness, data.mass);
    const std::vector<double> omega = model.UndampedSlipFrequencies({});
    ASSERT_EQ(omega.size(), 3u);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(omega[k], std::sqrt(modes.eigenvalues()(k)), 1e-12 * omega[k]) << k;
    EXPECT_TRUE(LinearOscillator<3>(RandomThreeMasses(random, true)).UndampedSlipFrequencies({}).empty());
  }
}

// A mass on a belt whose kinetic friction falls with the slip speed, F_k + alpha |s| (alpha < 0).
// Slipping backwards (s = x' - v_b < 0) it obeys m x'' + (c + alpha) x' + k x = F_k + alpha v_b:
// the damped oscillator about steady sliding x* = (F_k + alpha v_b)/k, rate zeta = (c + alpha)/2m,
// x(t) = x* + e^{-zeta t} (A cos w_d t + B sin w_d t) (closed form, independent of the modal
// bases). With c + alpha < 0 steady sliding is unstable: the motion about it grows.
TEST(LinearOscillator, FrictionFallingWithSlipSpeedIsNegativeDampingOfTheSlip) {
  const double m = 2.0, k = 3.0, c = 0.1, v_b = 1.5;
  for (const double alpha : {0.3, -0.4}) {
    LinearOscillatorData data;
    data.mass = Eigen::MatrixXd::Constant(1, 1, m);
    data.stiffness = Eigen::MatrixXd::Constant(1, 1, k);
    data.damping = Eigen::MatrixXd::Constant(1, 1, c);
    data.forcing = Eigen::VectorXd::Zero(1);
    data.friction_slope = alpha;
    const LinearOscillator<1> model(data);
    const LinearOscillator<1>::Parameters p{1.0, 0.5, 0.8, v_b};
    const double steady = (p.F_k + alpha * v_b) / k, zeta = (c + alpha) / (2.0 * m);
    const double w_d = std::sqrt(k / m - zeta * zeta);
    const Eigen::Vector2d start(steady + 0.05, 0.2);  // x' < v_b: slipping backwards
    const double a = start(0) - steady, b = (start(1) + zeta * a) / w_d;
    for (const double t : {0.3, 1.1, 2.5}) {
      const double x = steady + std::exp(-zeta * t) * (a * std::cos(w_d * t) + b * std::sin(w_d * t));
      const double v = std::exp(-zeta * t) * ((b * w_d - zeta * a) * std::cos(w_d * t) - (a * w_d + zeta * b) * std::sin(w_d * t));
      const Eigen::Vector2d flow = model.Flow(Mode::kSlipNegative, start, 0.0, t, p);
      EXPECT_NEAR(flow(0), x, 1e-12) << "alpha = " << alpha << ", t = " << t;
      EXPECT_NEAR(flow(1), v, 1e-12) << "alpha = " << alpha << ", t = " << t;
    }
    const Eigen::Vector2d later = model.Flow(Mode::kSlipNegative, start, 0.0, 2.0 * std::numbers::pi / w_d, p);
    EXPECT_EQ(std::abs(later(0) - steady) > std::abs(start(0) - steady), c + alpha < 0.0) << "alpha = " << alpha;
    // The slip is damped (by alpha): no undamped slip frequency. The friction's levels as given.
    EXPECT_TRUE(model.UndampedSlipFrequencies(p).empty());
    EXPECT_EQ(model.KineticForce(p), p.F_k);
    EXPECT_EQ(model.FrictionSlope(), alpha);
  }
  LinearOscillatorData bad;
  bad.mass = bad.stiffness = Eigen::MatrixXd::Ones(1, 1);
  bad.forcing = Eigen::VectorXd::Zero(1);
  bad.friction_slope = std::numeric_limits<double>::quiet_NaN();
  try {
    LinearOscillator<1> refused(bad);
    ADD_FAILURE() << "friction_slope = nan accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "friction_slope");
  }
}

// At both sizes: fixed at compile time, and read with the data (DynamicLinearOscillator).
template <typename Model>
class LinearOscillatorOfEitherSize : public testing::Test {};
using ThreeMassSizes = testing::Types<LinearOscillator<3>, DynamicLinearOscillator>;
TYPED_TEST_SUITE(LinearOscillatorOfEitherSize, ThreeMassSizes, ModelSizeName);

TYPED_TEST(LinearOscillatorOfEitherSize, FlowDerivativesAreTheCentralDifferencesOfItsFlows) {
  using State = typename TypeParam::State;
  std::mt19937 random(7);
  const TypeParam model(RandomThreeMasses(random, true));
  const typename TypeParam::Parameters p{0.77, 0.2, 0.3};
  State x(6);
  x << 0.3, -0.2, 0.1, 0.4, 0.25, -0.15;
  const double phase = 0.9, s = 1.7, h = 1e-6;
  for (Mode mode : {Mode::kSlipNegative, Mode::kSlipPositive, Mode::kStick}) {
    const auto d = model.FlowWithDerivatives(mode, x, phase, s, p);
    EXPECT_LT((d.state - model.Flow(mode, x, phase, s, p)).norm(), 1e-14);
    for (int j = 0; j < 6; ++j) {
      const State e = State::Unit(6, j) * h;
      const State difference =
          (model.Flow(mode, State(x + e), phase, s, p) - model.Flow(mode, State(x - e), phase, s, p)) / (2 * h);
      EXPECT_LT((difference - d.d_start.col(j)).norm(), 1e-7) << "start " << j;
    }
    EXPECT_LT((model.TransitionMatrix(mode, s, p) - d.d_start).norm(), 1e-12);
    const State time = (model.Flow(mode, x, phase, s + h, p) - model.Flow(mode, x, phase, s - h, p)) / (2 * h);
    EXPECT_LT((time - d.d_elapsed).norm(), 1e-7);
    const State along_phase = (model.Flow(mode, x, phase + h, s, p) - model.Flow(mode, x, phase - h, s, p)) / (2 * h);
    EXPECT_LT((along_phase - d.d_phase).norm(), 1e-7);
    for (int k = 0; k < 4; ++k) {
      auto up = p, down = p;
      TypeParam::ParameterAt(up, k) += h;
      TypeParam::ParameterAt(down, k) -= h;
      const State difference = (model.Flow(mode, x, phase, s, up) - model.Flow(mode, x, phase, s, down)) / (2 * h);
      EXPECT_LT((difference - d.d_parameters.col(k)).norm(), 1e-7) << "parameter " << k;
    }
  }
}

// In a stick the held coordinate does not move and the holding force, written from the closed
// forms, is the one the equations of motion give (the integrator's).
TEST(LinearOscillator, StickHoldsTheContactWithTheForceTheEquationsOfMotionNeed) {
  std::mt19937 random(11);
  const LinearOscillator<3> model(RandomThreeMasses(random, true));
  const LinearOscillator<3>::Parameters p{1.3, 0.2, 10.0};
  LinearOscillator<3>::State x;
  x << 0.3, -0.2, 0.1, 0.4, 0.25, 0.0;
  const LinearOscillator<3>::Motion motion = model.MotionInMode(Mode::kStick, x, 0.4, p);
  const ExponentialSum force = model.StickForceAlong(motion, 0.4, p);
  for (double s : {0.0, 0.5, 2.0}) {
    const LinearOscillator<3>::State y = motion.StateAt(s);
    EXPECT_NEAR(y(2), 0.1, 1e-14);
    EXPECT_NEAR(y(5), 0.0, 1e-14);
    const double psi = 0.4 + p.omega * s;
    EXPECT_NEAR(model.StickForce(y, psi, p), model.HoldingForce(y, psi, p), 1e-12);
    EXPECT_NEAR(force(s), model.HoldingForce(y, psi, p), 1e-12);
    EXPECT_NEAR(model.StickForceRate(y, psi, p), model.HoldingForceRate(y, psi, p), 1e-12);
  }
}

LinearOscillatorData TwoMasses() {
  LinearOscillatorData data;
  data.mass = Eigen::Matrix2d::Identity();
  data.stiffness = (Eigen::Matrix2d() << 2.0, -1.0, -1.0, 1.0).finished();
  data.forcing = Eigen::Vector2d(0.0, 1.0);
  return data;
}

void ExpectRejected(const LinearOscillatorData& data, const std::string& field) {
  try {
    const LinearOscillator<2> model(data);
    ADD_FAILURE() << "accepted, expected a complaint about " << field;
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()).rfind(field, 0), 0u) << e.what();
  }
}

TEST(LinearOscillator, RejectsDataThatIsNotAnOscillatorNamingTheField) {
  LinearOscillatorData bad = TwoMasses();
  bad.mass(0, 1) = 0.5;
  ExpectRejected(bad, "mass");  // not symmetric
  bad = TwoMasses();
  bad.mass(1, 1) = -1.0;
  ExpectRejected(bad, "mass");  // not positive definite
  bad = TwoMasses();
  bad.stiffness(0, 0) = std::numeric_limits<double>::quiet_NaN();
  ExpectRejected(bad, "stiffness");
  bad = TwoMasses();
  bad.stiffness = Eigen::Matrix2d::Ones();  // singular: a rigid-body mode, not yet served
  ExpectRejected(bad, "stiffness");
  bad = TwoMasses();
  bad.forcing = Eigen::Vector3d::Ones();
  ExpectRejected(bad, "forcing");
  bad = TwoMasses();
  bad.coordinates = {"x", "x"};
  ExpectRejected(bad, "coordinates");
  bad = TwoMasses();
  bad.coordinates = {"a", "a'"};  // a' would name the first coordinate's velocity too
  ExpectRejected(bad, "coordinates");
  bad = TwoMasses();
  bad.damping = 2.0 * std::sqrt(2.0) * Eigen::Matrix2d::Identity();  // the stick (k = 2, m = 1) critically damped: a defective mode
  ExpectRejected(bad, "damping");
  bad = TwoMasses();
  bad.mass *= 1e-300;
  bad.stiffness *= 1e300;  // M^-1 K overflows
  ExpectRejected(bad, "stiffness");
  bad = TwoMasses();
  bad.mass = Eigen::Matrix3d::Identity();
  ExpectRejected(bad, "mass");  // three coordinates for a model of two
  // A slip critically damped by the friction slope alone (one mass, m = k = 1, alpha = 2 sqrt(k m)):
  // the refusal names the slope, not the dampers the model does not have.
  LinearOscillatorData one;
  one.mass = one.stiffness = Eigen::MatrixXd::Ones(1, 1);
  one.forcing = Eigen::VectorXd::Ones(1);
  one.friction_slope = 2.0;
  try {
    const LinearOscillator<1> model(one);
    ADD_FAILURE() << "a critically damped slip accepted";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()).rfind("friction_slope", 0), 0u) << e.what();
  }
}

TEST(LinearOscillator, RefusesAForcingFrequencyOnANaturalFrequencyOfASlipOrAStick) {
  const LinearOscillator<2> model(TwoMasses());
  const double slip = std::sqrt((3.0 - std::sqrt(5.0)) / 2.0), stick = std::sqrt(2.0);  // eigenvalues of K; K_11
  // On it, and within the relative gap where the forced and free motions' cancellation costs accuracy.
  for (double omega : {slip, stick, slip * (1.0 + 5e-7), stick * (1.0 - 5e-7)}) {
    const auto invalid = model.Validate({omega, 0.1, 0.1});
    ASSERT_TRUE(invalid);
    EXPECT_EQ(std::string(invalid->what()).rfind("omega", 0), 0u) << invalid->what();
  }
  EXPECT_FALSE(model.Validate({1.0, 0.1, 0.2}));
  EXPECT_TRUE(model.Validate({1.0, 0.2, 0.1}));  // static below kinetic
  EXPECT_FALSE(model.Validate({slip * (1.0 + 2e-6), 0.1, 0.2}));
  LinearOscillatorData autonomous = TwoMasses();
  autonomous.forcing.setZero();
  const LinearOscillator<2> free(autonomous);
  EXPECT_FALSE(free.Validate({slip, 0.1, 0.2}));  // without forcing omega plays no part
  for (double omega : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), -1.0}) {
    EXPECT_TRUE(free.Validate({omega, 0.1, 0.2})) << "omega = " << omega;  // but must be a number
  }
  EXPECT_EQ(model.Description().initial_state, (std::vector<std::string>{"x1_0", "x2_0", "v1_0", "v2_0"}));
}

}  // namespace
}  // namespace stickslip
