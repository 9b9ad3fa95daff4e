// Progress of a run: the text, and when it is shown on a terminal and in a log.
#include "progress.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

namespace dymesh::cli {
namespace {

TEST(FormatProgress, BarPercentTimeRateAndEta) {
  EXPECT_EQ(FormatProgress(0.1, 0.25, 200, 2.0, 10), "[####......]  40%  t 0.1000 / 0.2500 s  100 steps/s  ETA 3 s");
  EXPECT_EQ(FormatProgress(0.1, 0.25, 200, 2.0, 0), " 40%  t 0.1000 / 0.2500 s  100 steps/s  ETA 3 s");
  EXPECT_NE(FormatProgress(0.1, 0.25, 200, 100.0, 0).find("ETA 2 min 30 s"), std::string::npos);
  EXPECT_NE(FormatProgress(0.01, 0.25, 200, 1000.0, 0).find("ETA 6 h 40 min"), std::string::npos);
  EXPECT_EQ(FormatProgress(0.0, 0.25, 0, 0.0, 4), "[....]   0%  t 0.0000 / 0.2500 s  0 steps/s");
}

// a clock the test moves by hand
struct FakeClock {
  double now = 100.0;
};

TEST(ProgressReporter, ShortRunsShowNothing) {
  FakeClock clock;
  std::ostringstream out;
  ProgressReporter progress(out, 0.25, {.terminal = true}, [&] { return clock.now; });
  for (int k = 1; k <= 100; ++k) {
    clock.now += 0.019;
    progress.Update(k * 0.0025, k);
  }
  progress.Finish();
  EXPECT_EQ(out.str(), "");
}

TEST(ProgressReporter, PlainLinesEveryFewSecondsInALog) {
  FakeClock clock;
  std::ostringstream out;
  ProgressReporter progress(out, 1.0, {.terminal = false}, [&] { return clock.now; });
  clock.now += 1.9;
  progress.Update(0.1, 100);
  EXPECT_EQ(out.str(), "");
  clock.now += 0.1;  // 2 s: first line
  progress.Update(0.2, 200);
  EXPECT_EQ(out.str(), "progress:  20%  t 0.2000 / 1.0000 s  100 steps/s  ETA 8 s\n");
  clock.now += 4.0;  // 6 s: not yet
  progress.Update(0.5, 500);
  clock.now += 1.5;  // 7.5 s: second line
  progress.Update(0.6, 600);
  progress.Finish();
  const std::string s = out.str();
  EXPECT_EQ(std::count(s.begin(), s.end(), '\n'), 2);
  EXPECT_EQ(s.find('\r'), std::string::npos);
}

TEST(ProgressReporter, BarRedrawnInPlaceOnATerminalAndCleared) {
  FakeClock clock;
  std::ostringstream out;
  ProgressReporter progress(out, 1.0, {.terminal = true, .bar_width = 10}, [&] { return clock.now; });
  clock.now += 2.0;
  progress.Update(0.5, 1000);
  EXPECT_EQ(out.str(), "\r\033[K[#####.....]  50%  t 0.5000 / 1.0000 s  500 steps/s  ETA 2 s");
  clock.now += 0.05;  // within the redraw period
  progress.Update(0.51, 1020);
  clock.now += 0.1;
  progress.Update(0.6, 1200);
  progress.Finish();
  const std::string s = out.str();
  EXPECT_EQ(std::count(s.begin(), s.end(), '\r'), 3);  // two draws and the clearing
  EXPECT_EQ(s.substr(s.size() - 4), "\r\033[K");
  EXPECT_EQ(s.find('\n'), std::string::npos);
}

}  // namespace
}  // namespace dymesh::cli
