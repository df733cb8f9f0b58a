// The trace files' one writer and one reader (io/trace_files.hpp): a trace written and read back
// gives the same bytes, every branch's directory reads as an ordinary run, and a damaged file is an
// error naming the file and the key or line, never a crash.
#include "stickslip/io/trace_files.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "stickslip/branches/trace.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/io/result_files.hpp"
#include "stickslip/io/run.hpp"

#include "support/file_text.hpp"

namespace stickslip {
namespace {

namespace fs = std::filesystem;

class StoredTraceFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const fs::path root(STICKSLIP_SOURCE_DIR);
    run_ = ReadRunFile(root / "continuation-scripts" / "paper-4.1-omega-down.toml");
    run_.output = "trace";
    run_.trace = TraceOptions{};
    stored_ = RecordTrace(run_, TraceOrbits(MakeSetup(run_, root / "results"), *run_.trace));
    // One directory per test: ctest runs them in parallel.
    dir_ = fs::path(::testing::TempDir()) /
           (std::string("trace_files_test_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    WriteTraceFiles(dir_, stored_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  RunFile run_;
  StoredTrace stored_;
  fs::path dir_;
};

TEST_F(StoredTraceFiles, ReadingThenWritingGivesTheSameBytesAndEveryBranchIsARun) {
  const StoredTrace read = ReadTraceFiles(dir_ / "trace");
  ASSERT_EQ(read.branches.size(), stored_.branches.size());
  ASSERT_GE(read.branches.size(), 3u);
  const TraceFiles a = FormatTraceFiles(stored_);
  const TraceFiles b = FormatTraceFiles(read);
  EXPECT_EQ(a.trace_csv, b.trace_csv);
  EXPECT_EQ(a.trace_json, b.trace_json);
  EXPECT_EQ(Slurp(dir_ / "trace" / "trace.json"), a.trace_json);
  for (std::size_t k = 0; k < read.branches.size(); ++k) {
    const StoredRun run = ReadRunFiles(dir_ / "trace" / read.branches[k].name);
    EXPECT_EQ(run.summary.output, read.branches[k].name);
    EXPECT_EQ(run.summary.signature, read.branches[k].signature);
    EXPECT_EQ(run.branch.size(), read.branches[k].points);
    const RunFiles files = FormatRunFiles(run);
    EXPECT_EQ(files.branch_csv, Slurp(dir_ / "trace" / read.branches[k].name / "branch.csv"));
  }
  // Written again over itself: the files of the user's are kept, named like a branch or not.
  Spit(dir_ / "trace" / "notes.txt", "mine");
  Spit(dir_ / "trace" / "branch-notes.md", "mine");
  fs::create_directory(dir_ / "trace" / "branch-2-map");
  Spit(dir_ / "trace" / "branch-2-map" / "regions.json", "mine");
  EXPECT_EQ(WriteTraceFiles(dir_, read), (std::vector<std::string>{"branch-2-map", "branch-notes.md", "notes.txt"}));
  EXPECT_EQ(Slurp(dir_ / "trace" / "notes.txt"), "mine");
  EXPECT_EQ(Slurp(dir_ / "trace" / "branch-notes.md"), "mine");
  EXPECT_EQ(Slurp(dir_ / "trace" / "branch-2-map" / "regions.json"), "mine");
  EXPECT_EQ(Slurp(dir_ / "trace" / "trace.csv"), a.trace_csv);
}

TEST_F(StoredTraceFiles, ADamagedFileIsAnErrorNamingItsFile) {
  const fs::path t = dir_ / "trace";
  const std::string json = Slurp(t / "trace.json");
  const std::string csv = Slurp(t / "trace.csv");
  auto expect_error = [&](const std::string& what, const std::string& file) {
    try {
      ReadTraceFiles(t);
      ADD_FAILURE() << what << " was accepted";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << what << ": " << e.what();
    }
    Spit(t / "trace.json", json);
    Spit(t / "trace.csv", csv);
  };
  Spit(t / "trace.json", json.substr(0, json.size() / 2));
  expect_error("truncated JSON", "trace.json");
  Spit(t / "trace.json", "[]");
  expect_error("not an object", "trace.json");
  std::string edited = json;
  edited.replace(edited.find("\"parameter\""), 11, "\"parameters\"");
  Spit(t / "trace.json", edited);
  expect_error("an unknown key", "trace.json");
  edited = json;
  edited.replace(edited.find("\"points\": "), 10, "\"points\": 9");
  Spit(t / "trace.json", edited);
  expect_error("a count that differs from the branch", "trace.json");
  // Another parameter than its branches' (trace.csv's column renamed with it): not read as theirs.
  edited = json;
  edited.replace(edited.find("\"parameter\": \"omega\""), 20, "\"parameter\": \"bogus\"");
  Spit(t / "trace.json", edited);
  std::string renamed = csv;
  renamed.replace(renamed.find(",omega,"), 7, ",bogus,");
  Spit(t / "trace.csv", renamed);
  expect_error("a parameter that is not its branches'", "trace.json: key 'parameter' = 'bogus' differs");
  Spit(t / "trace.csv", csv.substr(0, csv.find('\n') + 1));
  expect_error("rows missing", "trace.csv");
  std::string header = csv;
  header.replace(0, 6, "brunch");
  Spit(t / "trace.csv", header);
  expect_error("a wrong column", "trace.csv");
  fs::remove(t / "branch-2" / "summary.json");
  expect_error("a branch without its summary", "summary.json");
}

TEST_F(StoredTraceFiles, ADirectoryOfTheUsersIsNotReplaced) {
  fs::create_directories(dir_ / "mine");
  Spit(dir_ / "mine" / "notes.txt", "mine");
  StoredTrace other = stored_;
  other.output = "mine";
  EXPECT_THROW(WriteTraceFiles(dir_, other), InvalidInput);
  EXPECT_EQ(Slurp(dir_ / "mine" / "notes.txt"), "mine");
  EXPECT_FALSE(fs::exists(dir_ / "mine" / "trace.json"));
}

// A trace written by an older stickslip (its trace.json without a key added since) is still a
// trace, replaced by a new run; a trace.json that is not one of ours is not.
TEST_F(StoredTraceFiles, AnOlderTraceIsReplacedButNotAForeignTraceJson) {
  nlohmann::ordered_json old = nlohmann::ordered_json::parse(Slurp(dir_ / "trace" / "trace.json"));
  for (auto& branch : old["branches"]) ASSERT_EQ(branch.erase("bifurcations"), 1u);
  Spit(dir_ / "trace" / "trace.json", old.dump(2));
  ASSERT_THROW(ReadTraceFiles(dir_ / "trace"), InvalidInput);  // not this version's trace.json
  EXPECT_NO_THROW(WriteTraceFiles(dir_, stored_));
  EXPECT_EQ(Slurp(dir_ / "trace" / "trace.json"), FormatTraceFiles(stored_).trace_json);
  fs::create_directories(dir_ / "foreign");
  Spit(dir_ / "foreign" / "trace.json", "{\"name\": \"someone else's\"}");
  StoredTrace other = stored_;
  other.output = "foreign";
  EXPECT_THROW(WriteTraceFiles(dir_, other), InvalidInput);
  EXPECT_EQ(Slurp(dir_ / "foreign" / "trace.json"), "{\"name\": \"someone else's\"}");
}

}  // namespace
}  // namespace stickslip
