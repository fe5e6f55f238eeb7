// GCodeInterface end to end on the manual board: G-code text in, planned motion out.
#include "stepdance/interfaces/gcode/gcode_interface.hpp"

#include <gtest/gtest.h>

#include <math.h>

#include <string>
#include <vector>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/text_writer.hpp"
#include "support/engine_fixture.hpp"
#include "support/fake_byte_stream.hpp"

namespace stepdance {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDt = 40e-6;

/// An Arduino-style port that is not a ByteStream (as Teensyduino's usb_serial_class).
struct ArduinoStylePort {
  test_support::FakeByteStream link;
  int began_baud = 0;
  int available() { return static_cast<int>(link.bytes_available()); }
  int read() { return link.read_byte(); }
  int availableForWrite() { return static_cast<int>(link.write_space()); }
  size_t write(const uint8_t* data, size_t length) { return link.write_bytes(data, length); }
  void begin(uint32_t baud, uint16_t) { began_baud = static_cast<int>(baud); }
};

class GCodeInterfaceTest : public test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    ASSERT_EQ(gcode.begin(&host), Status::kOk);
    ASSERT_EQ(dance_start(), Status::kOk);
    step();
    ASSERT_NE(host.take().find("Grbl 1.1"), std::string::npos);
  }
  void step() {
    dance_loop();
    hal_manual::run_frames(1);
    if (!record) return;  // 16 bytes a frame: long runs that need no history skip it
    x.push_back(gcode.output_x.read_absolute());
    y.push_back(gcode.output_y.read_absolute());
  }
  /// Runs until the host has nothing left to send and the planner has been idle for 100 frames
  /// (lines may still wait in the link's receive buffer between moves); returns frames run.
  int run_until_idle(int limit = 5'000'000) {
    int frames = 0;
    int idle_frames = 0;
    while (idle_frames < 100 && frames < limit) {
      step();
      ++frames;
      const bool idle = gcode.interpolator().is_idle() && host.to_board.empty();
      idle_frames = idle ? idle_frames + 1 : 0;
    }
    return frames;
  }
  static int count(const std::string& text, const std::string& word) {
    int n = 0;
    for (size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
    return n;
  }

  test_support::FakeByteStream host;
  GCodeInterface gcode;
  bool record = true;
  std::vector<double> x, y;
};

TEST_F(GCodeInterfaceTest, SquareEndsWhereItStartedWithOneOkPerLine) {
  host.send("G21 G90\nG1 X10 F600\nG1 Y10\nG1 X0\nG1 Y0\n");
  run_until_idle();
  const std::string replies = host.take();
  EXPECT_EQ(count(replies, "ok\r\n"), 5) << replies;
  EXPECT_EQ(count(replies, "error"), 0) << replies;
  EXPECT_DOUBLE_EQ(gcode.output_x.read_absolute(), 0.0);
  EXPECT_DOUBLE_EQ(gcode.output_y.read_absolute(), 0.0);
  double max_x = 0, max_y = 0;
  for (size_t i = 0; i < x.size(); ++i) max_x = fmax(max_x, x[i]), max_y = fmax(max_y, y[i]);
  EXPECT_DOUBLE_EQ(max_x, 10.0);
  EXPECT_DOUBLE_EQ(max_y, 10.0);
}

TEST_F(GCodeInterfaceTest, RapidRunsAtTheMaxRateSetting) {
  // $110 = 6000 mm/min = 100 mm/s, $120 = 500 mm/s²: t = L/v + v/a = 1 s + 0.2 s.
  record = false;  // 1.2 s of 10 µs frames is more history than the M7 target's RAM holds
  host.send("$110=6000\n$120=500\nG0 X100\n");
  // The first and last frame in which X changed, counted as run_until_idle() would run them.
  long frame = 0, first = -1, last = -1;
  double previous = gcode.output_x.read_absolute();
  for (int idle_frames = 0; idle_frames < 100 && frame < 5'000'000; ++frame) {
    step();
    const double now = gcode.output_x.read_absolute();
    if (now != previous) {
      if (first < 0) first = frame;
      last = frame;
      previous = now;
    }
    idle_frames = gcode.interpolator().is_idle() && host.to_board.empty() ? idle_frames + 1 : 0;
  }
  ASSERT_GE(first, 0);
  EXPECT_NEAR((last - first + 1) * kDt, 100.0 / 100.0 + 100.0 / 500.0, 3 * kDt);
  EXPECT_DOUBLE_EQ(gcode.output_x.read_absolute(), 100.0);
}

