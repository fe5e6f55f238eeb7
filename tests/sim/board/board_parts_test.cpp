// The parts of a simulated board on their own, without a sketch: the console's lines and buffers,
// the ports' frames and captures, the pins' levels and listeners, the I2C buses' timing.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "board/host/board_console.hpp"
#include "board/host/board_i2c.hpp"
#include "board/host/board_pins.hpp"
#include "board/host/board_ports.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim {
namespace {

const uint8_t* bytes_of(const std::string& text) { return reinterpret_cast<const uint8_t*>(text.data()); }

TEST(BoardConsoleLines, LinesEndAtNewlineCarriageReturnsAreDroppedAndAnOpenLineWaitsForQuiet) {
  Scheduler scheduler;
  BoardConsole console(scheduler);
  std::vector<std::string> lines;
  console.on_line([&lines](const std::string& line) { lines.push_back(line); });
  const std::string printed = "ok\r\nG1 X1\npart";
  EXPECT_EQ(console.write(bytes_of(printed), printed.size(), 0), printed.size());
  ASSERT_EQ(lines, (std::vector<std::string>{"ok", "G1 X1"}));
  EXPECT_EQ(console.text(), printed);  // the text is kept as written, '\r' included
  // "part" is handed on 100 ms (kQuietNs) after it was written, not before.
  scheduler.run_until(99 * kMillisecond);
  EXPECT_EQ(lines.size(), 2u);
  scheduler.run_until(100 * kMillisecond);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[2], "part");
}

TEST(BoardConsoleLines, ALongLineIsHandedOnIn4096BytePieces) {
  Scheduler scheduler;
  BoardConsole console(scheduler);
  std::vector<size_t> sizes;
  console.on_line([&sizes](const std::string& line) { sizes.push_back(line.size()); });
  const std::string printed = std::string(10000, 'x') + "\n";
  console.write(bytes_of(printed), printed.size(), 0);
  // 10,000 = 4,096 + 4,096 + 1,808.
  EXPECT_EQ(sizes, (std::vector<size_t>{4096, 4096, 1808}));
}

TEST(BoardConsoleInput, TheReceiveBufferHolds4096BytesAndEmptiesAsTheSketchReads) {
  Scheduler scheduler;
  BoardConsole console(scheduler);
  EXPECT_EQ(console.input_room(), 8u * 512u);
  console.send("abc");
  EXPECT_EQ(console.available(), 3u);
  EXPECT_EQ(console.input_room(), 4093u);
  EXPECT_EQ(console.read(), 'a');
  EXPECT_EQ(console.read(), 'b');
  EXPECT_EQ(console.read(), 'c');
  EXPECT_EQ(console.read(), -1);
  EXPECT_EQ(console.input_room(), 4096u);
  console.send(std::string(5000, 'y'));
  EXPECT_EQ(console.input_room(), 0u);
}

TEST(BoardConsoleText, KeepsTheNewest64KiBOncePastTwiceThatAndCountsWhatItDropped) {
  Scheduler scheduler;
  BoardConsole console(scheduler);
  const std::string block(1024, 'z');
  for (int i = 0; i < 128; ++i) console.write(bytes_of(block), block.size(), 0);
  EXPECT_EQ(console.text().size(), 131072u);  // exactly twice 64 KiB: nothing trimmed yet
  EXPECT_EQ(console.text_dropped_bytes(), 0u);
  console.write(bytes_of(block), block.size(), 0);
  EXPECT_EQ(console.text().size(), 65536u);
  EXPECT_EQ(console.text_dropped_bytes(), 132096u - 65536u);
}

/// Records every frame it hears.
class FrameLog final : public WireListener {
 public:
  explicit FrameLog(bool idle) : idle_(idle) {}
  bool wants_idle_frames() const override { return idle_; }
  void on_frame(SimTime start_ns, const protocol::FrameWords& words, SimTime) override {
    starts.push_back(start_ns);
    steps.push_back(words.step_bits);
  }
  std::vector<SimTime> starts;
  std::vector<uint32_t> steps;

 private:
  bool idle_;
};

// One 3 µs STEP pulse (bits 0–2), DIR high at its fall: width 3 µs is signal 3 − 2 = 1, forward.
constexpr protocol::FrameWords kOnePulse{0b111u, 0b1111u};
constexpr SimTime kFrameNs = 40 * kMicrosecond;

TEST(BoardPortsFrames, AQueuedFrameIsPlayedOnceAtTheNextTickAndCountedAsSent) {
  BoardPorts ports;
  FrameLog busy(false), idle(true);
  ports.add_listener(0, &busy);
  ports.add_listener(0, &idle);
  EXPECT_TRUE(ports.claim_output(0));
  EXPECT_FALSE(ports.claim_output(0));
  ports.queue_frame(0, kOnePulse);
  ports.play_queued(1000, kFrameNs, INT64_MAX);
  ports.play_queued(1000 + kFrameNs, kFrameNs, INT64_MAX);
  EXPECT_EQ(busy.starts, (std::vector<SimTime>{1000}));
  EXPECT_EQ(idle.starts, (std::vector<SimTime>{1000, 1000 + kFrameNs}));
  EXPECT_EQ(idle.steps, (std::vector<uint32_t>{0b111u, 0u}));
  EXPECT_EQ(ports.sent(0)[1].forward, 1u);
  EXPECT_EQ(ports.sent(0).accepted(), 1u);
}

