// The strict Matrix Market reader (io/matrix_market.hpp): each format and symmetry read exactly,
// and each way a file can be wrong refused with the line, where Eigen 3.4's loadMarket returns
// success (a truncated file, a symmetric file's lost triangle, an out-of-range entry skipped).
#include "stickslip/io/matrix_market.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "stickslip/invalid_input.hpp"

namespace stickslip {
namespace {

Eigen::MatrixXd Parse(const std::string& text, const MatrixMarketLimits& limits = {}) {
  return ParseMatrixMarket(text, "stiffness", "K.mtx", limits);
}

TEST(MatrixMarket, ReadsAGeneralCoordinateFileEntryByEntry) {
  const Eigen::MatrixXd m = Parse(
      "%%MatrixMarket matrix coordinate real general\n% exported by an FE code\n\n2 3 3\n1 1 1.5\n2 3 -2e-3\n1 2 4\n");
  EXPECT_EQ(m, (Eigen::MatrixXd(2, 3) << 1.5, 4.0, 0.0, 0.0, 0.0, -2e-3).finished());
}

TEST(MatrixMarket, FillsBothTrianglesOfASymmetricFile) {
  const Eigen::MatrixXd m =
      Parse("%%MatrixMarket matrix coordinate real symmetric\n3 3 4\n1 1 2\n2 1 -1\n2 2 2\n3 2 -1\n");
  EXPECT_EQ(m, (Eigen::MatrixXd(3, 3) << 2, -1, 0, -1, 2, -1, 0, -1, 0).finished());
}

TEST(MatrixMarket, ReadsArraysColumnByColumnAndASymmetricArraysLowerTriangle) {
  EXPECT_EQ(Parse("%%MatrixMarket matrix array real general\n2 2\n1\n2\n3\n4\n"),
            (Eigen::MatrixXd(2, 2) << 1, 3, 2, 4).finished());
  EXPECT_EQ(Parse("%%MatrixMarket matrix array integer symmetric\n2 2\n5\n-1\n3\n"),
            (Eigen::MatrixXd(2, 2) << 5, -1, -1, 3).finished());
  EXPECT_EQ(Parse("%%MatrixMarket matrix array double general\n3 1\n0\n0\n1\n"), Eigen::Vector3d(0, 0, 1));
}

void ExpectRefused(const std::string& text, const std::string& says, const MatrixMarketLimits& limits = {}) {
  try {
    Parse(text, limits);
    ADD_FAILURE() << "accepted: " << text;
  } catch (const InvalidInput& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("stiffness = 'K.mtx' is invalid: ", 0), 0u) << message;
    EXPECT_NE(message.find(says), std::string::npos) << message;
  }
}

TEST(MatrixMarket, RefusesEveryFileThatIsNotExactlyAMatrixNamingTheLine) {
  const std::string coordinate = "%%MatrixMarket matrix coordinate real general\n";
  ExpectRefused(coordinate + "2 2 3\n1 1 1\n2 2 1\n", "truncated: 2 of the header's 3 entries");
  ExpectRefused(coordinate + "2 2 1\n1 1 1\n2 2 1\n", "line 4: more entries than the header's 1");
  ExpectRefused(coordinate + "2 2 1\n3 1 1\n", "line 3: the row '3'");
  ExpectRefused(coordinate + "2 2 1\n1 0 1\n", "line 3: the column '0'");
  ExpectRefused(coordinate + "2 2 2\n1 1 1\n1 1 2\n", "line 4: the entry (1, 1) again");
  ExpectRefused(coordinate + "2 2 1\n1 1 nan\n", "line 3: the value 'nan'");
  ExpectRefused(coordinate + "2 2 1\n1 1 1e999\n", "the value '1e999'");
  ExpectRefused(coordinate + "2 2 1\n1 1\n", "line 3: 2 fields");
  ExpectRefused(coordinate + "2 2 1\n% late\n1 1 1\n", "line 3: a comment after the size line");
  ExpectRefused(coordinate + "2 2\n", "line 2: 2 fields on the size line");
  ExpectRefused(coordinate + "2 2 5\n", "the entry count '5'");
  ExpectRefused(coordinate, "no size line");
  ExpectRefused("%%MatrixMarket matrix coordinate real symmetric\n2 2 1\n1 2 1\n", "above the diagonal");
  ExpectRefused("%%MatrixMarket matrix coordinate real symmetric\n2 3 0\n", "a square matrix");
  ExpectRefused("%%MatrixMarket matrix coordinate complex general\n1 1 1\n1 1 1 0\n", "the field complex");
  ExpectRefused("%%MatrixMarket matrix coordinate pattern general\n1 1 1\n1 1\n", "the field pattern");
  ExpectRefused("%%MatrixMarket matrix coordinate real hermitian\n1 1 1\n1 1 1\n", "the symmetry hermitian");
  ExpectRefused("%%MatrixMarket vector coordinate real general\n1 1 1\n1 1 1\n", "line 1: the object vector");
  ExpectRefused("%%MatrixMarket matrix coordinate real\n1 1 1\n1 1 1\n", "line 1: a banner of 4 words");
  ExpectRefused("1 1 1\n1 1 1\n", "line 1: no '%%MatrixMarket' banner");
  ExpectRefused("", "banner");
  ExpectRefused("%%MatrixMarket matrix array integer general\n1 1\n1.5\n", "the value '1.5'");
  ExpectRefused("%%MatrixMarket matrix array integer general\n1 1\n1e3\n", "the value '1e3'");
  ExpectRefused("%%MatrixMarket matrix array real general\n1 1\n" + std::string(1000, '7') + "\n",
                "the value '" + std::string(40, '7') + "...'");
  ExpectRefused(coordinate + "10000 10000 0\n", "10000x10000: valid at most 10000000 entries", {100000, 16u << 20});
  ExpectRefused("%%MatrixMarket matrix array real general\n2 2\n1\n2\n3\n", "truncated: 3 of the header's 4");
  ExpectRefused(coordinate + "1001 1 0\n", "the row count '1001'");
  MatrixMarketLimits small;
  small.max_bytes = 40;
  ExpectRefused(coordinate + "1 1 1\n1 1 1\n", "bytes: valid at most 40 bytes", small);
}

TEST(MatrixMarket, RefusesALargeFileBeforeReadingIt) {
  const std::filesystem::path file = std::filesystem::path(testing::TempDir()) / "large.mtx";
  {
    std::ofstream out(file);
    out << "%%MatrixMarket matrix array real general\n1 1\n" << std::string(100, ' ') << "1\n";
  }
  MatrixMarketLimits small;
  small.max_bytes = 64;
  try {
    ReadMatrixMarket(file, "mass", small);
    ADD_FAILURE() << "accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("valid at most 64 bytes"), std::string::npos) << e.what();
  }
  EXPECT_EQ(ReadMatrixMarket(file, "mass"), Eigen::MatrixXd::Ones(1, 1));
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace stickslip