TEST_F(GCodeInterfaceTest, ArcStaysWithinTheArcToleranceAndEndsExactly) {
  // A full circle of radius 10 around (10, 0), starting at the origin; $12 = 0.01 mm.
  host.send("$12=0.01\nG2 X0 Y0 I10 J0 F1200\n");
  run_until_idle();
  double worst = 0.0;
  for (size_t i = 0; i < x.size(); ++i) worst = fmax(worst, fabs(hypot(x[i] - 10.0, y[i]) - 10.0));
  EXPECT_LE(worst, 0.01 + 1e-9);
  EXPECT_GT(worst, 0.0);  // chords, not a point
  EXPECT_NEAR(gcode.output_x.read_absolute(), 0.0, 1e-12);
  EXPECT_NEAR(gcode.output_y.read_absolute(), 0.0, 1e-12);
  // It went all the way round: it reached x = 20 on the far side.
  double far = 0.0;
  for (double value : x) far = fmax(far, value);
  EXPECT_NEAR(far, 20.0, 0.011);
}

TEST_F(GCodeInterfaceTest, ManyMoreLinesThanThePlannerHoldsAreAllExecutedInOrder) {
  std::string program = "G91 G1 F3000\n";
  for (int i = 0; i < 600; ++i) program += (i % 2 == 0) ? "X0.5\n" : "Y0.25\n";
  record = false;
  host.send(program);
  run_until_idle();
  const std::string replies = host.take();
  EXPECT_EQ(count(replies, "ok\r\n"), 601);
  EXPECT_EQ(count(replies, "error"), 0);
  EXPECT_DOUBLE_EQ(gcode.output_x.read_absolute(), 300 * 0.5);
  EXPECT_DOUBLE_EQ(gcode.output_y.read_absolute(), 300 * 0.25);
}

