// A run's fields named in the words of its front end: a run file's keys at their line, the
// options of a run given by them. The message is composed once from the field and what is wrong
// with it (no message is a rewrite of another), so the same fault reads in each front end's words.
#include "stickslip/io/run_fields.hpp"

#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "stickslip/io/command_options.hpp"
#include "stickslip/io/run.hpp"
#include "stickslip/io/run_file.hpp"

namespace stickslip {
namespace {

TEST(OptionOfKey, IsTheKeysLastPartSpeltWithDashesButForThreeOptionsOfTheirOwnName) {
  EXPECT_EQ(OptionOfKey("continuation.ds_min"), "ds-min");
  EXPECT_EQ(OptionOfKey("start.restart.switch_branch"), "switch-branch");
  EXPECT_EQ(OptionOfKey("output"), "output");
  EXPECT_EQ(OptionOfKey("start.restart"), "point");
  EXPECT_EQ(OptionOfKey("unknowns.tie_u_r"), "tie-u_r");
  EXPECT_EQ(OptionOfKey("continuation.user_values_of"), "user-value");
}

TEST(KeyError, NamesARunFilesKeyAtItsLineAndARunGivenByOptionsByTheOption) {
  RunFile file;
  file.path = "a.toml";
  file.locations["continuation.range"] = "a.toml:7:1";
  const RunFileError in_file = KeyError(file, "continuation.range", "= [1, 2] excludes the start");
  EXPECT_STREQ(in_file.what(), "a.toml:7:1: key 'continuation.range' = [1, 2] excludes the start");
  EXPECT_EQ(in_file.field(), "continuation.range");
  const RunFileError given = KeyError(AsOneOffRun({}), "continuation.range", "= [1, 2] excludes the start");
  EXPECT_STREQ(given.what(), "range = [1, 2] excludes the start");
  EXPECT_EQ(given.field(), "range");
}

TEST(OnCommandLine, NamesTheRestartPointAsThePointOptionAndLeavesOtherFieldsAsTheyAre) {
  const InvalidInput restart = InvalidInput::WithMessage("restart", "restart = 'a:LP1' cannot be used: no run 'a'");
  EXPECT_STREQ(OnCommandLine(restart).what(), "point = 'a:LP1' cannot be used: no run 'a'");
  EXPECT_EQ(OnCommandLine(restart).field(), "point");
  const InvalidInput duration("d1", -5.0, "d1 >= 0");
  EXPECT_STREQ(OnCommandLine(duration).what(), duration.what());
}

// One fault of the start (u_r given twice), through the one builder, from a run file and from
// options: each message in its own words, neither made from the other.
std::string SetupRefusal(const RunFile& run) {
  try {
    MakeSetup(run, "no-results");
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

RunFile TwiceGivenStaticLevel(RunFile run) {
  run.output = "t";
  run.preset = "paper-5.1";
  run.set = {{"u_r", 0.5}, {"u_r", 0.6}};
  run.parameter = "omega";
  run.range_min = 0.1;
  run.range_max = 2.0;
  return run;
}

TEST(AtRunField, PlacesAStartFaultAtTheRunFilesKeyOrNamesTheOption) {
  RunFile file;
  file.path = "a.toml";
  file.locations["start.set"] = "a.toml:4:1";
  const std::string in_file = SetupRefusal(TwiceGivenStaticLevel(file));
  const std::string given = SetupRefusal(TwiceGivenStaticLevel(AsOneOffRun({})));
  EXPECT_TRUE(in_file.starts_with("a.toml:4:1: key 'start.set' gives 'u_r' twice (0.5 and 0.6)")) << in_file;
  EXPECT_TRUE(given.starts_with("set gives 'u_r' twice (0.5 and 0.6)")) << given;
  EXPECT_EQ(given.find("key '"), std::string::npos) << given;
}

// The one check of a run's values, from a run file and from options: a step of 0.5 past ds_max.
TEST(CheckRunValues, RefusesOneFaultInARunFilesKeysAndInTheOptionsWords) {
  const BranchSteps defaults;
  const std::string text = "output = \"t\"\n[start]\npreset = \"paper-5.1\"\n[continuation]\nparameter = \"omega\"\n"
                           "direction = \"up\"\nrange = [0.1, 2.0]\nds = 0.5\n";
  try {
    ParseRunFile(text, "t.toml");
    ADD_FAILURE() << "a step past ds_max was read";
  } catch (const RunFileError& e) {
    EXPECT_EQ(std::string(e.what()),
              fmt::format("t.toml:8:6: key 'continuation.ds' = 0.5 is invalid: valid range 0 < continuation.ds_min ({}) "
                          "<= continuation.ds <= continuation.ds_max ({})", defaults.ds_min, defaults.ds_max));
  }
  RunFile given = AsOneOffRun({});
  given.output = "t";
  given.range_min = 0.1;
  given.range_max = 2.0;
  given.steps.ds = 0.5;
  try {
    CheckRunValues(given);
    ADD_FAILURE() << "a step past ds-max was taken";
  } catch (const RunFileError& e) {
    EXPECT_EQ(std::string(e.what()), fmt::format("ds = 0.5 is invalid: valid range 0 < ds-min ({}) <= ds <= ds-max ({})",
                                                 defaults.ds_min, defaults.ds_max));
  }
}

}  // namespace
}  // namespace stickslip
