// Tests for study/progress.h, driven through an std::ostringstream: Lines prints rate-limited
// progress lines, an end line per step, "cached" lines and the summary table; Terminal
// redraws one line with '\r' no more often than its interval allows; Quiet prints nothing;
// advance() from two threads sums exactly; start() of a new step ends the previous one.
#include "dayphoton/study/progress.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace dayphoton::study {
namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

TEST(Progress, ChooseStyle) {
  EXPECT_EQ(Progress::choose_style(true, false), ProgressStyle::Terminal);
  EXPECT_EQ(Progress::choose_style(false, false), ProgressStyle::Lines);
  EXPECT_EQ(Progress::choose_style(true, true), ProgressStyle::Quiet);
  EXPECT_EQ(Progress::choose_style(false, true), ProgressStyle::Quiet);
}

TEST(Progress, LinesPrintsStepEndsCachedStepsAndSummary) {
  std::ostringstream out;
  Progress progress(out, ProgressStyle::Lines, 1e9);  // no intermediate lines
  progress.start("photons", 10, "photons");
  for (int i = 0; i < 10; ++i) progress.advance();
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  progress.cached("sky matrix");  // ends "photons"
  progress.start("coefficients", 4, "sensors");
  progress.advance(4);
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  progress.note("coefficients: 2 grids");
  progress.print_summary();  // ends "coefficients"

  const std::string text = out.str();
  const std::vector<std::string> lines = lines_of(text);
  ASSERT_GE(lines.size(), 4u) << text;
  EXPECT_EQ(lines[0].rfind("photons: done in ", 0), 0u) << lines[0];
  EXPECT_TRUE(has(lines[0], "(10 photons,")) << lines[0];
  EXPECT_EQ(lines[1], "sky matrix: cached");
  EXPECT_EQ(lines[2], "coefficients: 2 grids");
  EXPECT_EQ(lines[3].rfind("coefficients: done in ", 0), 0u) << lines[3];
  // The table: header, one row per step in order, total.
  ASSERT_EQ(lines.size(), 4u + 1 + 3 + 1) << text;
  for (const char* column : {"step", "work", "unit", "seconds", "rate", "share"})
    EXPECT_TRUE(has(lines[4], column)) << lines[4];
  EXPECT_EQ(lines[5].rfind("photons", 0), 0u);
  EXPECT_TRUE(has(lines[5], " 10 ")) << lines[5];
  EXPECT_EQ(lines[6].rfind("sky matrix", 0), 0u);
  EXPECT_TRUE(has(lines[6], "from cache")) << lines[6];  // a cached step shows no time
  EXPECT_FALSE(has(lines[6], "0.00")) << lines[6];
  EXPECT_EQ(lines[7].rfind("coefficients", 0), 0u);
  EXPECT_TRUE(has(lines[7], "sensors")) << lines[7];
  EXPECT_EQ(lines[8].rfind("total", 0), 0u);
  EXPECT_TRUE(has(lines[8], "100.0 %")) << lines[8];
  // No '\r' redraws in a log.
  EXPECT_FALSE(has(text, "\r"));

  const auto& steps = progress.steps();
  ASSERT_EQ(steps.size(), 3u);
  EXPECT_EQ(steps[0].name, "photons");
  EXPECT_EQ(steps[0].work, 10u);
  EXPECT_GE(steps[0].seconds, 0.005);
  EXPECT_FALSE(steps[0].cached);
  EXPECT_TRUE(steps[1].cached);
  EXPECT_EQ(steps[1].work, 0u);
  EXPECT_EQ(steps[2].unit, "sensors");
  EXPECT_EQ(steps[2].work, 4u);
}

TEST(Progress, LinesAreRateLimitedByTheInterval) {
  // Interval 0: every advance is due and prints its own line.
  std::ostringstream every;
  {
    Progress progress(every, ProgressStyle::Lines, 0.0);
    progress.start("sensors", 4, "sensors");
    for (int i = 0; i < 4; ++i) progress.advance();
  }  // the destructor ends the step
  const std::vector<std::string> lines = lines_of(every.str());
  ASSERT_EQ(lines.size(), 5u) << every.str();
  EXPECT_EQ(lines[0].rfind("sensors: 1/4 sensors (25.0 %), ", 0), 0u) << lines[0];
  EXPECT_TRUE(has(lines[0], "sensors/s")) << lines[0];
  EXPECT_TRUE(has(lines[0], "ETA ")) << lines[0];
  EXPECT_EQ(lines[3].rfind("sensors: 4/4 sensors (100.0 %), ", 0), 0u) << lines[3];
  EXPECT_EQ(lines[4].rfind("sensors: done in ", 0), 0u) << lines[4];

  // A long interval: only the end line, however much work is reported.
  std::ostringstream rarely;
  Progress progress(rarely, ProgressStyle::Lines, 1e9);
  progress.start("hours", 8760, "hours");
  for (int i = 0; i < 8760; ++i) progress.advance();
  progress.end();
  EXPECT_EQ(lines_of(rarely.str()).size(), 1u) << rarely.str();
}

