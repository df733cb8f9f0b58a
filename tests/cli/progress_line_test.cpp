// The progress line: drawn in place with '\r', not before a delay, not more often than its
// interval, erased at the end, and nothing at all when disabled (stderr not a terminal). A clock of
// the test's own makes the timing exact.
#include "progress_line.hpp"

#include <cstdio>
#include <string>

#include <gtest/gtest.h>

namespace stickslip::cli {
namespace {

struct FakeClock {
  ProgressLine::Clock::time_point now{};
  void Advance(double seconds) {
    now += std::chrono::duration_cast<ProgressLine::Clock::duration>(std::chrono::duration<double>(seconds));
  }
};

std::string Contents(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string out;
  for (int c; (c = std::fgetc(f)) != EOF;) out += static_cast<char>(c);
  std::fseek(f, 0, SEEK_END);
  return out;
}

TEST(ProgressLine, DrawsAfterTheDelayAtMostOncePerIntervalAndErasesAtTheEnd) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  FakeClock clock;
  {
    ProgressLine line("sweep", {}, f, true, [&] { return clock.now; });
    line.Update({1, 10, "points"});
    EXPECT_EQ(Contents(f), "");  // a quick command shows nothing
    clock.Advance(1.0);
    line.Update({2, 10, "points"});
    EXPECT_EQ(Contents(f), "\rsweep: 2/10 points (20%), 2 points/s, 4 s left");
    clock.Advance(0.1);
    line.Update({3, 10, "points"});  // within the interval: not drawn
    EXPECT_EQ(Contents(f), "\rsweep: 2/10 points (20%), 2 points/s, 4 s left");
    clock.Advance(0.1);
    line.Update({4, 10, "points"});
    EXPECT_EQ(Contents(f).substr(47), "\rsweep: 4/10 points (40%), 3.33 points/s, 2 s left");
  }
  // Destroyed: blanks over the longest text and returns to the start of the line.
  const std::string all = Contents(f);
  EXPECT_EQ(all.substr(all.size() - 51), "\r" + std::string(49, ' ') + "\r");
  std::fclose(f);
}

TEST(ProgressLine, DrawsNothingWhenDisabled) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  FakeClock clock;
  {
    ProgressLine line("run", {}, f, false, [&] { return clock.now; });
    EXPECT_FALSE(line.enabled());
    EXPECT_FALSE(line.Callback());  // the library is not asked to report
    for (int k = 0; k < 10; ++k) {
      clock.Advance(1.0);
      line.Update({static_cast<double>(k), 10, "points"});
    }
    line.Clear();
  }
  EXPECT_EQ(Contents(f), "");
  std::fclose(f);
}

TEST(ProgressLine, TextNamesTheValueAndCountsTimeLeftFromTheRate) {
  Progress p{120, 400, "points", 0.61234};
  EXPECT_EQ(ProgressLine::Text("paper-5.1-omega-up", p, 4.0, "omega"),
            "paper-5.1-omega-up: 120/400 points (30%), 30 points/s, 9 s left, omega = 0.61234");
  EXPECT_EQ(ProgressLine::Text("simulate", {3, 1e6, "periods"}, 1.0, ""),
            "simulate: 3/1e+06 periods (0%), 3 periods/s, 92 h 35 min left");
  EXPECT_EQ(ProgressLine::Text("x", {0, 10, "points"}, 1.0, "omega"), "x: 0/10 points (0%)");
}

}  // namespace
}  // namespace stickslip::cli
