// Unit tests of FourTrackRecorder and FourTrackPlayer: exact round trips in both formats, files
// from an independent writer, the 40-minute sizes, and a full ring stopping the recording cleanly.
#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "hal_manual.hpp"
#include "recording/recording_test_support.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/engine.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/recording/four_track_player.hpp"
#include "stepdance/recording/four_track_recorder.hpp"
#include "support/collector_block.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

using test_support::Collector;
using test_support::ScriptedSource;

constexpr double kStep = 0.01;  // the default resolution, world units per recorded step

/// Random whole steps in [-most, most] per frame, one script per track.
std::vector<std::vector<int>> random_steps(size_t frames, int most, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> pick(-most, most);
  std::vector<std::vector<int>> steps(4, std::vector<int>(frames));
  for (auto& track : steps) {
    for (int& step : track) step = pick(random);
  }
  return steps;
}

std::vector<double> as_world(const std::vector<int>& steps, double resolution) {
  std::vector<double> world;
  for (int step : steps) world.push_back(step * resolution);
  return world;
}

/// The original's data byte, written here from the format's description, not with the library.
uint8_t original_byte(const std::vector<std::vector<int>>& steps, size_t frame) {
  uint8_t byte = 0;
  for (int track = 0; track < 4; ++track) {
    const int step = steps[track][frame];
    const uint8_t code = step > 0 ? 3 : step < 0 ? 2 : 0;  // bit 1 = stepped, bit 0 = forward
    byte = static_cast<uint8_t>(byte | code << (2 * track));
  }
  return byte;
}

class RecordingTest : public test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    for (int track = 0; track < 4; ++track) {
      sources[track].begin();
      recorder.tracks[track].input_target_position.map(&sources[track].output);
    }
    ASSERT_EQ(recorder.begin(), Status::kOk);
    ASSERT_EQ(player.begin(), Status::kOk);
    for (int track = 0; track < 4; ++track) {
      collectors[track].begin();
      player.output_BlockPorts[track].map(&collectors[track].input);
    }
    ASSERT_EQ(dance_start(), Status::kOk);
  }

  /// Runs frames with a loop pass every `loop_every` frames.
  void run(size_t frames, size_t loop_every = 8) {
    for (size_t frame = 1; frame <= frames; ++frame) {
      hal_manual::run_frames(1);
      if (frame % loop_every == 0) dance_loop();
    }
    dance_loop();
  }

  /// Records `steps` (whole steps per frame per track) and stops.
  void record(const char* name, const std::vector<std::vector<int>>& steps) {
    ASSERT_EQ(recorder.start(name), Status::kOk);
    for (int track = 0; track < 4; ++track) sources[track].play(as_world(steps[track], kStep));
    run(steps[0].size());
    ASSERT_EQ(recorder.stop(), Status::kOk);
  }

  /// Plays `name` to its end and returns each frame's change per track, in steps.
  std::vector<std::vector<long>> play(const char* name, size_t frames) {
    std::vector<std::vector<long>> played(4);
    EXPECT_EQ(player.start(name), Status::kOk);
    for (size_t frame = 0; frame < frames; ++frame) {
      hal_manual::run_frames(1);
      if (frame % 8 == 0) dance_loop();
      for (int track = 0; track < 4; ++track) {
        played[track].push_back(std::lround(collectors[track].last_change() / player.output_BlockPorts[track].ratio()));
      }
    }
    return played;
  }

  ScriptedSource sources[4];
  FourTrackRecorder recorder;
  FourTrackPlayer player;
  Collector collectors[4];
};

TEST_F(RecordingTest, OriginalFormatRoundTripsEveryStepAndMatchesAnIndependentEncoding) {
  const size_t frames = 20000;
  const auto steps = random_steps(frames, 1, 7);
  record("walk", steps);
  EXPECT_EQ(recorder.current_sample_index, frames);
  const std::vector<uint8_t> data = test_support::read_file("walk.bin");
  ASSERT_EQ(data.size(), frames);
  for (size_t frame = 0; frame < frames; ++frame) ASSERT_EQ(data[frame], original_byte(steps, frame)) << frame;
  const std::vector<uint8_t> length = test_support::read_file("walk_len.bin");
  EXPECT_EQ(std::string(length.begin(), length.end()), "20000\r\n");

  const auto played = play("walk", frames + 50);
  for (int track = 0; track < 4; ++track) {
    for (size_t frame = 0; frame < frames; ++frame) ASSERT_EQ(played[track][frame], steps[track][frame]) << frame;
    for (size_t frame = frames; frame < frames + 50; ++frame) ASSERT_EQ(played[track][frame], 0);
  }
  EXPECT_FALSE(player.playback_active);
  EXPECT_EQ(player.current_sample_index, frames);
  EXPECT_EQ(player.max_num_playback_samples, frames);
}