// At 10 µs frames the planner keeps real time: the same rapid takes the same 1.2 s (four times
// the frames) and ends exactly; a dwell still waits its 0.5 s.
TEST_F(GCodeInterfaceTest, AtTenMicrosecondFramesMovesAndDwellsKeepRealTime) {
  engine().stop();
  ASSERT_EQ(set_frame_period_us(10), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  constexpr double kDt10 = 10e-6;
  record = false;  // 1.2 s of 10 µs frames is more history than the M7 target's RAM holds
  host.send("$110=6000\n$120=500\nG0 X100\n");
  // The first and last frame in which X changed, counted as run_until_idle() would run them.
  long frame = 0, first = -1, last = -1;
  double previous = gcode.output_x.read_absolute();
  for (int idle_frames = 0; idle_frames < 100 && frame < 5'000'000; ++frame) {
    step();
    const double now = gcode.output_x.read_absolute();
    if (now != previous) {
      if (first < 0) first = frame;
      last = frame;
      previous = now;
    }
    idle_frames = gcode.interpolator().is_idle() && host.to_board.empty() ? idle_frames + 1 : 0;
  }
  ASSERT_GE(first, 0);
  EXPECT_NEAR((last - first + 1) * kDt10, 100.0 / 100.0 + 100.0 / 500.0, 0.001);
  EXPECT_DOUBLE_EQ(gcode.output_x.read_absolute(), 100.0);
  host.take();
  host.send("G4 P0.5\nG1 X101 F600\n");
  int frames = 0;
  while (gcode.output_x.read_absolute() == 100.0 && frames < 400000) {
    step();
    ++frames;
  }
  EXPECT_NEAR(frames * kDt10, 0.5 + TimeBasedInterpolator::kStartDelayUs * 1e-6, 0.002);
}

// Grbl's mc_dwell: protocol_buffer_synchronize (the queue drains), then delay_sec; the line's
// `ok` comes at the end, the state meanwhile is Idle (the planner is empty), and realtime
// commands are served throughout. Each loop pass returns (the test's step() runs one a frame).
TEST_F(GCodeInterfaceTest, DwellWaitsForTheQueueThenAnswersAtItsEnd) {
  host.send("$120=1000\nG1 X10 F600\n");
  for (int i = 0; i < 100; ++i) step();
  host.take();
  host.send("G4 P1.5\n");
  for (int i = 0; i < 100; ++i) step();
  EXPECT_EQ(host.take(), "");  // the move is still running: nothing is owed yet
  int frames = 100;
  while (gcode.output_x.read_absolute() != 10.0 && frames < 200000) {
    step();
    ++frames;
  }
  // From the G1 line: the start delay, 10 mm at 10 mm/s and its two 0.01 s ramps at 1000 mm/s².
  EXPECT_NEAR((frames + 100) * kDt, 0.02 + 10.0 / 10.0 + 10.0 / 1000.0, 0.01);
  const int move_end = frames;
  std::string replies;
  bool status_seen = false;
  while (replies.find("ok") == std::string::npos && frames < move_end + 100000) {
    if (frames == move_end + 18750) {  // halfway through the dwell
      host.send("?");
      step();
      ++frames;
      const std::string status = host.take();
      EXPECT_EQ(status.rfind("<Idle|", 0), 0u) << status;
      status_seen = true;
      continue;
    }
    step();
    ++frames;
    replies += host.take();
  }
  EXPECT_TRUE(status_seen);
  EXPECT_EQ(replies, "ok\r\n");
  EXPECT_NEAR((frames - move_end) * kDt, 1.5, 0.002);
}

// A Ctrl-X during a dwell ends it; as on Grbl (delay_sec returns on abort, gc_execute_line then
// returns STATUS_OK) the line gets its `ok` before the welcome, and no alarm (nothing moved).
TEST_F(GCodeInterfaceTest, ResetDuringADwellAnswersTheLineBeforeTheWelcome) {
  host.send("G4 P10\n");
  for (int i = 0; i < 1000; ++i) step();
  EXPECT_EQ(host.take(), "");
  host.send("\x18");
  for (int i = 0; i < 10; ++i) step();
  const std::string replies = host.take();
  EXPECT_EQ(replies.rfind("ok\r\n\r\nGrbl 1.1h", 0), 0u) << replies;
  EXPECT_EQ(replies.find("ALARM"), std::string::npos) << replies;
  host.send("G0 X1\n");
  run_until_idle();
  EXPECT_EQ(host.take(), "ok\r\n");
  EXPECT_DOUBLE_EQ(gcode.output_x.read_absolute(), 1.0);
}

TEST_F(GCodeInterfaceTest, DwellWaitsItsTime) {
  host.send("G4 P0.5\nG1 X1 F600\n");
  int frames = 0;
  while (gcode.output_x.read_absolute() == 0.0 && frames < 100000) {
    step();
    ++frames;
  }
  // The move is read once the dwell ends and starts from rest after the planner's start delay.
  EXPECT_NEAR(frames * kDt, 0.5 + TimeBasedInterpolator::kStartDelayUs * 1e-6, 0.002);
}

TEST_F(GCodeInterfaceTest, FeedHoldDeceleratesResumeFinishes) {
  host.send("$120=1000\n$110=3000\nG1 X100 F3000\n");
  for (int i = 0; i < 20000; ++i) step();
  host.send("!");
  for (int i = 0; i < 5000; ++i) step();
  const double held_at = gcode.output_x.read_absolute();
  EXPECT_GT(held_at, 0.0);
  EXPECT_LT(held_at, 100.0);
  // Stopping from 50 mm/s at 1000 mm/s² covers 1.25 mm; nothing moves once held.
  for (int i = 0; i < 1000; ++i) step();
  EXPECT_EQ(gcode.output_x.read_absolute(), held_at);
  host.take();
  host.send("?");
  step();
  EXPECT_NE(host.take().find("<Hold:0|"), std::string::npos);
  host.send("~");
  run_until_idle();
  EXPECT_DOUBLE_EQ(gcode.output_x.read_absolute(), 100.0);
}

TEST_F(GCodeInterfaceTest, ResetWhileMovingStopsAndLocksUntilUnlocked) {
  host.send("G1 X100 F3000\n");
  for (int i = 0; i < 10000; ++i) step();
  host.send("\x18");
  for (int i = 0; i < 10; ++i) step();
  const double stopped_at = gcode.output_x.read_absolute();
  EXPECT_LT(stopped_at, 100.0);
  const std::string after_reset = host.take();
  EXPECT_NE(after_reset.find("ALARM:3"), std::string::npos) << after_reset;
  host.send("G1 X0\n");
  for (int i = 0; i < 10; ++i) step();
  EXPECT_NE(host.take().find("error:9"), std::string::npos);
  host.send("$X\nG1 X0 F3000\n");
  run_until_idle();
  EXPECT_DOUBLE_EQ(gcode.output_x.read_absolute(), 0.0);
}

TEST_F(GCodeInterfaceTest, StatusReportsTheMachinePositionWhileRunning) {
  host.send("G1 X5 F600\n");
  for (int i = 0; i < 10000; ++i) step();  // 0.4 s of a 0.5 s move
  host.take();
  host.send("?");
  step();
  const std::string status = host.take();
  ASSERT_NE(status.find("<Run|MPos:"), std::string::npos) << status;
  const double reported = atof(status.c_str() + status.find("MPos:") + 5);
  EXPECT_NEAR(reported, gcode.output_x.read_absolute(), 0.001);
}

TEST_F(GCodeInterfaceTest, ThousandShortSegmentsStreamedByCharacterCountingNeverStarveThePlanner) {
  // 1,000 segments of 0.05 mm along a gentle arc (R = 100 mm) at 60 mm/s: 1,200 lines a second,
  // sent as Grbl's character-counting streamers do (at most 128 bytes unacknowledged) while the
  // loop runs only every fifth frame (200 µs, the simulator's loop period).
  const double radius = 100.0, v = 60.0, segment = 0.05;
  const int count = 1000;
  std::vector<std::string> lines = {"G21 G90 G1 F3600\n"};
  for (int k = 1; k <= count; ++k) {
    const double angle = k * segment / radius;
    char storage[64];
    TextWriter line(storage, sizeof(storage));
    line.character('X').fixed(radius * sin(angle), 4).text(" Y").fixed(radius * (1 - cos(angle)), 4).character('\n');
    lines.push_back(line.c_str());
  }
  record = false;
  size_t next = 0, acknowledged = 0, in_flight_bytes = 0;
  std::vector<size_t> in_flight;
  std::string replies;
  int frames = 0;
  double last_x = 0.0, last_y = 0.0, slowest_cruise = 1e9;
  const double cruise_from_s = 0.2, cruise_until_s = count * segment / v - 0.1;
  while ((acknowledged < lines.size() || !gcode.interpolator().is_idle()) && frames < 200000) {
    if (frames % 5 == 0) {
      while (next < lines.size() && in_flight_bytes + lines[next].size() <= 128) {
        host.send(lines[next]);
        in_flight.push_back(lines[next].size());
        in_flight_bytes += lines[next].size();
        ++next;
      }
      dance_loop();
      replies += host.take();
      for (size_t at = replies.find("\r\n"); at != std::string::npos; at = replies.find("\r\n")) {
        EXPECT_EQ(replies.substr(0, at), "ok") << "line " << acknowledged + 1;
        replies.erase(0, at + 2);
        ASSERT_FALSE(in_flight.empty());
        in_flight_bytes -= in_flight.front();
        in_flight.erase(in_flight.begin());
        ++acknowledged;
      }
    }
    hal_manual::run_frames(1);
    ++frames;
    const double now_x = gcode.output_x.read_absolute(), now_y = gcode.output_y.read_absolute();
    const double t = frames * kDt;
    if (t > cruise_from_s && t < cruise_until_s) {
      slowest_cruise = fmin(slowest_cruise, hypot(now_x - last_x, now_y - last_y) / kDt);
    }
    last_x = now_x;
    last_y = now_y;
  }
  EXPECT_EQ(acknowledged, lines.size());
  EXPECT_EQ(gcode.interpolator().underruns(), 0u);  // no block ever ended with nothing after it
  EXPECT_NEAR(slowest_cruise, v, 1e-3);             // and the path speed never sagged
  EXPECT_NEAR(gcode.output_x.read_absolute(), radius * sin(count * segment / radius), 1e-4);
}

struct SpindleEvent {
  bool on, clockwise;
  double speed, x_at_call;
};
std::vector<SpindleEvent> spindle_events;
GCodeInterface* spindle_interface = nullptr;

void record_spindle(bool on, bool clockwise, double speed) {
  spindle_events.push_back({on, clockwise, speed, spindle_interface->output_x.read_absolute()});
}

TEST_F(GCodeInterfaceTest, SpindleChangesWaitForThePrecedingMoves) {
  spindle_events.clear();
  spindle_interface = &gcode;
  gcode.set_spindle_callback(&record_spindle);
  host.send("G1 X10 F600\nM3 S500\nG1 X20\nM4 S250\nM5\n");
  run_until_idle();
  ASSERT_EQ(spindle_events.size(), 3u);
  EXPECT_TRUE(spindle_events[0].on && spindle_events[0].clockwise);
  EXPECT_EQ(spindle_events[0].speed, 500.0);
  EXPECT_EQ(spindle_events[0].x_at_call, 10.0);  // after the first move, before the second
  EXPECT_TRUE(spindle_events[1].on && !spindle_events[1].clockwise);
  EXPECT_EQ(spindle_events[1].x_at_call, 20.0);
  EXPECT_FALSE(spindle_events[2].on);
}

TEST_F(GCodeInterfaceTest, ProgramPauseHoldsAfterItsMovesUntilCycleStart) {
  host.send("G1 X5 F600\nM0\nG1 X10\n");
  for (int i = 0; i < 50000; ++i) step();  // 2 s: the first move (0.5 s) is long done
  EXPECT_EQ(gcode.output_x.read_absolute(), 5.0);
  host.take();
  host.send("?");
  step();
  EXPECT_NE(host.take().find("<Hold:0|"), std::string::npos);
  host.send("~");
  run_until_idle();
  EXPECT_EQ(gcode.output_x.read_absolute(), 10.0);
}

TEST(GCodeInterfaceSettings, HostSettingsSurviveARebootAndSetThePlannerLimits) {
  test_support::reset_global_state();  // erased EEPROM
  {
    test_support::FakeByteStream host;
    GCodeInterface gcode;
    ASSERT_EQ(gcode.begin(&host), Status::kOk);
    host.take();
    host.send("$110=7200\n$120=640\n");
    dance_loop();
    EXPECT_EQ(host.take(), "ok\r\nok\r\n");
  }
  EXPECT_GT(hal_manual::eeprom_writes(), 0u);
  // Power cycle: RAM and engine start afresh, the EEPROM keeps its bytes.
  hal_manual::reboot();
  engine().clear();
  test_support::FakeByteStream host;
  GCodeInterface gcode;
  ASSERT_EQ(gcode.begin(&host), Status::kOk);
  gcode.settings().set_from_sketch(110, 6000);  // a sketch default does not override the host
  EXPECT_EQ(host.take(), "\r\nGrbl 1.1h ['$' for help]\r\n");
  host.send("$$\n");
  dance_loop();
  const std::string listing = host.take();
  EXPECT_NE(listing.find("\r\n$110=7200.000\r\n"), std::string::npos) << listing;
  EXPECT_NE(listing.find("\r\n$120=640.000\r\n"), std::string::npos) << listing;
  // The planner took them: along X, 7200 mm/min = 120 mm/s and 640 mm/s².
  const double along_x[planner::kPlannerAxes] = {1.0};
  EXPECT_DOUBLE_EQ(gcode.interpolator().limits().max_speed(along_x, 1.0), 120.0);
  EXPECT_DOUBLE_EQ(gcode.interpolator().limits().max_acceleration(along_x, 1.0), 640.0);
  test_support::reset_global_state();
}

TEST(GCodeInterfaceBegin, TakesArduinoStylePortsThroughTheAdapter) {
  test_support::reset_global_state();
  ArduinoStylePort port;
  GCodeInterface gcode;
  ASSERT_EQ(gcode.begin(&port, 115200), Status::kOk);
  EXPECT_EQ(port.began_baud, 115200);
  EXPECT_NE(port.link.take().find("Grbl 1.1"), std::string::npos);
  port.link.send("G1 X1 F600\n");
  dance_loop();
  EXPECT_EQ(port.link.take(), "ok\r\n");
  test_support::reset_global_state();
}

}  // namespace
}  // namespace stepdance
