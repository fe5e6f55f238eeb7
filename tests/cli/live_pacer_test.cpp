// LivePacer: a live run keeps to `speed` times the wall clock; when it falls behind it makes up
// at most LivePacer::kCatchUpLimit and gives the rest up, so it never runs faster than `speed`
// to catch up (a sender slowed by the same load would be outrun and its queue drained).
#include "live_pacer.hpp"

#include <gtest/gtest.h>

namespace stepdance::cli {
namespace {

using Clock = LivePacer::Clock;
using std::chrono::microseconds;
using std::chrono::milliseconds;

const Clock::time_point kStart = Clock::time_point{} + std::chrono::seconds(100);

TEST(LivePacer, OnTimeInstantsAreDueAtSpeedTimesTheWallClock) {
  LivePacer pacer;
  pacer.anchor(kStart, 0, 4.0);
  // 1 simulated ms at 4x is due 0.25 ms after the anchor; reached early, nothing is late.
  const LivePacer::Due due = pacer.due(sim::kMillisecond, kStart + microseconds(100));
  EXPECT_EQ(due.wall, kStart + microseconds(250));
  EXPECT_EQ(due.lag_ms, 0.0);
  EXPECT_EQ(due.given_up_ms, 0.0);
}

TEST(LivePacer, ASmallLagIsMadeUp) {
  LivePacer pacer;
  pacer.anchor(kStart, 0, 4.0);
  // Due at 0.5 ms, reached at 1.5 ms: 1 ms late, within the catch-up limit: nothing given up,
  // and the next instants keep their places on the clock.
  const LivePacer::Due late = pacer.due(2 * sim::kMillisecond, kStart + microseconds(1500));
  EXPECT_DOUBLE_EQ(late.lag_ms, 1.0);
  EXPECT_EQ(late.given_up_ms, 0.0);
  EXPECT_EQ(pacer.due(10 * sim::kMillisecond, kStart + microseconds(1500)).wall, kStart + microseconds(2500));
}

TEST(LivePacer, ALongStallIsGivenUpNotCaughtUpInABurst) {
  LivePacer pacer;
  pacer.anchor(kStart, 0, 4.0);
  // The run was descheduled: the instant at 2 ms (due at 0.5 ms) is reached 50 ms into the run.
  const Clock::time_point woke = kStart + milliseconds(50);
  const LivePacer::Due stalled = pacer.due(2 * sim::kMillisecond, woke);
  EXPECT_DOUBLE_EQ(stalled.lag_ms, 49.5);
  EXPECT_DOUBLE_EQ(stalled.given_up_ms, 49.5 - 2.0);
  EXPECT_EQ(stalled.wall, woke - milliseconds(2));
  // The next 40 simulated ms take 10 ms of wall time at 4x, less the 2 ms made up: the run
  // does not race through them (without the limit they would all be due 40 ms ago).
  EXPECT_EQ(pacer.due(42 * sim::kMillisecond, woke).wall, woke + milliseconds(8));
}

}  // namespace
}  // namespace stepdance::cli
