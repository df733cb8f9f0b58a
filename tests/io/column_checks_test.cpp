// Every numeric column of stickslip's tables is checked by its kind (io/column_kinds.hpp), every
// signature parsed, by the readers that map-sweep --merge, map --brute-force, plot, a restart and
// Python's MapSweepResult.load and Branch.load share (issue 22, defect 8): a value outside its
// column's valid values, and not one of the non-finite values the format documents for it, is
// refused naming the file, the line and the column.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/map_file.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/io/trace_files.hpp"

#include "support/file_text.hpp"

namespace stickslip {
namespace {

namespace fs = std::filesystem;

const fs::path kResults = fs::path(STICKSLIP_SOURCE_DIR) / "results";

std::string ErrorOf(const std::function<void()>& read) {
  try {
    read();
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "(accepted)";
}

// `text` with the field of column `column` on line `line` (1-based) replaced by `value`.
std::string WithField(const std::string& text, int line, const std::string& column, const std::string& value) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  auto fields = [](const std::string& l) {
    std::vector<std::string> f;
    std::istringstream s(l);
    for (std::string x; std::getline(s, x, ',');) f.push_back(x);
    if (!l.empty() && l.back() == ',') f.emplace_back();
    return f;
  };
  const std::vector<std::string> header = fields(lines[0]);
  std::vector<std::string> row = fields(lines[line - 1]);
  row[std::find(header.begin(), header.end(), column) - header.begin()] = value;
  lines[line - 1] = fmt::format("{}", fmt::join(row, ","));
  return fmt::format("{}\n", fmt::join(lines, "\n"));
}

// ---- the brute-force map's file

constexpr const char* kMapHeader =
    "i,j,ni,nj,omega,u_r,section_phase,run,attractors,attractor,status,period,stops_per_period,sticks_per_period,"
    "starts,signature,k,x1,x2,v1,v2\n";
constexpr const char* kMapRow = "0,0,1,1,0.54,1.2,3,c0e8f73db3a1559f,1,0,periodic,1,2,1,4,slip- stick slip- / antisymmetric,0,1,2,3,0\n";

std::string MapError(const std::string& column, const std::string& value) {
  const std::string text = WithField(std::string(kMapHeader) + kMapRow, 2, column, value);
  return ErrorOf([&] { ReadBruteForceMapCsv(text, "map.csv"); });
}

TEST(ColumnChecks, TheMapFileAsWrittenIsRead) {
  EXPECT_EQ(MapError("x1", "1"), "(accepted)");
  EXPECT_EQ(MapError("signature", ""), "(accepted)");  // no orbit type was read
}

TEST(ColumnChecks, ANanInAMapFilesSectionPointIsRefused) {
  EXPECT_EQ(MapError("x1", "nan"), "map.csv:2: column 'x1' = 'nan' is not a finite number: valid a finite number");
  EXPECT_EQ(MapError("v2", "-inf").find("map.csv:2: column 'v2' = '-inf' is not a finite number"), 0u);
}

TEST(ColumnChecks, AMapFilesSignatureIsParsed) {
  EXPECT_EQ(MapError("signature", "slip- bogus").find("map.csv:2: column 'signature' = 'slip- bogus' is invalid: "), 0u)
      << MapError("signature", "slip- bogus");
}

TEST(ColumnChecks, AMapFilesParametersAndCountsAreInTheirRanges) {
  EXPECT_EQ(MapError("u_r", "1e308"), "map.csv:2: column 'u_r' = '1e308' is invalid: valid 1e-06 <= u_r <= 1000");
  EXPECT_EQ(MapError("omega", "-0.5").find("map.csv:2: column 'omega' = '-0.5' is invalid: valid 0.01 <= omega"), 0u);
  EXPECT_EQ(MapError("stops_per_period", "-1").find("map.csv:2: column 'stops_per_period' = '-1' is invalid"), 0u);
  EXPECT_EQ(MapError("starts", "0").find("map.csv:2: column 'starts' = '0' is invalid"), 0u);
}

// ---- a run's branch.csv and special-points.csv

RunFiles StoredTexts(const fs::path& dir) {
  return {Slurp(dir / "branch.csv"), Slurp(dir / "special-points.csv"), Slurp(dir / "summary.json")};
}

std::string BranchError(const std::string& run, int line, const std::string& column, const std::string& value) {
  RunFiles files = StoredTexts(kResults / run);
  files.branch_csv = WithField(files.branch_csv, line, column, value);
  return ErrorOf([&] { ParseRunFiles(files, "stored"); });
}

TEST(ColumnChecks, AnOutOfRangeParameterInABranchFileIsRefused) {
  EXPECT_EQ(BranchError("paper-5.1-omega-up", 3, "u_s", "1e308"),
            "stored/branch.csv:3: column 'u_s' = '1e308' is invalid: valid |u_s| <= 1000 (a branch ends where a "
            "released u_s reaches 0)");
  EXPECT_EQ(BranchError("paper-5.1-omega-up", 3, "chi", "2").find("stored/branch.csv:3: column 'chi' = '2' is invalid"), 0u);
}

TEST(ColumnChecks, ADurationIsWithinThePeriodOnAnAdmissibleRowToRounding) {
  EXPECT_EQ(BranchError("paper-5.1-omega-up", 3, "d2", "-5").find("stored/branch.csv:3: column 'd2' = '-5' is invalid: "
                                                                  "valid 0 <= d2 <= "),
            0u);
  EXPECT_EQ(BranchError("paper-5.1-omega-up", 3, "d2", "1e3").find("stored/branch.csv:3: column 'd2' = '1e3' is invalid"), 0u);
  // A zero-length segment to rounding below zero, as a located change of type gives it.
  EXPECT_EQ(BranchError("paper-5.1-omega-up", 3, "d2", "-4.7e-15"), "(accepted)");
}

// The non-finite values the format documents: an inapplicable margin inf, det(H + I) of an
// orbit that is not antisymmetric nan, a Floquet value that could not be computed nan, a product
// over the multipliers that overflows inf or -inf (never a multiplier).
TEST(ColumnChecks, OnlyTheDocumentedNonFiniteValuesAreRead) {
  const std::string run = "paper-5.1-omega-up";  // slip- slip+ stick slip+, not antisymmetric
  EXPECT_EQ(BranchError(run, 3, "margin:velocity:1", "inf"), "(accepted)");
  EXPECT_EQ(BranchError(run, 3, "margin:velocity:1", "-inf").find("stored/branch.csv:3: column 'margin:velocity:1' = "
                                                                  "'-inf' is invalid: valid a finite number, inf"),
            0u);
  EXPECT_EQ(BranchError(run, 3, "margin:duration:1", "nan"), "(accepted)");
  EXPECT_EQ(BranchError(run, 3, "floquet:det(M-I)", "nan"), "(accepted)");
  EXPECT_EQ(BranchError(run, 3, "floquet:mu1_re", "inf").find("stored/branch.csv:3: column 'floquet:mu1_re' = 'inf'"), 0u);
  EXPECT_EQ(BranchError(run, 3, "floquet:torus", "-inf"), "(accepted)");
  EXPECT_EQ(BranchError(run, 3, "floquet:det(M+I)", "inf"), "(accepted)");
  EXPECT_EQ(BranchError(run, 3, "floquet:det(H+I)", "0.5").find("stored/branch.csv:3: column 'floquet:det(H+I)' = '0.5' "
                                                                "is invalid: valid nan (the orbit is not antisymmetric)"),
            0u);
  EXPECT_EQ(BranchError("paper-6-omega-up", 3, "floquet:det(H+I)", "0.5"), "(accepted)");  // antisymmetric
}

TEST(ColumnChecks, MeasuresAndCountsAreInTheirRanges) {
  const std::string run = "paper-5.1-omega-up";
  EXPECT_EQ(BranchError(run, 3, "amplitude:x1", "-1").find("stored/branch.csv:3: column 'amplitude:x1' = '-1' is invalid"), 0u);
  EXPECT_EQ(BranchError(run, 3, "stick-fraction", "1.5").find("stored/branch.csv:3: column 'stick-fraction' = '1.5'"), 0u);
  EXPECT_EQ(BranchError(run, 3, "stops", "-2").find("stored/branch.csv:3: column 'stops' = '-2' is invalid"), 0u);
  EXPECT_EQ(BranchError(run, 3, "step_size", "nan").find("stored/branch.csv:3: column 'step_size' = 'nan'"), 0u);
  EXPECT_EQ(BranchError(run, 3, "pt", "0").find("stored/branch.csv:3: column 'pt' = '0' is invalid"), 0u);
}

// ---- a trace: its branches are runs, trace.csv and trace.json are read through the same checks

class ColumnChecksOfATrace : public ::testing::Test {
 protected:
  void SetUp() override { Copy("paper-4.1-omega-trace"); }
  void Copy(const std::string& trace) {
    dir_ = fs::temp_directory_path() / fmt::format("stickslip-column-checks-{}", ::getpid());
    fs::remove_all(dir_);
    fs::copy(kResults / trace, dir_, fs::copy_options::recursive);
  }
  void TearDown() override { fs::remove_all(dir_); }
  void Replace(const fs::path& file, const std::string& text) { std::ofstream(dir_ / file, std::ios::binary) << text; }
  fs::path dir_;
};

TEST_F(ColumnChecksOfATrace, ANegativeDurationInATracesBranchIsRefused) {
  Replace("branch-1/branch.csv", WithField(Slurp(dir_ / "branch-1/branch.csv"), 2, "d1", "-5"));
  const std::string e = ErrorOf([&] { ReadTraceFiles(dir_); });
  EXPECT_EQ(e.find((dir_ / "branch-1/branch.csv").string() + ":2: column 'd1' = '-5' is invalid: valid 0 <= d1 <= "), 0u) << e;
}

TEST_F(ColumnChecksOfATrace, ASignatureInTraceCsvIsParsed) {
  Replace("trace.csv", WithField(Slurp(dir_ / "trace.csv"), 3, "signature", "slip- bogus"));
  const std::string e = ErrorOf([&] { ReadTraceFiles(dir_); });
  EXPECT_EQ(e.find((dir_ / "trace.csv").string() + ":3: column 'signature' = 'slip- bogus' is invalid: "), 0u) << e;
}

// trace.json: a bifurcation's parameter in the continued parameter's range, its singularity >= 0.
TEST_F(ColumnChecksOfATrace, ABifurcationsParameterInTraceJsonIsInItsRange) {
  Copy("paper-5.1-omega-trace");
  std::string json = Slurp(dir_ / "trace.json");
  const std::size_t at = json.find("\"parameter\": 0.");
  ASSERT_NE(at, std::string::npos);
  json.replace(at, json.find(',', at) - at, "\"parameter\": 1e308");
  Replace("trace.json", json);
  const std::string e = ErrorOf([&] { ReadTraceFiles(dir_); });
  EXPECT_NE(e.find(".parameter' = 1e+308 is invalid: valid 0.01 <= omega <= 100"), std::string::npos) << e;
}

}  // namespace
}  // namespace stickslip