TEST(Progress, UnknownTotalHasNoPercentageOrEta) {
  std::ostringstream out;
  Progress progress(out, ProgressStyle::Lines, 0.0);
  progress.start("sources", 0, "sources");
  progress.advance(3);
  progress.end();
  const std::vector<std::string> lines = lines_of(out.str());
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].rfind("sources: 3 sources, ", 0), 0u) << lines[0];
  EXPECT_FALSE(has(lines[0], "%"));
  EXPECT_FALSE(has(lines[0], "ETA"));
}

TEST(Progress, QuietPrintsNothing) {
  std::ostringstream out;
  {
    Progress progress(out, ProgressStyle::Quiet, 0.0);
    progress.start("photons", 10, "photons");
    progress.advance(10);
    progress.note("hello");
    progress.cached("sky");
    progress.start("coefficients", 1, "sensors");
    progress.print_summary();
    EXPECT_EQ(progress.steps().size(), 3u);  // still recorded
  }
  EXPECT_TRUE(out.str().empty()) << out.str();
}

TEST(Progress, StartEndsThePreviousStep) {
  std::ostringstream out;
  Progress progress(out, ProgressStyle::Lines, 1e9);
  progress.start("a", 5, "things");
  progress.advance(3);
  EXPECT_TRUE(progress.steps().empty());
  progress.start("b", 5, "things");
  ASSERT_EQ(progress.steps().size(), 1u);
  EXPECT_EQ(progress.steps()[0].name, "a");
  EXPECT_EQ(progress.steps()[0].work, 3u);  // what was done, not the announced total
  EXPECT_TRUE(has(out.str(), "a: done in "));
  progress.advance(2);
  progress.end();
  progress.end();  // no open step: nothing happens
  ASSERT_EQ(progress.steps().size(), 2u);
  EXPECT_EQ(progress.steps()[1].work, 2u);  // the new step counts from zero
}

TEST(Progress, AdvanceFromTwoThreadsSumsExactly) {
  std::ostringstream out;
  Progress progress(out, ProgressStyle::Terminal);
  constexpr std::uint64_t PerThread = 300000;
  progress.start("photons", 2 * PerThread, "photons");
  const auto begin = std::chrono::steady_clock::now();
  std::thread a([&] { for (std::uint64_t i = 0; i < PerThread; ++i) progress.advance(); });
  std::thread b([&] { for (std::uint64_t i = 0; i < PerThread / 2; ++i) progress.advance(2); });
  a.join();
  b.join();
  const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
  progress.end();
  ASSERT_EQ(progress.steps().size(), 1u);
  EXPECT_EQ(progress.steps()[0].work, 2 * PerThread);

  // Redraws: one at start, one at the end, and between them at most one per
  // TerminalInterval_s (plus one for a draw falling due at the very end of the loop).
  const std::string text = out.str();
  const auto redraws = std::count(text.begin(), text.end(), '\r');
  EXPECT_GE(redraws, 2);
  EXPECT_LE(double(redraws), 3.0 + elapsed_s / Progress::TerminalInterval_s) << elapsed_s << " s";
  EXPECT_TRUE(has(text, "[####################] photons  600000 photons  ")) << text;
  EXPECT_TRUE(has(text, "done in ")) << text;
  EXPECT_EQ(text.back(), '\n');
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1);
}

TEST(Progress, TerminalRedrawsOneLineAndKeepsNotesAboveIt) {
  std::ostringstream out;
  Progress progress(out, ProgressStyle::Terminal);
  progress.start("annual illuminance", 8760, "hours");
  progress.advance(4380);
  progress.note("grid 1 of 2");
  progress.end();
  progress.cached("metrics");
  const std::string text = out.str();
  // The start draw: an empty bar, the step, the count and an unknown ETA.
  EXPECT_EQ(text.rfind("\r[....................] annual illuminance  0/8760 hours  ", 0), 0u) << text;
  // The note replaces the status line (padded over it), then the status is redrawn at half.
  EXPECT_TRUE(has(text, "\rgrid 1 of 2 ")) << text;
  EXPECT_TRUE(has(text, "\n\r[##########..........] annual illuminance  4380/8760 hours  ")) << text;
  EXPECT_TRUE(has(text, "ETA ")) << text;
  EXPECT_TRUE(has(text, "done in ")) << text;
  EXPECT_TRUE(has(text, "\nmetrics: cached\n")) << text;
}

}  // namespace
}  // namespace dayphoton::study
