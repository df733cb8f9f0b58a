// Appendix 1 of the paper: identities of H(t) and Gamma(t), and the matrix form of the flows
// (eqs. 5, 8, 10) against stickslip's spectral form.
#include "stickslip/model/pascal_2014/modal.hpp"

#include <random>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "stickslip/model/pascal_2014/flows.hpp"

namespace stickslip {
namespace {

Parameters Example() { return {0.3, 4.0, 0.6, 0.1, 0.2996}; }

Eigen::Matrix2d StiffnessMatrix(const Parameters& p) {  // K of eq. (56)
  Eigen::Matrix2d k;
  k << 1.0, -p.chi, -p.chi * p.eta, p.chi * p.eta;
  return k;
}

TEST(NaturalFrequencies, AreRootsOfTheCharacteristicEquation) {
  for (double chi : {0.1, 0.3, 0.7, 0.95}) {
    for (double eta : {0.2, 1.0, 4.0, 30.0}) {
      Parameters p = Example();
      p.chi = chi;
      p.eta = eta;
      const auto [w1, w2] = NaturalFrequencies(chi, eta);
      EXPECT_LT(w1, w2);
      const Eigen::Matrix2d k = StiffnessMatrix(p);
      for (double w : {w1, w2}) {
        EXPECT_NEAR((k - w * w * Eigen::Matrix2d::Identity()).determinant(), 0.0,
                    1e-13 * k.norm() * k.norm());
      }
      // (K - omega_j^2 I) psi_j = 0 for the columns of Lambda.
      const Eigen::Matrix2d lambda = ModalMatrix(chi, w1, w2);
      EXPECT_LT(((k - w1 * w1 * Eigen::Matrix2d::Identity()) * lambda.col(0)).norm(), 1e-12 * k.norm());
      EXPECT_LT(((k - w2 * w2 * Eigen::Matrix2d::Identity()) * lambda.col(1)).norm(), 1e-12 * k.norm());
    }
  }
}

TEST(ForcedResponse, SolvesTheHarmonicBalance) {
  const Parameters p = Example();
  const Eigen::Vector2d q = ForcedAmplitude(p.chi, p.eta, p.omega);
  // Q cos(omega t + phi) satisfies eq. (2) with u = 0: (K - omega^2 I) Q = (0, 1).
  const Eigen::Vector2d residual =
      (StiffnessMatrix(p) - p.omega * p.omega * Eigen::Matrix2d::Identity()) * q;
  EXPECT_NEAR(residual(0), 0.0, 1e-14);
  EXPECT_NEAR(residual(1), 1.0, 1e-14);
}

TEST(StaticOffset, BalancesTheSlidingFriction) {
  const Parameters p = Example();
  const Eigen::Vector2d d0 = StaticOffset(p.chi, p.u_s);
  const Eigen::Vector2d force = StiffnessMatrix(p) * d0;  // K d0 = (0, eta u_s), eq. (7)
  EXPECT_NEAR(force(0), 0.0, 1e-15);
  EXPECT_NEAR(force(1), p.eta * p.u_s, 1e-15);
}

class TransitionMatrices : public ::testing::Test {
 protected:
  std::mt19937 rng{20140267};
  std::uniform_real_distribution<double> time{-20.0, 20.0};
};

// H1^2 - H2 H3 = I (the paper prints "= 0" in eq. 57; ERRATA).
TEST_F(TransitionMatrices, SlipBlocksSatisfyTheDeterminantIdentity) {
  const Parameters p = Example();
  for (int i = 0; i < 50; ++i) {
    const Eigen::Matrix4d h = SlipTransition(p.chi, p.eta, time(rng));
    const Eigen::Matrix2d h1 = h.topLeftCorner<2, 2>();
    const Eigen::Matrix2d h2 = h.topRightCorner<2, 2>();
    const Eigen::Matrix2d h3 = h.bottomLeftCorner<2, 2>();
    EXPECT_LT((h1 * h1 - h2 * h3 - Eigen::Matrix2d::Identity()).norm(), 1e-12);
  }
}

// Gamma1^2 - Gamma2 Gamma3 = I (eq. 59 prints "= 0"; ERRATA).
TEST_F(TransitionMatrices, StickBlocksSatisfyTheDeterminantIdentity) {
  const Parameters p = Example();
  for (int i = 0; i < 50; ++i) {
    const Eigen::Matrix4d g = StickTransition(p.chi, time(rng));
    const Eigen::Matrix2d g1 = g.topLeftCorner<2, 2>();
    const Eigen::Matrix2d g2 = g.topRightCorner<2, 2>();
    const Eigen::Matrix2d g3 = g.bottomLeftCorner<2, 2>();
    EXPECT_LT((g1 * g1 - g2 * g3 - Eigen::Matrix2d::Identity()).norm(), 1e-12);
  }
}

TEST_F(TransitionMatrices, AreTheIdentityAtTimeZero) {
  const Parameters p = Example();
  // Lambda diag(1) Lambda^{-1} is the identity up to rounding.
  EXPECT_LT((SlipTransition(p.chi, p.eta, 0.0) - Eigen::Matrix4d::Identity()).norm(), 1e-15);
  EXPECT_EQ(StickTransition(p.chi, 0.0), Eigen::Matrix4d::Identity());
}

TEST_F(TransitionMatrices, ComposeAsFlows) {
  const Parameters p = Example();
  for (int i = 0; i < 20; ++i) {
    const double t = time(rng);
    const double s = time(rng);
    EXPECT_LT((SlipTransition(p.chi, p.eta, t + s) -
               SlipTransition(p.chi, p.eta, t) * SlipTransition(p.chi, p.eta, s)).norm(), 1e-11);
    EXPECT_LT((StickTransition(p.chi, t + s) - StickTransition(p.chi, t) * StickTransition(p.chi, s))
                  .norm(), 1e-11);
  }
}

// Z(t) = H(t)(Z0 - F0) + F(t), Z = (X - d0, X') for slip- (eq. 5); Zbar = Z + 2 Delta0 for
// slip+ (eq. 8); X(t) = Gamma(t) X0 in a stick (eq. 10).
TEST_F(TransitionMatrices, GiveTheSameFlowsAsTheSpectralForm) {
  const Parameters p = Example();
  std::uniform_real_distribution<double> value(-3.0, 3.0);
  for (Mode mode : {Mode::kSlipNegative, Mode::kSlipPositive, Mode::kStick}) {
    for (int i = 0; i < 20; ++i) {
      State x0(value(rng), value(rng), value(rng), mode == Mode::kStick ? 0.0 : value(rng));
      const double phase = value(rng);
      const double t = std::abs(time(rng));
      State expected;
      if (mode == Mode::kStick) {
        expected = StickTransition(p.chi, t) * x0;
      } else {
        const Eigen::Vector2d q = ForcedAmplitude(p.chi, p.eta, p.omega);
        auto forcing = [&](double s) {  // F(s) = (R, R'), R = Q cos(omega s + phase), eq. (5)
          State f;
          f << q * std::cos(p.omega * s + phase), -p.omega * q * std::sin(p.omega * s + phase);
          return f;
        };
        State offset = State::Zero();  // Delta0 = (d0, 0), sign by eq. (5), (8)
        offset.head<2>() = StaticOffset(p.chi, p.u_s) * (mode == Mode::kSlipNegative ? 1.0 : -1.0);
        expected = SlipTransition(p.chi, p.eta, t) * (x0 - offset - forcing(0.0)) + forcing(t) + offset;
      }
      const State actual = Flow(mode, x0, phase, t, p);
      EXPECT_LT((actual - expected).lpNorm<Eigen::Infinity>(), 1e-11 * (1.0 + expected.norm()))
          << ToString(mode) << " at t = " << t;
    }
  }
}

}  // namespace
}  // namespace stickslip
