// A trace of a run file's [model] through the trace files' one writer and one reader
// (io/trace_files.hpp, io/result_files.hpp): the model is erased to columns by name, written,
// read back to the same bytes, and its trace.csv holds each orbit's period and start as the closed
// form of the mass on a belt gives them (support/belt_cycle.hpp, ../shared/FRICTION-LITERATURE.md);
// a run of another model is never read as the paper's orbit.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "stickslip/invalid_input.hpp"
#include "stickslip/io/model_trace.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/io/trace_files.hpp"
#include "support/file_text.hpp"
#include "support/belt_cycle.hpp"

namespace stickslip {
namespace {

namespace fs = std::filesystem;

// The undamped mass on a belt (m = k = 1, F_s = 1.5, F_k = 1) from rest at v_b = 0.2, traced in
// the belt's speed over [0.1, 0.5] and stored as `stickslip find --model --trace --output belt`
// stores it.
class BeltTraceFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const BeltCycle belt;
    ModelFileStart start{.model = DynamicLinearOscillator(belt.Data()),
                         .parameters = {1.0, belt.F_k, belt.F_s, belt.v_b},
                         .slowest_frequency = belt.w(),
                         .state = Eigen::VectorXd::Zero(2),
                         .phi = 0.0};
    const ModelTraceRun run = TraceModel(start, 50, 1, "v_b", 0.1, 0.5);
    ASSERT_TRUE(run.trace.has_value()) << run.find.found.message;
    stored_ = RecordTrace(run.find.model,
                          {.run_file = "belt.toml", .output = "belt", .parameter = "v_b"},
                          *run.trace);
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    root_ = fs::temp_directory_path() / (std::string("stickslip-model-trace-") + test->name());
    fs::remove_all(root_);
  }
  void TearDown() override { fs::remove_all(root_); }

  StoredTrace stored_;
  fs::path root_;
};

TEST_F(BeltTraceFiles, ReadBackToTheSameBytes) {
  WriteTraceFiles(root_, stored_);
  const StoredTrace read = ReadTraceFiles(root_ / "belt");
  EXPECT_EQ(read.model, kLinearOscillatorModel);
  EXPECT_EQ(FormatTraceFiles(read).trace_csv, FormatTraceFiles(stored_).trace_csv);
  EXPECT_EQ(FormatTraceFiles(read).trace_json, FormatTraceFiles(stored_).trace_json);
  ASSERT_EQ(read.runs.size(), stored_.runs.size());
  for (std::size_t k = 0; k < read.runs.size(); ++k) {
    const RunFiles a = FormatRunFiles(read.runs[k]), b = FormatRunFiles(stored_.runs[k]);
    EXPECT_EQ(a.branch_csv, b.branch_csv) << k;
    EXPECT_EQ(a.special_points_csv, b.special_points_csv) << k;
    EXPECT_EQ(a.summary_json, b.summary_json) << k;
    EXPECT_EQ(read.runs[k].summary.model, kLinearOscillatorModel);
  }
}

