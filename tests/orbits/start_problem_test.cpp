// The one start-problem builder: which values win, what a zero-length segment and a missing one
// do, and which field each kind of bad input is blamed on.
#include "stickslip/orbits/start_problem.hpp"

#include <chrono>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

namespace stickslip {
namespace {

namespace ov = orbit_variables;

// Section 5.1's data as printed in eq. (36), for a start given by hand.
StartInput HandMadeSlipStick() {
  StartInput input;
  input.signature = "slip- slip+ stick slip+";
  input.set = {{"chi", 0.22}, {"eta", 4.2}, {"omega", 2 * std::numbers::pi / 11}, {"u_s", 0.0138}, {"u_r", 0.4962}};
  input.guess = {{"d1", 3.2663}, {"d2", 2.0}, {"d3", 2.7337}, {"d4", 3.0}};
  return input;
}

InvalidInput ErrorOf(const std::function<void()>& build) {
  try {
    build();
  } catch (const InvalidInput& e) {
    return e;
  }
  ADD_FAILURE() << "no InvalidInput thrown";
  return InvalidInput::WithMessage("", "");
}

TEST(StartProblem, AcceptsADurationGivenAsZero) {
  StartInput input = HandMadeSlipStick();
  input.guess[2].second = 0.0;  // d3
  const StartProblem start = BuildStartProblem(input);
  EXPECT_EQ(start.orbit.durations, (std::vector<double>{3.2663, 2.0, 0.0, 3.0}));
}

TEST(StartProblem, RefusesADurationThatWasNeverGiven) {
  StartInput input = HandMadeSlipStick();
  input.guess.pop_back();
  const InvalidInput e = ErrorOf([&] { BuildStartProblem(input); });
  EXPECT_EQ(e.field(), "guess");
  EXPECT_NE(std::string(e.what()).find("misses d4"), std::string::npos) << e.what();
}

TEST(StartProblem, RefusesANegativeDuration) {
  StartInput input = HandMadeSlipStick();
  input.guess[1].second = -0.5;  // d2
  const InvalidInput e = ErrorOf([&] { BuildStartProblem(input); });
  EXPECT_EQ(e.field(), "d2");
  EXPECT_EQ(e.valid_range(), "0 <= d2 <= 11, the orbit's period 1 x 2 pi/omega, to rounding (1e-12 of it)");
}

// A located change of type gives its zero-length segment to rounding, of either sign (-4.7e-15
// of a period of 20.3 at results/paper-4.2-omega-trace/branch-3:LP6, which a restart refused):
// the builder takes a value within kDurationRounding of the period below zero as the zero-length
// segment, 0, and refuses one beyond, built here directly.
TEST(StartProblem, TakesARoundingLevelNegativeDurationAsAZeroLengthSegment) {
  StartInput input = HandMadeSlipStick();
  const double period = 11.0;
  for (const double d : {-4.7e-15, -2.3e-16 * period, -kDurationRounding * period}) {
    input.guess[2].second = d;  // d3
    const StartProblem start = BuildStartProblem(input);
    EXPECT_EQ(start.orbit.durations[2], 0.0) << d;
    EXPECT_FALSE(std::signbit(start.orbit.durations[2])) << d;
  }
  input.guess[2].second = -3.0 * kDurationRounding * period;
  EXPECT_EQ(ErrorOf([&] { BuildStartProblem(input); }).field(), "d3");
}

// The same through a restart point, as `continue --point RUN:LABEL` reads it.
TEST(StartProblem, RestartsFromAPointWhoseZeroLengthSegmentIsSlightlyNegative) {
  StartInput input;
  input.restart = RestartPoint{"run", "LP6", "slip- slip+ stick slip+",
                               {{"chi", 0.22}, {"eta", 4.2}, {"omega", 2 * std::numbers::pi / 11}, {"u_s", 0.0138},
                                {"u_r", 0.4962}, {"x10", -0.36}, {"x20", 4.19}, {"v10", -0.26}, {"phi", 0.32},
                                {"d1", 3.2663}, {"d2", 2.0}, {"d3", -4.7087812137759014e-15}, {"d4", 5.7337}}};
  input.parameter = "omega";
  input.free = {"u_r"};
  input.fix = {{"d2", std::nullopt}};
  const StartProblem start = BuildStartProblem(input);
  EXPECT_EQ(start.orbit.durations[2], 0.0);
}

// A point stored past a change of type (continue_past_type_changes) has a segment of negative
// length, as its run computed it: a restart takes it as stored; the same value as a guess is refused.
TEST(StartProblem, TakesARestartPointsNegativeDurationPastAChangeOfTypeAsStored) {
  StartInput input;
  input.restart = RestartPoint{"run", "GR5", "slip- slip+ stick slip+",
                               {{"chi", 0.22}, {"eta", 4.2}, {"omega", 2 * std::numbers::pi / 11}, {"u_s", 0.0138},
                                {"u_r", 0.4962}, {"x10", -0.36}, {"x20", 4.19}, {"v10", -0.26}, {"phi", 0.32},
                                {"d1", 3.2663}, {"d2", 2.0}, {"d3", -0.078}, {"d4", 5.8117}}};
  EXPECT_EQ(BuildStartProblem(input).orbit.durations[2], -0.078);
  input.guess = {{"d3", -0.078}};
  EXPECT_EQ(ErrorOf([&] { BuildStartProblem(input); }).field(), "d3");
}

// u_s <= 0 is the end of the physical family (a branch ends there with u_s = -2.7e-11, located
// to the event tolerance): a restart there is refused, and the message says why.
TEST(StartProblem, RefusesAStartAtTheFamilysEndSayingSo) {
  for (const double u_s : {-2.6862791665319474e-11, 0.0}) {
    StartInput input = HandMadeSlipStick();
    input.set[3].second = u_s;
    const InvalidInput e = ErrorOf([&] { BuildStartProblem(input); });
    EXPECT_EQ(e.field(), "u_s");
    EXPECT_NE(std::string(e.what()).find("end of the physical family"), std::string::npos) << e.what();
  }
  StartInput input = HandMadeSlipStick();
  input.set[3].second = 1e-7;  // below the valid range, but no family's end
  EXPECT_EQ(std::string(ErrorOf([&] { BuildStartProblem(input); }).what()).find("family"), std::string::npos);
}

// A duration equal to the period to rounding (a solved one-segment orbit) is accepted; one
// longer by a part in a billion is refused.
TEST(StartProblem, AcceptsADurationOfThePeriodToRoundingOnly) {
  StartInput input = HandMadeSlipStick();
  input.guess[3].second = std::nextafter(11.0, 20.0);  // d4, the period 2 pi/omega = 11
  EXPECT_NO_THROW(BuildStartProblem(input));
  input.guess[3].second = 11.0 * (1.0 + 1e-9);
  EXPECT_EQ(ErrorOf([&] { BuildStartProblem(input); }).field(), "d4");
}

// A restart's d1..dn are the durations of its own type; under another signature they would
// silently name other segments (item 4 of issue 10): the builder refuses, pointing to the edits.
TEST(StartProblem, RefusesASignatureThatDiffersFromTheRestartPoints) {
  StartInput input = HandMadeSlipStick();
  input.guess.clear();
  input.restart = RestartPoint{"run", "SK1", "slip- slip+ / antisymmetric",
                               {{"d1", 3.0}, {"d2", 2.0}, {"x10", 0.1}, {"x20", 0.2}, {"v10", 0.0}, {"phi", 0.0}}};
  const InvalidInput e = ErrorOf([&] { BuildStartProblem(input); });
  EXPECT_EQ(e.field(), "signature");
  EXPECT_NE(std::string(e.what()).find("differs from the restart point's orbit type"), std::string::npos) << e.what();
}

// Set, guess and fix values each replace the preset's printed value; a name is given in one of
// them only (RepeatedAcrossSetAndGuess below).
// 100,000 guess names took 25 s when every pair was compared for repeats (issue 22): now one
// pass, refused at the first unknown name, and a repeat among many still found.
TEST(StartProblem, ManyGuessNamesAreRefusedInLinearTime) {
  StartInput input = HandMadeSlipStick();
  for (int k = 0; k < 100000; ++k) input.guess.emplace_back(fmt::format("g{}", k), 1.0);
  const auto start = std::chrono::steady_clock::now();
  const InvalidInput unknown = ErrorOf([&] { BuildStartProblem(input); });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(unknown.field(), "guess");
  EXPECT_NE(std::string(unknown.what()).find("g0"), std::string::npos) << unknown.what();
  EXPECT_LT(seconds, 2.0);
  input.guess.emplace_back("g99998", 2.0);
  const InvalidInput repeated = ErrorOf([&] { BuildStartProblem(input); });
  EXPECT_EQ(std::string(repeated.what()), "guess gives 'g99998' twice (1 and 2): give it once (in set, guess or a fix value)");
}

TEST(StartProblem, SetGuessAndFixValuesReplaceThePresets) {
  StartInput input;
  input.preset = "paper-5.1";
  input.set = {{"x10", 2.0}, {"u_r", 0.6}};
  input.guess = {{"x20", 5.0}};
  input.fix = {{"phi", 0.5}};
  input.free = {"u_r"};
  const StartProblem start = BuildStartProblem(input);
  EXPECT_EQ(start.orbit.x10, 2.0);
  EXPECT_EQ(start.orbit.x20, 5.0);
  EXPECT_EQ(start.orbit.v10, -0.2578);  // the printed value
  EXPECT_EQ(start.orbit.phi, 0.5);
  EXPECT_EQ(start.orbit.parameters.u_r, 0.6);
  EXPECT_EQ(start.orbit.parameters.chi, 0.22);
  EXPECT_EQ(start.orbit.durations, (std::vector<double>{3.2663, 2.0, 2.7337, 3.0}));
  const int n = 4;
  EXPECT_EQ(start.free, (std::vector<int>{ov::kX10, ov::kX20, ov::kV10, ov::Duration(0), ov::Duration(1), ov::Duration(2),
                                          ov::Duration(3), ov::Parameter(n, ParameterId::kStaticFriction)}));
}

TEST(StartProblem, TyingCopiesTheSlidingFrictionLevel) {
  StartInput input;
  input.preset = "paper-4.1";
  input.tie_u_r = true;
  input.free = {"u_s"};
  input.fix = {{"phi", std::nullopt}};
  const StartProblem start = BuildStartProblem(input);
  EXPECT_TRUE(start.unknowns.tie_static_friction);
  EXPECT_EQ(start.orbit.parameters.u_r, 0.1);
}

TEST(StartProblem, ThePaperChoiceReplacesThePresetsUnknowns) {
  StartInput input;
  input.preset = "paper-5.2";
  input.paper_choice = true;
  const StartProblem start = BuildStartProblem(input);
  EXPECT_EQ(start.unknowns.release, (std::vector<std::string>{"u_r"}));
  EXPECT_EQ(start.unknowns.fix, (std::vector<std::string>{"phi"}));
}

struct BadInput {
  const char* what;
  std::function<void(StartInput*)> change;
  const char* field;
  const char* text;
};

class StartProblemBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(StartProblemBadInput, IsBlamedOnItsField) {
  StartInput input = HandMadeSlipStick();
  input.parameter = "omega";
  GetParam().change(&input);
  const InvalidInput e = ErrorOf([&] { BuildStartProblem(input); });
  EXPECT_EQ(e.field(), GetParam().field) << e.what();
  EXPECT_NE(std::string(e.what()).find(GetParam().text), std::string::npos) << e.what();
  EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(
    EveryField, StartProblemBadInput,
    ::testing::Values(
        BadInput{"UnknownPreset", [](StartInput* in) { in->preset = "paper-9"; }, "preset", "paper-4.1, paper-4.2"},
        BadInput{"Signature", [](StartInput* in) { in->signature = "slip- stik"; }, "signature", "token 2 'stik'"},
        BadInput{"SignatureBesideADifferentPreset", [](StartInput* in) { in->preset = "paper-6"; }, "signature",
                 "give exactly one"},
        BadInput{"NoOrbitType", [](StartInput* in) { in->signature.clear(); }, "signature", "missing"},
        BadInput{"SetKey", [](StartInput* in) { in->set.emplace_back("d1", 1.0); }, "set", "valid range keys chi, eta"},
        BadInput{"GuessName", [](StartInput* in) { in->guess.emplace_back("mu", 1.0); }, "guess", "'mu'"},
        BadInput{"NotANumber", [](StartInput* in) { in->guess.emplace_back("x10", std::nan("")); }, "x10", "finite"},
        BadInput{"Infinite", [](StartInput* in) { in->set.emplace_back("phi", HUGE_VAL); }, "phi", "finite"},
        BadInput{"OutOfRange", [](StartInput* in) { in->set[0].second = 1e308; }, "chi", "0.01 <= chi <= 0.99"},
        BadInput{"RepeatedSetKey", [](StartInput* in) { in->set.emplace_back("omega", 0.7); }, "set", "gives 'omega' twice"},
        BadInput{"RepeatedGuess", [](StartInput* in) { in->guess.emplace_back("d2", 2.5); }, "guess", "gives 'd2' twice"},
        BadInput{"RepeatedAcrossSetAndGuess", [](StartInput* in) { in->guess.emplace_back("omega", 0.7); }, "guess",
                 "gives 'omega' twice"},
        BadInput{"RepeatedAcrossGuessAndFix", [](StartInput* in) { in->fix.push_back({"d1", 3.0}); }, "guess",
                 "gives 'd1' twice"},
        BadInput{"FreeOfAnUnknown", [](StartInput* in) { in->free.push_back("x10"); }, "free", "is an unknown already"},
        BadInput{"PresetWithRestart",
                 [](StartInput* in) {
                   in->preset = "paper-5.1";
                   in->restart = RestartPoint{"run", "TR1", "slip- slip+ stick slip+", {}};
                 },
                 "restart", "give at most one of them"},
        BadInput{"MissingParameter", [](StartInput* in) { in->set.erase(in->set.begin()); }, "chi", "missing"},
        BadInput{"MovingStart", [](StartInput* in) { in->set.emplace_back("v20", 1.0); }, "v20", "v20 = 0"},
        BadInput{"FreeName", [](StartInput* in) { in->free = {"mu"}; }, "free", "'mu'"},
        BadInput{"FixName", [](StartInput* in) { in->fix = {{"mu", 1.0}}; }, "fix", "'mu'"},
        BadInput{"FreeAndFixed", [](StartInput* in) { in->free = {"u_r"}, in->fix = {{"u_r", std::nullopt}}; }, "fix",
                 "released by free as well"},
        BadInput{"NotSquare", [](StartInput* in) { in->free = {"u_r"}; }, "unknowns", "9 unknowns"},
        BadInput{"TiedRelease", [](StartInput* in) { in->tie_u_r = true, in->free = {"u_r"}; }, "free", "tied"},
        BadInput{"PaperChoiceWithoutPreset", [](StartInput* in) { in->paper_choice = true; }, "paper_choice",
                 "only with a preset"},
        BadInput{"ParameterName", [](StartInput* in) { in->parameter = ""; }, "parameter", "not a variable"},
        BadInput{"ParameterAnUnknown", [](StartInput* in) { in->parameter = "x10"; }, "parameter", "unknown already"},
        BadInput{"ParameterTied", [](StartInput* in) { in->tie_u_r = true, in->parameter = "u_r"; }, "parameter",
                 "tied to u_s"}),
    [](const ::testing::TestParamInfo<BadInput>& test) { return std::string(test.param.what); });

TEST(ModelStart, TakesThePaperExampleAndSet) {
  StartInput input;
  input.preset = "paper-4.1";
  input.set = {{"v20", 0.5}, {"omega", 0.65}};
  const ModelStart start = BuildModelStart(input);
  EXPECT_EQ(start.parameters.omega, 0.65);
  EXPECT_EQ(start.parameters.u_r, 0.2996);
  EXPECT_EQ(start.initial_state, State(1.5608, 3.3295, 0.1523, 0.5));
  EXPECT_EQ(start.phi, 0.3925);
}

TEST(ModelStart, TakesARestartPointsColumns) {
  StartInput input;
  input.restart = RestartPoint{"run", "TR1", "slip-", {{"chi", 0.3}, {"eta", 4}, {"omega", 0.6}, {"u_s", 0.1},
                                                     {"u_r", 0.3}, {"x10", 1}, {"v10", 2}, {"phi", 3}, {"d1", 9}}};
  const ModelStart start = BuildModelStart(input);
  EXPECT_EQ(start.initial_state, State(1, 0, 2, 0));
  EXPECT_EQ(start.phi, 3.0);
  EXPECT_EQ(start.parameters.eta, 4.0);
}

TEST(ModelStart, RefusesAPresetBesideARestartPointAndOrbitMembers) {
  StartInput input;
  input.preset = "paper-4.1";
  input.restart = RestartPoint{"run", "TR1", "slip-", {}};
  EXPECT_EQ(ErrorOf([&] { BuildModelStart(input); }).field(), "restart");
  input.restart.reset();
  input.guess = {{"d1", 1.0}};
  EXPECT_EQ(ErrorOf([&] { BuildModelStart(input); }).field(), "guess");
}

}  // namespace
}  // namespace stickslip