TEST(BoardPortsFrames, APulseFallingAfterTheRunsEndIsNotCountedButStillPlayed) {
  BoardPorts ports;
  FrameLog listener(false);
  ports.add_listener(1, &listener);
  // The pulse falls 3 µs after the frame start; the run ends 2 µs after it.
  ports.play(1, 0, kOnePulse, kFrameNs, 2 * kMicrosecond);
  EXPECT_EQ(listener.starts.size(), 1u);
  EXPECT_EQ(ports.sent(1).accepted(), 0u);
  EXPECT_TRUE(ports.output_claimed(1));
}

TEST(BoardPortsCapture, APulseAtAPortNotBegunIsUnclaimedAndOneAtABegunPortIsDecoded) {
  BoardPorts ports;
  // 4 µs wide: signal 2; DIR low at the fall: reverse.
  const ArrivingPulse pulse{10 * kMicrosecond, 14 * kMicrosecond, true, false};
  EXPECT_FALSE(ports.capture(2, pulse).has_value());
  EXPECT_EQ(ports.unclaimed_pulses(2), 1u);
  ports.begin_input(2, protocol::DirSampleEdge::kFalling);
  const auto captured = ports.capture(2, pulse);
  ASSERT_TRUE(captured.has_value());
  EXPECT_FALSE(captured->dir_high);
  EXPECT_EQ(ports.received(2)[2].reverse, 1u);
  EXPECT_EQ(ports.received(2).accepted(), 1u);
}

TEST(BoardPinsLevels, ADrivenOutputWinsThenTheDeviceThenThePullUp) {
  BoardPins pins;
  EXPECT_FALSE(pins.level(5, 0));  // plain input, nothing connected
  ASSERT_EQ(pins.set_mode(5, STEPDANCE_PIN_INPUT_PULLUP, 0), 0);
  EXPECT_TRUE(pins.level(5, 0));
  pins.connect_input(5, [](SimTime time) { return time >= 100; });
  EXPECT_FALSE(pins.level(5, 99));
  EXPECT_TRUE(pins.level(5, 100));
  pins.set_mode(5, STEPDANCE_PIN_OUTPUT, 0);
  pins.write(5, false, 0);
  EXPECT_FALSE(pins.level(5, 200));
  EXPECT_NE(pins.set_mode(BoardPins::kPins, STEPDANCE_PIN_OUTPUT, 0), 0);
}

TEST(BoardPinsListeners, HearChangesOfADrivenLevelAndOfDrivingNotRepeats) {
  BoardPins pins;
  std::vector<std::string> heard;
  pins.on_change(7, [&heard](SimTime time, bool level, bool driven) {
    heard.push_back(std::to_string(time) + (level ? " high" : " low") + (driven ? " driven" : " released"));
  });
  pins.write(7, true, 1);  // not an output yet: nobody hears it
  pins.set_mode(7, STEPDANCE_PIN_OUTPUT, 2);
  pins.write(7, true, 3);  // no change
  pins.write(7, false, 4);
  pins.set_mode(7, STEPDANCE_PIN_INPUT, 5);
  pins.drive_high(7, 6);
  EXPECT_EQ(heard, (std::vector<std::string>{"2 high driven", "4 low driven", "5 low released", "6 high driven"}));
}

/// Acknowledges everything and answers zeros.
class NullDevice final : public I2cDevice {
 public:
  bool write(SimTime, const uint8_t*, size_t) override { return true; }
  void read(SimTime, uint8_t* data, size_t length) override {
    for (size_t i = 0; i < length; ++i) data[i] = 0;
  }
};

TEST(BoardI2cTiming, ABusNotBegunRefusesAndLoopPassesAreTimedApartFromSetup) {
  BoardI2c buses;
  NullDevice device;
  buses.attach(1, 0x3c, &device);
  const uint8_t written[2] = {0, 1};
  int64_t wire_ns = -1;
  EXPECT_EQ(buses.transfer(1, 0x3c, written, 2, nullptr, 0, 0, &wire_ns), static_cast<int>(I2cOutcome::kBusError));
  EXPECT_EQ(wire_ns, 0);
  EXPECT_FALSE(buses.begin(2, 400000));
  ASSERT_TRUE(buses.begin(1, 400000));
  // In setup: START + (address + 2 bytes) × 9 bits + STOP = 29 bit times at 400 kHz (2.5 µs).
  EXPECT_EQ(buses.transfer(1, 0x3c, written, 2, nullptr, 0, 0, &wire_ns), static_cast<int>(I2cOutcome::kOk));
  const int64_t one = wire_ns;
  EXPECT_EQ(one, 29 * 2500);
  buses.begin_loop_pass();
  buses.transfer(1, 0x3c, written, 2, nullptr, 0, 0, &wire_ns);
  buses.transfer(1, 0x3c, written, 2, nullptr, 0, 0, &wire_ns);
  buses.end_loop_pass();
  buses.count_loop_pass();
  buses.begin_loop_pass();
  buses.end_loop_pass();
  buses.count_loop_pass();  // a pass without transfers is not counted
  EXPECT_EQ(buses.timing().transfers, 3u);
  EXPECT_EQ(buses.timing().setup_ns, one);
  EXPECT_EQ(buses.timing().total_ns, 3 * one);
  EXPECT_EQ(buses.timing().max_loop_pass_ns, 2 * one);
  EXPECT_EQ(buses.timing().loop_passes_with_i2c, 1u);
}

}  // namespace
}  // namespace stepdance::sim
