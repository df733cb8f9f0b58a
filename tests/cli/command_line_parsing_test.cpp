// A seeded fuzz test of the command line's parsers (issue 11): ParseNumber and ParseCount, the
// KEY=VALUE texts of --set, --guess and --fix, and Signature::Parse, on 20000 generated inputs
// each (deterministic: a splitmix64 generator with a fixed seed; a second of run time). Every
// input gives a value or InvalidInput, never a crash or another exception; an accepted number is
// what strtod reads from the same text, all of it; an accepted signature reads back from its
// text form as itself. tests/fuzz/command_line_fuzzer.cpp runs the same properties under
// libFuzzer.
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "number_text.hpp"
#include "start_options.hpp"
#include "stickslip/invalid_input.hpp"
#include "stickslip/orbits/signature.hpp"

namespace stickslip::cli {
namespace {

constexpr int kInputs = 20000;

// splitmix64: the same numbers on every platform.
class Generator {
 public:
  explicit Generator(std::uint64_t seed) : state_(seed) {}
  std::uint64_t Next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  std::size_t Below(std::size_t n) { return static_cast<std::size_t>(Next() % n); }
  template <typename T>
  const T& Pick(const std::vector<T>& items) { return items[Below(items.size())]; }

 private:
  std::uint64_t state_;
};

// Texts near numbers: pieces of decimal syntax, words strtod knows (inf, nan, 0x), signs,
// spaces, huge and tiny exponents and an occasional arbitrary byte, in random order.
std::string NumberLikeText(Generator& g) {
  static const std::vector<std::string> pieces = {
      "0", "1", "2", "5", "9", "12", "0.5", ".", "e", "E", "e-", "e+", "+", "-", "308", "309", "-324", "400",
      "1e308", "1e-310", "inf", "nan", "infinity", "0x", "1p3", " ", "\t", "=", ",", "_", "x", "1'000", "\n"};
  std::string text;
  const std::size_t count = g.Below(6);
  for (std::size_t i = 0; i < count; ++i) {
    if (g.Below(20) == 0) {
      text += static_cast<char>(g.Below(256));
    } else {
      text += g.Pick(pieces);
    }
  }
  return text;
}

// What strtod reads from the whole text, if it reads all of it to a finite number.
std::optional<double> StrtodWhole(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

// Plain decimal text with a normal (not subnormal, not overflowing) value must be accepted.
bool PlainDecimal(const std::string& text) {
  static const std::regex decimal(R"([+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?)");
  if (!std::regex_match(text, decimal)) return false;
  const std::optional<double> value = StrtodWhole(text);
  return value && (*value == 0.0 || std::abs(*value) >= 2.3e-308) && errno == 0;
}

TEST(CommandLineParsing, NumbersAreStrtodOfTheWholeTextOrInvalidInput) {
  Generator g(20261124);
  int accepted = 0;
  for (int i = 0; i < kInputs; ++i) {
    const std::string text = NumberLikeText(g);
    SCOPED_TRACE("text '" + text + "'");
    try {
      const double value = ParseNumber("x", text, "a number");
      ++accepted;
      const std::optional<double> expected = StrtodWhole(text);
      ASSERT_TRUE(expected.has_value());
      ASSERT_EQ(value, *expected);
      ASSERT_TRUE(std::isfinite(value));
    } catch (const InvalidInput& e) {
      ASSERT_EQ(e.field(), "x");
      ASSERT_FALSE(PlainDecimal(text));
    }
  }
  EXPECT_GT(accepted, kInputs / 20);  // the generator reaches both outcomes
  EXPECT_LT(accepted, kInputs);
}

TEST(CommandLineParsing, CountsAreWholeNumbersInTheirRangeOrInvalidInput) {
  Generator g(7);
  int accepted = 0;
  for (int i = 0; i < kInputs; ++i) {
    const std::string text = NumberLikeText(g);
    SCOPED_TRACE("text '" + text + "'");
    try {
      const int value = ParseCount("max-points", text, 1, 1000000);
      ++accepted;
      const std::optional<double> expected = StrtodWhole(text);
      ASSERT_TRUE(expected.has_value());
      ASSERT_EQ(static_cast<double>(value), *expected);
      ASSERT_TRUE(value >= 1 && value <= 1000000);
    } catch (const InvalidInput& e) {
      ASSERT_EQ(e.field(), "max-points");
    }
  }
  EXPECT_GT(accepted, 0);
}

TEST(CommandLineParsing, RefusesASignAfterTheLeadingPlus) {
  for (const char* text : {"+-5", "++5", "+", "-", "+ 5", " 5", "5 ", "0x10", "1e400", "inf", "nan"}) {
    EXPECT_THROW(ParseNumber("x", text, "a number"), InvalidInput) << text;
  }
  EXPECT_EQ(ParseNumber("x", "+5", "a number"), 5.0);
}

TEST(CommandLineParsing, AssignmentsGiveTheNameBeforeTheFirstEqualsAndTheNumberAfterIt) {
  Generator g(11);
  static const std::vector<std::string> names = {"omega", "u_s", "x10", "d1", "", "phi", "omega=", "a b"};
  int accepted = 0;
  for (int i = 0; i < kInputs; ++i) {
    std::string text = g.Below(10) == 0 ? NumberLikeText(g) : g.Pick(names) + "=" + NumberLikeText(g);
    SCOPED_TRACE("text '" + text + "'");
    StartFlags flags;
    const int which = static_cast<int>(g.Below(3));
    (which == 0 ? flags.set : which == 1 ? flags.guess : flags.fix).push_back(text);
    try {
      const StartInput input = ToStartInput(flags);
      const std::size_t equals = text.find('=');
      if (which == 2 && equals == std::string::npos) {  // --fix NAME holds a variable at its guess
        ASSERT_EQ(input.fix.size(), 1u);
        ASSERT_EQ(input.fix[0].name, text);
        ASSERT_FALSE(input.fix[0].value.has_value());
        continue;
      }
      ++accepted;
      ASSERT_NE(equals, std::string::npos);
      const std::optional<double> expected = StrtodWhole(text.substr(equals + 1));
      ASSERT_TRUE(expected.has_value());
      const std::string name = text.substr(0, equals);
      if (which == 2) {
        ASSERT_EQ(input.fix[0].name, name);
        ASSERT_EQ(input.fix[0].value, expected);
      } else {
        const NamedValues& values = which == 0 ? input.set : input.guess;
        ASSERT_EQ(values.size(), 1u);
        ASSERT_EQ(values[0].first, name);
        ASSERT_EQ(values[0].second, *expected);
      }
    } catch (const InvalidInput&) {
    }
  }
  EXPECT_GT(accepted, kInputs / 20);
}

// Texts near signatures: modes, the option words and numbers, misspellings, separators.
std::string SignatureLikeText(Generator& g) {
  static const std::vector<std::string> tokens = {
      "slip-", "slip+", "stick", "slip", "stik", "/", "antisymmetric", "period", "1", "2", "4", "0", "-1", "2.5",
      "1e9", "99999999999", "x", "  ", "\t", "slip-slip+", "/ /", "period period"};
  std::string text;
  const std::size_t count = 1 + g.Below(8);
  for (std::size_t i = 0; i < count; ++i) {
    if (g.Below(30) == 0) {
      text += static_cast<char>(g.Below(256));
    } else {
      text += g.Pick(tokens);
    }
    text += g.Below(8) == 0 ? "" : " ";
  }
  return text;
}

TEST(CommandLineParsing, AcceptedSignaturesReadBackFromTheirTextForm) {
  Generator g(3);
  int accepted = 0;
  for (int i = 0; i < kInputs; ++i) {
    const std::string text = SignatureLikeText(g);
    SCOPED_TRACE("text '" + text + "'");
    try {
      const Signature signature = Signature::Parse(text);
      ++accepted;
      const std::string form = signature.ToString();
      const Signature again = Signature::Parse(form);
      ASSERT_EQ(again, signature);
      ASSERT_EQ(again.ToString(), form);
      ASSERT_GE(signature.size(), 1);
      ASSERT_GE(signature.period_multiple(), 1);
    } catch (const InvalidInput& e) {
      ASSERT_EQ(e.field(), "signature");
    }
  }
  EXPECT_GT(accepted, kInputs / 100);  // the generator reaches both outcomes
}

}  // namespace
}  // namespace stickslip::cli
