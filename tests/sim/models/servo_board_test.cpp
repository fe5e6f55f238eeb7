// ServoBoard: firmware arithmetic, once-per-period width updates and the output waveform.
#include <gtest/gtest.h>

#include <vector>

#include "models/servo_board.hpp"

namespace stepdance::sim {
namespace {

constexpr SimTime kPeriod = 24850 * kMicrosecond;  // 24 000 + 850 µs
constexpr SimTime kSample = 3500;                  // 3.5 µs after a pulse starts

/// Width of pulses 0..count−1, read at each pulse's start.
std::vector<int> widths(ServoBoard& board, int count) {
  std::vector<int> out;
  for (int k = 0; k < count; ++k) out.push_back(board.pulse_width_us_at(board.pulse_start(k)));
  return out;
}

void steps(ServoBoard& board, SimTime first, int count, bool dir_high) {
  for (int i = 0; i < count; ++i) board.on_step_rising(first + i * 40 * kMicrosecond, dir_high);
}

TEST(ServoBoard, BuildSettingsMatchTheFirmware) {
  ServoBoard narrow(ServoBuild::k90deg);
  ServoBoard wide(ServoBuild::k180deg);
  EXPECT_TRUE(narrow.settings_valid());
  EXPECT_TRUE(wide.settings_valid());
  EXPECT_EQ(narrow.period(), kPeriod);
  EXPECT_EQ(narrow.neutral_width_us(), 1540);
  EXPECT_EQ(narrow.settings().top_limit_steps, 500);
  EXPECT_EQ(wide.settings().bottom_limit_steps, -750);
}

TEST(ServoBoard, StepsReachThePulseAfterTheNextSample) {
  ServoBoard board;
  steps(board, 1 * kMillisecond, 200, true);  // 1.00 .. 8.96 ms, during pulse 0
  // Sample 1 (24 853.5 µs) sees +200, so pulse 2 at 49 700 µs is 1540 + 200.
  EXPECT_EQ(widths(board, 4), (std::vector<int>{1540, 1540, 1740, 1740}));
  EXPECT_EQ(board.pulse_width_us_at(2 * kPeriod - 1), 1540);
  EXPECT_EQ(board.pulse_width_us_at(2 * kPeriod), 1740);
}

TEST(ServoBoard, WidthOnlyChangesAtPeriodBoundaries) {
  ServoBoard board;
  steps(board, 30 * kMillisecond, 100, true);   // during pulse 1, after sample 1: reaches pulse 3
  steps(board, 60 * kMillisecond, 220, false);  // during pulse 2, after sample 2: reaches pulse 4
  EXPECT_EQ(widths(board, 6), (std::vector<int>{1540, 1540, 1540, 1640, 1420, 1420}));
  for (int k = 0; k < 5; ++k) {
    const int at_start = board.pulse_width_us_at(board.pulse_start(k));
    EXPECT_EQ(board.pulse_width_us_at(board.pulse_start(k) + kPeriod / 2), at_start);
    EXPECT_EQ(board.pulse_width_us_at(board.pulse_start(k + 1) - 1), at_start);
  }
}

TEST(ServoBoard, AStepAtTheSampleInstantMissesThatSample) {
  ServoBoard board;
  board.on_step_rising(kPeriod + kSample - 1, true);  // just before sample 1
  board.on_step_rising(kPeriod + kSample, true);      // at sample 1: counted after it
  EXPECT_EQ(widths(board, 4), (std::vector<int>{1540, 1540, 1541, 1542}));
}

TEST(ServoBoard, WindowIsClampedButTheCountKeepsGoing) {
  ServoBoard narrow(ServoBuild::k90deg);
  ServoBoard wide(ServoBuild::k180deg);
  steps(narrow, 0, 600, true);
  steps(wide, 0, 800, false);
  EXPECT_EQ(narrow.position_steps(), 600);
  EXPECT_EQ(narrow.pulse_width_us_at(2 * kPeriod), 2040);  // 1540 + 500
  EXPECT_EQ(wide.pulse_width_us_at(2 * kPeriod), 918);     // 622 steps by sample 1 (24 853.5 µs)
  EXPECT_EQ(wide.pulse_width_us_at(3 * kPeriod), 790);     // all 800: 1540 − 750
  steps(narrow, 3 * kPeriod, 150, false);                  // 450: back inside the window
  EXPECT_EQ(narrow.pulse_width_us_at(5 * kPeriod), 1990);
}

TEST(ServoBoard, OutputIsHighForTheWidthFromEachPulseStart) {
  ServoBoard board;
  steps(board, 0, 200, true);
  EXPECT_TRUE(board.output_high_at(0));
  EXPECT_TRUE(board.output_high_at(1540 * kMicrosecond - 1));
  EXPECT_FALSE(board.output_high_at(1540 * kMicrosecond));
  EXPECT_TRUE(board.output_high_at(2 * kPeriod + 1740 * kMicrosecond - 1));
  EXPECT_FALSE(board.output_high_at(2 * kPeriod + 1740 * kMicrosecond));
  EXPECT_FALSE(board.output_high_at(3 * kPeriod - 1));
}

TEST(ServoBoard, NothingHappensBeforePowerUp) {
  ServoBoard board(ServoBuild::k90deg, 10 * kMicrosecond);
  board.on_step_rising(5 * kMicrosecond, true);
  EXPECT_EQ(board.steps_before_power_up(), 1u);
  EXPECT_EQ(board.position_steps(), 0);
  EXPECT_EQ(board.pulse_index_at(9 * kMicrosecond), -1);
  EXPECT_EQ(board.pulse_width_us_at(9 * kMicrosecond), 0);
  EXPECT_FALSE(board.output_high_at(9 * kMicrosecond));
  EXPECT_EQ(board.pulse_start(1), 10 * kMicrosecond + kPeriod);
  EXPECT_EQ(board.pulse_width_us_at(10 * kMicrosecond), 1540);
}

TEST(ServoBoard, EarlierTimesAreAnsweredFromHistory) {
  ServoBoard board;
  steps(board, 0, 10, true);
  EXPECT_EQ(board.pulse_width_us_at(10 * kPeriod), 1550);
  EXPECT_EQ(board.pulse_width_us_at(kPeriod), 1540);
  EXPECT_EQ(board.pulse_width_us_at(2 * kPeriod), 1550);
}

}  // namespace
}  // namespace stepdance::sim
