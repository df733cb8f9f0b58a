// The periodicity equations: exact Jacobian against finite differences for every kind of
// segment end, single against multiple shooting, dense against sparse solvers.
#include "stickslip/orbits/periodicity.hpp"

#include <Eigen/QR>
#include <Eigen/SVD>
#include <gtest/gtest.h>

#include "stickslip/orbits/orbit_solver.hpp"
#include "stickslip/orbits/paper_presets.hpp"
#include "support/central_differences.hpp"

namespace stickslip {
namespace {

namespace ov = orbit_variables;

// A signature with every end kind: abnormal stop, reversal, stick entry, exit into slip+, exit
// into slip-; evaluated away from any solution, where every term of the Jacobian matters.
Orbit EveryEndKind() {
  const Signature s = Signature::Parse("slip- slip- slip+ stick slip+ stick");
  return Orbit{s, {0.3, 4.0, 0.6, 0.1, 0.25}, 1.3, 2.9, 0.2, 0.4, {1.1, 0.9, 2.3, 1.2, 1.7, 0.8}};
}

class JacobianTest : public ::testing::TestWithParam<Shooting> {};

TEST_P(JacobianTest, MatchesCentralFiniteDifferencesForEveryEndKind) {
  for (bool antisymmetric : {false, true}) {
    Orbit o = EveryEndKind();
    o.signature = Signature(o.signature.segments(), antisymmetric);
    const PeriodicityEquations equations(o.signature, GetParam());
    Eigen::VectorXd v = equations.Variables(o);
    // Move the multiple-shooting states off the trajectory too.
    for (int k = ov::Count(o.signature.size()); k < v.size(); ++k) v(k) += 0.01 * (k % 5 - 2);
    Eigen::VectorXd r;
    Eigen::MatrixXd j;
    equations.Evaluate(v, &r, &j);
    ASSERT_EQ(j.rows(), equations.EquationCount());
    ASSERT_EQ(j.cols(), equations.VariableCount());
    const auto names = equations.EquationNames();
    const Eigen::MatrixXd differences = CentralDifferenceJacobian(equations, v);
    for (int k = 0; k < v.size(); ++k) {
      const Eigen::VectorXd fd = differences.col(k);
      for (int row = 0; row < r.size(); ++row) {
        EXPECT_NEAR(j(row, k), fd(row), 1e-6 * (1.0 + std::abs(fd(row))))
            << "equation " << names[row] << ", variable " << k << ", antisymmetric " << antisymmetric;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(BothFormulations, JacobianTest,
                         ::testing::Values(Shooting::kSingle, Shooting::kMultiple),
                         [](const ::testing::TestParamInfo<Shooting>& s) {
                           return std::string(s.param == Shooting::kSingle ? "Single" : "Multiple");
                         });

TEST(PeriodicityEquations, CountIsNPlusFourPlusOnePerAbnormalStop) {
  const Orbit o = EveryEndKind();
  EXPECT_EQ(PeriodicityEquations(o.signature, Shooting::kSingle).EquationCount(), 6 + 4 + 1);
  EXPECT_EQ(PeriodicityEquations(o.signature, Shooting::kMultiple).EquationCount(), 11 + 4 * 5);
}

OrbitSolution SolvePreset(const PaperPreset& preset, ShootingChoice shooting,
                          LinearSolverType sparse = LinearSolverType::kKlu) {
  const Orbit guess = preset.Guess();
  OrbitSolverOptions options;
  options.shooting = shooting;
  options.sparse_solver = sparse;
  return SolveOrbit(guess, FreeIndices(guess.signature, preset.unknowns), preset.unknowns.tie_static_friction, options);
}

double MaxDifference(const Orbit& a, const Orbit& b) {
  return (ov::Pack(a) - ov::Pack(b)).lpNorm<Eigen::Infinity>();
}

TEST(OrbitSolver, SingleAndMultipleShootingGiveTheSameOrbitOnEveryPaperExample) {
  for (const PaperPreset& preset : PaperPresets()) {
    const OrbitSolution single = SolvePreset(preset, ShootingChoice::kSingle);
    const OrbitSolution multiple = SolvePreset(preset, ShootingChoice::kMultiple);
    ASSERT_TRUE(single.summary.Converged()) << preset.example->name << single.summary.BriefReport();
    ASSERT_TRUE(multiple.summary.Converged()) << preset.example->name << multiple.summary.BriefReport();
    EXPECT_EQ(multiple.shooting, Shooting::kMultiple);
    EXPECT_LT(MaxDifference(single.orbit, multiple.orbit), 1e-10) << preset.example->name;
  }
}

TEST(OrbitSolver, SparseSolversAgreeWithEachOther) {
  for (const PaperPreset& preset : PaperPresets()) {
    const OrbitSolution klu = SolvePreset(preset, ShootingChoice::kMultiple, LinearSolverType::kKlu);
    const OrbitSolution umfpack = SolvePreset(preset, ShootingChoice::kMultiple, LinearSolverType::kUmfpack);
    const OrbitSolution dense = SolvePreset(preset, ShootingChoice::kMultiple, LinearSolverType::kDenseLu);
    ASSERT_TRUE(klu.summary.Converged() && umfpack.summary.Converged() && dense.summary.Converged());
    EXPECT_LT(MaxDifference(klu.orbit, umfpack.orbit), 1e-12) << preset.example->name;
    EXPECT_LT(MaxDifference(klu.orbit, dense.orbit), 1e-12) << preset.example->name;
  }
}

// Section 4.2 has an abnormal stop in each half: without the symmetry both need x2'' = 0, one
// equation more than unknowns (10 x 9). The system is consistent at the orbit, so Gauss-Newton
// (least squares) solves it, and a full column rank makes the solution locally unique.
Orbit SolveFullPeriod(const Orbit& guess, const UnknownChoice& choice) {
  std::vector<int> free = {ov::kX10, ov::kX20, ov::kV10, ov::kPhi};
  for (int i = 0; i < guess.signature.size(); ++i) free.push_back(ov::Duration(i));
  for (const std::string& name : choice.release) free.push_back(*ov::IndexOf(guess.signature.size(), name));
  const OrbitSystem system(guess, free, choice.tie_static_friction, Shooting::kSingle);
  Eigen::VectorXd u = system.Unknowns(guess);
  Eigen::VectorXd r;
  JacobianMatrix j;
  for (int iteration = 0; iteration < 20; ++iteration) {
    system.Evaluate(u, &r, &j);
    u -= ToDense(j).colPivHouseholderQr().solve(r);
  }
  system.Evaluate(u, &r, &j);
  EXPECT_LT(r.lpNorm<Eigen::Infinity>(), 1e-12);
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(ToDense(j));
  EXPECT_GT(svd.singularValues().minCoeff(), 1e-6 * svd.singularValues().maxCoeff());
  return system.ToOrbit(u);
}

// The paper proves X(t + Theta/2) = -X(t) for sections 4.1, 4.2 and 6. Solving the full-period
// equations (no symmetry assumed) from the reduced solution must give the same orbit.
TEST(OrbitSolver, FullPeriodSolutionsOfAntisymmetricOrbitsEqualTheReducedOnes) {
  for (const PaperPreset& preset : PaperPresets()) {
    const OrbitSolution reduced = SolvePreset(preset, ShootingChoice::kSingle);
    const Orbit& half = reduced.orbit;
    if (!half.signature.antisymmetric()) continue;
    Orbit full = half;
    full.signature = Signature(half.signature.FullPeriod());
    full.durations.insert(full.durations.end(), half.durations.begin(), half.durations.end());
    // Perturb the guess so that the full system has work to do.
    full.x10 += 1e-3;
    full.durations[0] += 1e-3;
    const UnknownChoice& choice = preset.unknowns;
    const Orbit o = SolveFullPeriod(full, choice);
    const int n = half.signature.size();
    EXPECT_NEAR(o.x10, half.x10, 1e-9);
    EXPECT_NEAR(o.x20, half.x20, 1e-9);
    EXPECT_NEAR(o.v10, half.v10, 1e-9);
    EXPECT_NEAR(o.phi, half.phi, 1e-9);
    EXPECT_NEAR(o.parameters.eta, half.parameters.eta, 1e-9);
    EXPECT_NEAR(o.parameters.u_s, half.parameters.u_s, 1e-9);
    for (int i = 0; i < n; ++i) {
      EXPECT_NEAR(o.durations[i], half.durations[i], 1e-9) << preset.example->name;
      EXPECT_NEAR(o.durations[n + i], half.durations[i], 1e-9) << preset.example->name;
    }
    // And the state half a period later is the opposite one.
    const std::vector<State> states = o.SegmentStates();
    EXPECT_LT((states[n] + o.InitialState()).lpNorm<Eigen::Infinity>(), 1e-9);
  }
}

TEST(UnknownChoice, RejectsANonSquareChoiceWithTheCounts) {
  const Orbit o = FindPaperPreset("paper-5.1")->Guess();
  auto error = [&](const UnknownChoice& choice) -> InvalidInput {
    try {
      FreeIndices(o.signature, choice);
    } catch (const InvalidInput& e) {
      return e;
    }
    return InvalidInput::WithMessage("", "no error");
  };
  const InvalidInput not_square = error({{"u_r"}, {}, false});
  EXPECT_EQ(not_square.field(), "unknowns");
  EXPECT_NE(std::string(not_square.what()).find("not square"), std::string::npos) << not_square.what();
  EXPECT_NE(std::string(not_square.what()).find("8 equations but there are 9 unknowns"), std::string::npos)
      << not_square.what();
  const InvalidInput unknown = error({{"mu"}, {}, false});
  EXPECT_EQ(unknown.field(), "free");
  EXPECT_NE(std::string(unknown.what()).find("'mu'"), std::string::npos);
  EXPECT_EQ(FreeIndices(o.signature, {{"u_r"}, {"phi"}, false}).size(), 8u);
}

}  // namespace
}  // namespace stickslip