TEST_F(RecordingTest, AFileFromAnIndependentWriterPlaysToTheExactPosition) {
  const size_t frames = 30000;
  const auto steps = random_steps(frames, 1, 11);
  std::vector<uint8_t> data;
  long expected[4] = {};
  for (size_t frame = 0; frame < frames; ++frame) {
    data.push_back(original_byte(steps, frame));
    for (int track = 0; track < 4; ++track) expected[track] += steps[track][frame];
  }
  data.push_back(0xFF);  // beyond the length file's count: must not be played
  test_support::write_file("dance.bin", data);
  test_support::write_file("dance_len.bin", std::to_string(frames) + "\r\n");
  play("dance", frames + 10);
  for (int track = 0; track < 4; ++track) {
    EXPECT_NEAR(collectors[track].position, expected[track] * kStep, 1e-9) << "track " << track;
  }
  EXPECT_EQ(player.file_format(), RecordingFormat::kOriginal);
}

TEST_F(RecordingTest, OurFormatRecordsManyStepsPerFrameExactly) {
  const size_t frames = 8000;
  const auto steps = random_steps(frames, 100, 3);
  recorder.set_file_format(RECORDING_FORMAT_STEPDANCE);
  record("fast", steps);
  const std::vector<uint8_t> data = test_support::read_file("fast.bin");
  ASSERT_EQ(data.size(), 64 + 4 * frames);
  for (size_t frame = 0; frame < frames; ++frame) {
    for (int track = 0; track < 4; ++track) {
      ASSERT_EQ(static_cast<int8_t>(data[64 + 4 * frame + track]), steps[track][frame]) << frame;
    }
  }
  const auto played = play("fast", frames + 5);
  EXPECT_EQ(player.file_format(), RecordingFormat::kStepdance);
  for (int track = 0; track < 4; ++track) {
    for (size_t frame = 0; frame < frames; ++frame) ASSERT_EQ(played[track][frame], steps[track][frame]) << frame;
  }
}

TEST_F(RecordingTest, OurFormatCarriesTheResolutionOfEachTrack) {
  recorder.tracks[1].set_resolution(0.05);
  recorder.set_file_format(RECORDING_FORMAT_STEPDANCE);
  ASSERT_EQ(recorder.start("scaled"), Status::kOk);
  sources[1].play(std::vector<double>(100, 0.05));  // one 0.05-unit step per frame
  run(100);
  recorder.stop();
  player.set_resolution(1.0);  // applies to original-format files only
  play("scaled", 120);
  EXPECT_NEAR(collectors[1].position, 5.0, 1e-9);
}

TEST_F(RecordingTest, TheOriginalFormatLagsAtOneStepPerFrameAndCatchesUp) {
  ASSERT_EQ(recorder.start("lag"), Status::kOk);
  sources[0].play({0.05});  // five steps in one frame
  run(10);
  recorder.stop();
  const std::vector<uint8_t> data = test_support::read_file("lag.bin");
  ASSERT_EQ(data.size(), 10u);
  for (size_t frame = 0; frame < 10; ++frame) EXPECT_EQ(data[frame], frame < 5 ? 0x03 : 0x00) << frame;
}

TEST_F(RecordingTest, FortyMinutesPlanSixtyMillionSamples) {
  ASSERT_EQ(recorder.start("long", 40), Status::kOk);
  EXPECT_EQ(recorder.max_num_samples, 40ull * 60 * 25000);
  recorder.stop();
}

