// A chain of masses, springs and dampers (model/chain.hpp) as the matrices of the linear
// oscillator, against the matrices written by hand: M. Pascal's two masses, and a three-mass chain
// whose contact is on its first mass (put last, its name kept).
#include "stickslip/model/chain.hpp"

#include <string>

#include <gtest/gtest.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/model/linear_oscillator.hpp"

namespace stickslip {
namespace {

TEST(Chain, TwoMassesAreThoseOfThePapersOscillator) {
  // ground -k1- m1 -k2- m2, F0 cos on m2, the contact on m2: M = diag(m1, m2),
  // K = [[k1 + k2, -k2], [-k2, k2]] (../shared/FRICTION-LITERATURE.md).
  const Chain chain{{3.0, 2.0}, {{0, kGround, 5.0}, {0, 1, 7.0}}, {{1, kGround, 0.25}}, {0.0, 4.0}, 1, {}};
  const LinearOscillatorData data = ChainData(chain);
  EXPECT_EQ(data.mass, Eigen::Vector2d(3.0, 2.0).asDiagonal().toDenseMatrix());
  EXPECT_EQ(data.stiffness, (Eigen::Matrix2d() << 12.0, -7.0, -7.0, 7.0).finished());
  EXPECT_EQ(data.damping, (Eigen::Matrix2d() << 0.0, 0.0, 0.0, 0.25).finished());
  EXPECT_EQ(data.forcing, Eigen::Vector2d(0.0, 4.0));
  EXPECT_EQ(data.coordinates, (std::vector<std::string>{"m1", "m2"}));
  EXPECT_NO_THROW(LinearOscillator<2>{data});
}

TEST(Chain, PutsTheContactsMassLastAndKeepsEveryName) {
  // ground -1- a -2- b -3- c, dampers a-ground 0.1 and b-c 0.2, forcing on c, the contact on a.
  const Chain chain{{1.0, 2.0, 3.0},
                    {{0, kGround, 1.0}, {0, 1, 2.0}, {1, 2, 3.0}},
                    {{0, kGround, 0.1}, {1, 2, 0.2}},
                    {0.0, 0.0, 1.5},
                    0,
                    {"a", "b", "c"}};
  const LinearOscillatorData data = ChainData(chain);
  // In the order b, c, a.
  EXPECT_EQ(data.coordinates, (std::vector<std::string>{"b", "c", "a"}));
  EXPECT_EQ(data.mass, Eigen::Vector3d(2.0, 3.0, 1.0).asDiagonal().toDenseMatrix());
  EXPECT_EQ(data.stiffness, (Eigen::Matrix3d() << 5.0, -3.0, -2.0, -3.0, 3.0, 0.0, -2.0, 0.0, 3.0).finished());
  EXPECT_EQ(data.damping, (Eigen::Matrix3d() << 0.2, -0.2, 0.0, -0.2, 0.2, 0.0, 0.0, 0.0, 0.1).finished());
  EXPECT_EQ(data.forcing, Eigen::Vector3d(0.0, 1.5, 0.0));
  EXPECT_EQ(LinearOscillator<3>(data).Description().coordinates, data.coordinates);
}

void ExpectRejected(const Chain& chain, const std::string& field) {
  try {
    const LinearOscillator<2> model(ChainData(chain));
    ADD_FAILURE() << "accepted, expected a complaint about " << field;
  } catch (const InvalidInput& e) {
    EXPECT_EQ(std::string(e.what()).rfind(field, 0), 0u) << e.what();
  }
}

TEST(Chain, RejectsWhatIsNoChainNamingTheField) {
  const Chain good{{1.0, 1.0}, {{0, kGround, 1.0}, {0, 1, 1.0}}, {}, {0.0, 1.0}, 1, {}};
  Chain bad = good;
  bad.masses[1] = 0.0;
  ExpectRejected(bad, "masses[1]");
  bad = good;
  bad.springs[1].to = 0;  // to itself
  ExpectRejected(bad, "springs[1]");
  bad = good;
  bad.springs[0].from = 2;  // no such mass
  ExpectRejected(bad, "springs[0]");
  bad = good;
  bad.dampers = {{0, 1, -0.1}};
  ExpectRejected(bad, "dampers[0]");
  bad = good;
  bad.contact = 2;
  ExpectRejected(bad, "contact");
  bad = good;
  bad.forcing = {1.0};
  ExpectRejected(bad, "forcing");
  bad = good;
  bad.springs = {{0, 1, 1.0}};  // not held to the ground: a rigid-body mode
  ExpectRejected(bad, "stiffness");
  bad = good;
  bad.names = {"m1", "m1"};
  ExpectRejected(bad, "names");
  bad = good;
  bad.names = {"m1", "m2'"};  // its velocity would be named m2'' and could meet another's
  ExpectRejected(bad, "names");
  bad = good;
  bad.springs = {{0, kGround, 1e308}, {0, kGround, 1e308}};
  ExpectRejected(bad, "springs");
  bad = good;
  bad.contact = 2147483647;  // the largest int: the message's 1-based number must not overflow
  ExpectRejected(bad, "contact = 2147483648");
}

}  // namespace
}  // namespace stickslip
