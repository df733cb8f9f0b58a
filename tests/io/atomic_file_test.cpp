// Output files appear whole or not at all: AtomicFileWriter's pieces reach the target only at
// Commit; a writer dropped before it leaves the target as it was and no temporary file.
#include "stickslip/io/atomic_file.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "support/file_text.hpp"

namespace stickslip {
namespace {

namespace fs = std::filesystem;

class AtomicFile : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = fs::temp_directory_path() / ("atomic_file_test." + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                              ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(directory_);
    fs::create_directories(directory_);
  }
  void TearDown() override { fs::remove_all(directory_); }
  int Entries() const { return static_cast<int>(std::distance(fs::directory_iterator(directory_), fs::directory_iterator())); }
  fs::path directory_;
};

TEST_F(AtomicFile, WriterPiecesAppearAtCommit) {
  const fs::path target = directory_ / "series.csv";
  AtomicFileWriter out(target);
  out.Write("t,x1\n");
  for (int k = 0; k < 1000; ++k) out.Write(std::to_string(k) + ",0.5\n");
  EXPECT_FALSE(fs::exists(target));
  out.Commit();
  const std::string text = Slurp(target);
  EXPECT_EQ(text.substr(0, 5), "t,x1\n");
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1001);
  EXPECT_EQ(Entries(), 1);
}

TEST_F(AtomicFile, WriterDroppedBeforeCommitLeavesTheTargetAndNoTemporaryFile) {
  const fs::path target = directory_ / "series.csv";
  std::ofstream(target) << "keep\n";
  try {
    AtomicFileWriter out(target);
    out.Write("half a file");
    throw std::runtime_error("the simulation failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(Slurp(target), "keep\n");
  EXPECT_EQ(Entries(), 1);
}

// The temporary's name is predictable (its writer's pid): a link or file planted there is not the
// writer's to truncate, write through or rename over the target (before, the planted link's target
// received the file).
TEST_F(AtomicFile, WriterRefusesALinkPlantedAtItsTemporaryName) {
  const fs::path target = directory_ / "run.toml";
  fs::path temporary;
  {
    AtomicFileWriter probe(target);  // this process's temporary name, then dropped
    for (const fs::directory_entry& e : fs::directory_iterator(directory_)) temporary = e.path();
  }
  ASSERT_FALSE(temporary.empty());
  const fs::path precious = directory_ / "precious.txt";
  std::ofstream(precious) << "mine\n";
  fs::create_symlink(precious, temporary);
  try {
    AtomicFileWriter out(target);
    FAIL() << "a link at the temporary name was taken";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("is in the way"), std::string::npos) << e.what();
  }
  EXPECT_EQ(Slurp(precious), "mine\n");
  EXPECT_TRUE(fs::is_symlink(temporary));
  EXPECT_FALSE(fs::exists(target));
}

TEST_F(AtomicFile, WriterRefusesAMissingDirectory) {
  EXPECT_THROW(AtomicFileWriter(directory_ / "missing" / "x.csv"), std::runtime_error);
  EXPECT_EQ(Entries(), 0);
}

TEST_F(AtomicFile, WholeWriteReplacesTheTarget) {
  const fs::path target = directory_ / "b.run";
  std::ofstream(target) << "old";
  WriteFileAtomically(target, "new");
  EXPECT_EQ(Slurp(target), "new");
  EXPECT_EQ(Entries(), 1);
}

}  // namespace
}  // namespace stickslip