// A [model]'s runs carry its units in summary.json (labels of the numbers, for figures); a summary
// written before units could be declared has none and reads as SI; units no model may declare are
// refused naming the file.
TEST_F(BeltTraceFiles, SummariesCarryTheModelsUnitsAndOlderOnesReadAsSi) {
  const RunFiles si = FormatRunFiles(stored_.runs.front());
  EXPECT_NE(si.summary_json.find("\"units\": {\n    \"length\": \"m\",\n    \"time\": \"s\",\n    \"force\": \"N\"\n  }"),
            std::string::npos)
      << si.summary_json;
  const auto with_units = [&](const std::string& units) {
    RunFiles files = si;
    const std::size_t at = files.summary_json.find("  \"units\"");
    files.summary_json.replace(at, files.summary_json.find("},\n", at) + 3 - at, units);
    return files;
  };
  EXPECT_EQ(ParseRunFiles(with_units(""), "belt").summary.units, SiUnits());
  const RunFiles small = with_units("  \"units\": {\"length\": \"mm\", \"time\": \"ms\", \"force\": \"kN\"},\n");
  const StoredRun read = ParseRunFiles(small, "belt");
  EXPECT_EQ(read.summary.units, (ModelUnits{"mm", "ms", "kN"}));
  EXPECT_NE(FormatRunFiles(read).summary_json.find("\"length\": \"mm\""), std::string::npos);
  EXPECT_EQ(FormatRunFiles(read).summary_json, FormatRunFiles(ParseRunFiles(FormatRunFiles(read), "belt")).summary_json);
  for (const char* bad : {"  \"units\": {\"length\": \"\", \"time\": \"s\", \"force\": \"N\"},\n",
                                 "  \"units\": {\"length\": \"m\", \"time\": \"s\"},\n", "  \"units\": \"SI\",\n"}) {
    try {
      ParseRunFiles(with_units(bad), "belt");
      ADD_FAILURE() << "accepted " << bad;
    } catch (const InvalidInput& e) {
      EXPECT_TRUE(std::string(e.what()).starts_with("belt/summary.json: ")) << e.what();
      EXPECT_TRUE(e.field().starts_with("units")) << e.field();
    }
  }
}

// Autonomous: the period is the cycle's time, T_stick + T_slip, not a forcing period (omega,
// which plays no part, is no column); the stick is entered at x = (2 F_k - F_s)/k.
TEST_F(BeltTraceFiles, HoldTheClosedFormCycleOfEveryPoint) {
  WriteTraceFiles(root_, stored_);
  const std::string header = Slurp(root_ / "belt" / "trace.csv").substr(0, Slurp(root_ / "belt" / "trace.csv").find('\n'));
  EXPECT_EQ(header, "branch,signature,pt,label,v_b,phi,period,x1_0,stable,admissible");
  EXPECT_EQ(Slurp(root_ / "belt" / "branch-1" / "branch.csv").find(",omega,"), std::string::npos);
  ASSERT_GT(stored_.points.size(), 10u);
  double worst = 0.0;
  for (const StoredTracePoint& p : ReadTraceFiles(root_ / "belt").points) {
    BeltCycle at;
    at.v_b = p.lambda;
    ASSERT_EQ(p.signature, "stick slip-");
    worst = std::max({worst, std::abs(p.period - (at.Stick() + at.Slip())), std::abs(Named(p.start, "x1_0") - at.Restick())});
  }
  EXPECT_LE(worst, 1e-9);
  RecordProperty("worst_difference", std::to_string(worst));
}

// What every linear oscillator with a Coulomb contact has, checked where the row is admissible: a
// duration within the period (for the belt, whose period is its durations' sum: not negative),
// F_k > 0, F_s >= F_k; and every branch with the same start state.
TEST_F(BeltTraceFiles, RefuseAnImpossibleRowAndABranchOfAnotherStartState) {
  WriteTraceFiles(root_, stored_);
  const fs::path branch = root_ / "belt" / "branch-2" / "branch.csv";
  const std::string text = Slurp(branch);
  auto refused = [&](const std::string& from, const std::string& to, const std::string& why) {
    std::string damaged = text;
    damaged.replace(damaged.find(from), from.size(), to);
    Spit(branch, damaged);
    try {
      ReadRunFiles(branch.parent_path());
      ADD_FAILURE() << "read with " << to;
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    }
    Spit(branch, text);
  };
  // Row 2 (pt 1): F_k, F_s, v_b, phi, x1_0, d1, d2 = 1, 1.5, 0.2, 0, 0.5, 5, 3.9026...
  refused(",5,3.9026", ",-1,3.9026", "column 'd1' = '-1' is invalid");
  refused("\n1,EP1,1,1.5,", "\n1,EP1,1,0.5,", "column 'F_s' = '0.5' is invalid: valid F_s >= F_k = 1");
  refused("\n1,EP1,1,", "\n1,EP1,-1,", "column 'F_k' = '-1' is invalid: valid F_k > 0");
  refused(",stick-fraction,", ",stick-share,", "the measure columns are invalid");
  std::string renamed = text;
  renamed.replace(renamed.find(",x1_0,"), 6, ",y1_0,");
  Spit(branch, renamed);
  std::string special = Slurp(branch.parent_path() / "special-points.csv");
  special.replace(special.find(",x1_0,"), 6, ",y1_0,");
  Spit(branch.parent_path() / "special-points.csv", special);
  try {
    ReadTraceFiles(root_ / "belt");
    FAIL() << "a branch of another start state read into the trace";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("key 'branch-2' has the start state y1_0 where branch-1 has x1_0"), std::string::npos)
        << e.what();
  }
}

