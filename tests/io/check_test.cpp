// Regression checks compare the stored records themselves: a stored run agrees with itself, a
// moved fold is reported with its label and column, multipliers are matched to the nearest
// rather than by position, and the orbit's measures are compared as the solution is.
#include "stickslip/io/check.hpp"

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "stickslip/io/result_files.hpp"

namespace stickslip {
namespace {

const std::filesystem::path kRun = std::filesystem::path(STICKSLIP_SOURCE_DIR) / "results" / "paper-5.1-omega-up";

TEST(CompareWithStored, FindsNoDifferenceBetweenAStoredRunAndItself) {
  const StoredRun stored = ReadRunFiles(kRun);
  EXPECT_TRUE(CompareWithStored(stored, stored).empty());
}

TEST(CompareWithStored, ReportsAFoldMovedBeyondTheParameterTolerance) {
  const StoredRun stored = ReadRunFiles(kRun);
  StoredRun fresh = stored;
  StoredSpecialPoint& fold = fresh.special_points[3];
  ASSERT_EQ(fold.point.label, "LP4");
  Named(fold.point.solution, "omega") *= 1 + 1e-6;  // the tolerance is a relative 1e-8
  const std::vector<Difference> differences = CompareWithStored(fresh, stored);
  ASSERT_EQ(differences.size(), 1u);
  EXPECT_EQ(differences[0].file, "special-points.csv");
  EXPECT_EQ(differences[0].row, "LP4");
  EXPECT_EQ(differences[0].column, "omega");
  EXPECT_EQ(differences[0].stored, "0.5868188660921189");
}

TEST(CompareWithStored, MatchesMultipliersToTheNearestWhateverTheirOrder) {
  const StoredRun stored = ReadRunFiles(kRun);
  StoredRun fresh = stored;
  for (StoredSpecialPoint& s : fresh.special_points) {
    std::reverse(s.point.multipliers.begin(), s.point.multipliers.end());
  }
  EXPECT_TRUE(CompareWithStored(fresh, stored).empty());
  // Now first, the zero multiplier of the stick (the entry into it), stored fourth, moved by 1e-5
  // (the tolerance is 1e-6).
  fresh.special_points[0].point.multipliers[0] += 1e-5;
  const std::vector<Difference> differences = CompareWithStored(fresh, stored);
  ASSERT_EQ(differences.size(), 1u);
  EXPECT_EQ(differences[0].row, "EP1");
  EXPECT_EQ(differences[0].column, "multiplier 4");
}

TEST(CompareWithStored, ReportsAMeasureBeyondTheSolutionToleranceAndACountThatDiffers) {
  const StoredRun stored = ReadRunFiles(kRun);
  StoredRun fresh = stored;
  StoredPoint& fold = fresh.special_points[3].point;
  Named(fold.measures, "amplitude:x2") *= 1 + 1e-8;  // within 1e-7 (1 + |x|)
  EXPECT_TRUE(CompareWithStored(fresh, stored).empty());
  Named(fold.measures, "amplitude:x2") = Named(stored.special_points[3].point.measures, "amplitude:x2") + 1e-5;
  Named(fold.measures, "sticks") = 2;
  std::vector<std::string> found;
  for (const Difference& d : CompareWithStored(fresh, stored)) found.push_back(d.row + " " + d.column);
  EXPECT_EQ(found, (std::vector<std::string>{"LP4 amplitude:x2", "LP4 sticks"}));
}

// A run stored before the friction measures existed has them nan: they are not compared, the
// other measures still are.
TEST(CompareWithStored, LeavesOutTheMeasuresTheStoredFilesLack) {
  StoredRun stored = ReadRunFiles(kRun);
  const StoredRun fresh = stored;
  stored.absent_measures = {"friction-work", "equivalent-damping"};
  for (StoredSpecialPoint& s : stored.special_points) Named(s.point.measures, "friction-work") = std::nan("");
  for (StoredPoint& p : stored.branch) Named(p.measures, "equivalent-damping") = std::nan("");
  EXPECT_TRUE(CompareWithStored(fresh, stored).empty());
  stored.absent_measures.clear();
  EXPECT_FALSE(CompareWithStored(fresh, stored).empty());
}

}  // namespace
}  // namespace stickslip