// At 10 µs frames our format records the period in its header (bytes 12..15, ns) and plays back
// exactly; the original format, which stores no period, is refused; and a 10 µs recording does
// not play at 40 µs, where it would run four times too slow.
TEST_F(RecordingTest, AtTenMicrosecondFramesOurFormatStoresThePeriodAndTheOriginalIsRefused) {
  engine().stop();
  ASSERT_EQ(set_frame_period_us(10), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  EXPECT_EQ(recorder.start("orig10"), Status::kUnsupported);
  recorder.set_file_format(RECORDING_FORMAT_STEPDANCE);
  ASSERT_EQ(recorder.start("minute", 1), Status::kOk);
  EXPECT_EQ(recorder.max_num_samples, 60ull * 100000);  // one minute of 10 µs frames
  recorder.stop();
  const size_t frames = 2000;
  const auto steps = random_steps(frames, 100, 5);
  record("fast10", steps);
  const std::vector<uint8_t> data = test_support::read_file("fast10.bin");
  ASSERT_GE(data.size(), 16u);
  EXPECT_EQ(data[12] | data[13] << 8 | data[14] << 16 | data[15] << 24, 10000);
  const auto played = play("fast10", frames + 5);
  for (int track = 0; track < 4; ++track) {
    for (size_t frame = 0; frame < frames; ++frame) ASSERT_EQ(played[track][frame], steps[track][frame]) << frame;
  }
  engine().stop();
  ASSERT_EQ(set_frame_period_us(40), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  EXPECT_EQ(player.start("fast10"), Status::kUnsupported);
}

TEST_F(RecordingTest, AFullBufferStopsTheRecordingCleanlyWithACountedWarning) {
  ASSERT_EQ(recorder.start("slow"), Status::kOk);
  sources[0].play(std::vector<double>(20000, kStep));
  // No loop pass: the card never gets the ring's bytes, as with a card that stalls.
  hal_manual::run_frames(FourTrackRecorder::kBufferBytes + 5);
  EXPECT_FALSE(recorder.recorder_active);
  EXPECT_EQ(recorder.overruns(), 1u);
  EXPECT_EQ(fault_level(), static_cast<uint8_t>(FaultLevel::kWarning));
  FaultReport report;
  ASSERT_TRUE(recent_fault_report(0, report));
  EXPECT_EQ(report.reason, FaultReason::kOverrun);
  dance_loop();  // the loop finishes the file with everything that fitted
  EXPECT_EQ(test_support::read_file("slow.bin").size(), FourTrackRecorder::kBufferBytes);
  const std::vector<uint8_t> length = test_support::read_file("slow_len.bin");
  EXPECT_EQ(std::string(length.begin(), length.end()), std::to_string(FourTrackRecorder::kBufferBytes) + "\r\n");
  EXPECT_TRUE(engine().running());  // motion goes on
}

TEST_F(RecordingTest, PlaybackWaitsThroughAnUnderrunAndLosesNoStep) {
  const size_t frames = 3 * FourTrackPlayer::kBufferBytes;
  std::vector<uint8_t> data(frames, 0x03);  // track 1 forward every frame
  test_support::write_file("steady.bin", data);
  test_support::write_file("steady_len.bin", std::to_string(frames) + "\r\n");
  ASSERT_EQ(player.start("steady"), Status::kOk);
  hal_manual::run_frames(FourTrackPlayer::kBufferBytes + 100);  // no loop: the ring runs dry
  EXPECT_EQ(player.underruns(), 100u);
  EXPECT_TRUE(player.playback_active);
  EXPECT_EQ(fault_level(), static_cast<uint8_t>(FaultLevel::kWarning));
  run(2 * frames);
  EXPECT_NEAR(collectors[0].position, frames * kStep, 1e-9);
  EXPECT_FALSE(player.playback_active);
}

TEST_F(RecordingTest, NamesTooLongForTheCardAreRefusedClearly) {
  const std::string name(60, 'n');
  EXPECT_EQ(recorder.start(name.c_str()), Status::kBadArgument);
  EXPECT_FALSE(recorder.recorder_active);
  EXPECT_EQ(player.start(name.c_str()), Status::kBadArgument);
  EXPECT_EQ(player.start("missing"), Status::kIoError);
}

TEST_F(RecordingTest, ABoardWithoutACardSlotIsNamedAsSuchOnTheConsole) {
  hal_manual::set_storage_present(false);  // a Teensy 4.0: its core defines BUILTIN_SDCARD, no slot
  hal_manual::take_console_output();
  EXPECT_EQ(recorder.start("take"), Status::kUnsupported);
  EXPECT_FALSE(recorder.recorder_active);
  EXPECT_EQ(player.start("take"), Status::kUnsupported);
  EXPECT_FALSE(player.playback_active);
  const std::string console = hal_manual::take_console_output();
  EXPECT_NE(console.find("FourTrackRecorder::start: this board has no SD card slot"), std::string::npos) << console;
  EXPECT_NE(console.find("FourTrackPlayer::start: this board has no SD card slot"), std::string::npos) << console;
  hal_manual::set_storage_present(true);
  EXPECT_EQ(recorder.start("take"), Status::kOk);  // the slot back, recording works again
}

TEST_F(RecordingTest, PauseLeavesOutTheMovesMadeMeanwhile) {
  ASSERT_EQ(recorder.start("paused"), Status::kOk);
  sources[0].play(std::vector<double>(30, kStep));
  run(10);
  recorder.pause();
  run(10);
  recorder.resume();
  run(10);
  recorder.stop();
  const std::vector<uint8_t> data = test_support::read_file("paused.bin");
  ASSERT_EQ(data.size(), 20u);
  for (uint8_t byte : data) EXPECT_EQ(byte, 0x03);
}

}  // namespace
}  // namespace stepdance