// The slip's natural frequencies a [model]'s trace carries for its figures: read back as written, a
// list that is not one of positive numbers refused.
TEST_F(BeltTraceFiles, CarryTheSlipsNaturalFrequencies) {
  stored_.natural_frequencies = {1.25};  // (the belt's is 1: a value of its own, to find in the text)
  WriteTraceFiles(root_, stored_);
  const fs::path json = root_ / "belt" / "trace.json";
  EXPECT_EQ(ReadTraceFiles(root_ / "belt").natural_frequencies, stored_.natural_frequencies);
  std::string text = Slurp(json);
  text.replace(text.find("1.25"), 4, "-1.25");
  Spit(json, text);
  try {
    ReadTraceFiles(root_ / "belt");
    FAIL() << "a negative natural frequency read";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("key 'natural_frequencies' = [-1.25] is invalid"), std::string::npos) << e.what();
  }
}

TEST_F(BeltTraceFiles, AreNeverReadAsThePapersOrbit) {
  try {
    OrbitOf(stored_.runs.front(), stored_.runs.front().branch.front());
    FAIL() << "a [model]'s point read as the paper's orbit";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "model");
  }
}

// A summary naming a model stickslip does not know, and a branch of another model than its
// trace's, are refused naming the file and the key.
TEST_F(BeltTraceFiles, RefuseAnUnknownModelAndABranchOfAnotherModel) {
  WriteTraceFiles(root_, stored_);
  const fs::path summary = root_ / "belt" / "branch-1" / "summary.json";
  const std::string text = Slurp(summary);
  std::string other = text;
  other.replace(other.find("\"linear-oscillator\""), 19, "\"nonlinear\"");
  Spit(summary, other);
  try {
    ReadRunFiles(root_ / "belt" / "branch-1");
    FAIL() << "an unknown model read";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("summary.json: key 'model'"), std::string::npos) << e.what();
  }
  std::string paper = text;
  const std::string units = "  \"units\": {\n    \"length\": \"m\",\n    \"time\": \"s\",\n    \"force\": \"N\"\n  },\n";
  paper.erase(paper.find(units), units.size());
  paper.erase(paper.find("  \"model\": \"linear-oscillator\",\n"), 33);
  Spit(summary, paper);
  try {
    ReadTraceFiles(root_ / "belt");
    FAIL() << "a branch without the model read into a [model]'s trace";
  } catch (const InvalidInput& e) {  // read as the paper's run it now claims to be
    EXPECT_NE(std::string(e.what()).find("branch-1/summary.json: key 'parameter' = 'v_b' is invalid: valid a variable of the orbit, x10"), std::string::npos) << e.what();
  }
  Spit(summary, text);
  const fs::path trace_json = root_ / "belt" / "trace.json";
  std::string without = Slurp(trace_json);
  without.erase(without.find("  \"model\": \"linear-oscillator\",\n"), 33);
  Spit(trace_json, without);
  try {
    ReadTraceFiles(root_ / "belt");
    FAIL() << "a [model]'s branch read into a trace of the paper's model";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("is a run of another model"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace stickslip
