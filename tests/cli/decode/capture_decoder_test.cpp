// Capture decoder: encode_frame waveforms decoded to exact counts, glitches, rounding, modes, frames.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "decode/capture_decoder.hpp"
#include "stepdance/protocol/frame_encoder.hpp"

namespace stepdance::sim {
namespace {

using protocol::PulseVerdict;

// Appends one word's levels as edges: bit n covers [start + n µs, start + n + 1 µs); falling
// edges of STEP move by stretch_ns (a cable that widens pulses).
void append_word(EdgeList& line, uint32_t word, SimTime start, SimTime stretch_ns = 0) {
  bool level = false;
  for (int bit = 0; bit <= 32; ++bit) {
    const bool now = bit < 32 && ((word >> bit) & 1u);
    if (now == level) continue;
    line.push_back(Edge{start + bit * kMicrosecond + (now ? 0 : stretch_ns), now});
    level = now;
  }
}

void append_pulse(EdgeList& line, SimTime rise, SimTime width) {
  line.push_back(Edge{rise, true});
  line.push_back(Edge{rise + width, false});
}

struct Round {
  uint8_t active;
  uint8_t forward;
};

// Encodes rounds of requests into frames 40 µs apart from 100 µs (frame slot 5 left idle): each
// round is requested once every carried signal has gone out, carried signals first.
struct EncodedCapture {
  PortWaveform wave;
  std::vector<int> pulses_per_frame;
};

EncodedCapture encode_rounds(const std::vector<Round>& rounds, SimTime stretch_ns = 0) {
  EncodedCapture capture;
  uint8_t pending = 0;
  uint8_t pending_forward = 0;
  size_t next_round = 0;
  int slot = 0;
  while (pending != 0 || next_round < rounds.size()) {
    if (pending == 0) {
      pending = rounds[next_round].active;
      pending_forward = rounds[next_round].forward;
      ++next_round;
    }
    protocol::FrameRequest request;
    request.active_mask = pending;
    request.forward_mask = pending_forward & pending;
    request.priority_mask = pending;
    const protocol::EncodedFrame frame = protocol::encode_frame(request);
    if (slot == 5) ++slot;
    const SimTime start = 100 * kMicrosecond + slot * 40 * kMicrosecond;
    append_word(capture.wave.step, frame.words.step_bits, start, stretch_ns);
    append_word(capture.wave.dir, frame.words.dir_bits, start);
    capture.pulses_per_frame.push_back(__builtin_popcount(frame.sent_mask));
    pending = frame.carried_mask;
    ++slot;
  }
  return capture;
}

const std::vector<Round> kRounds = {
    {0x3F, 0x3F},  // every signal forward
    {0x3F, 0x00},  // every signal reverse
    {0x3F, 0x15},  // X, R, Z forward; Y, T, E reverse
    {0x03, 0x01},  // X forward, Y reverse
};

void expect_round_counts(const DecodeResult& result) {
  EXPECT_EQ(result.counts[SIGNAL_X], (DirectionCounts{3, 1}));
  EXPECT_EQ(result.counts[SIGNAL_Y], (DirectionCounts{1, 3}));
  EXPECT_EQ(result.counts[SIGNAL_R], (DirectionCounts{2, 1}));
  EXPECT_EQ(result.counts[SIGNAL_T], (DirectionCounts{1, 2}));
  EXPECT_EQ(result.counts[SIGNAL_Z], (DirectionCounts{2, 1}));
  EXPECT_EQ(result.counts[SIGNAL_E], (DirectionCounts{1, 2}));
  EXPECT_EQ(result.accepted, 20u);
}

TEST(CaptureDecoder, EncodedFramesDecodeToExactCountsAndFrameStatistics) {
  const EncodedCapture capture = encode_rounds(kRounds);
  ASSERT_EQ(capture.pulses_per_frame, (std::vector<int>{5, 1, 5, 1, 5, 1, 2}));  // E is carried each time
  const DecodeResult result = decode_step_dir(capture.wave.step, capture.wave.dir, DecodeOptions{});
  expect_round_counts(result);
  EXPECT_EQ(result.counts.too_short, 0u);
  EXPECT_EQ(result.counts.too_long, 0u);
  EXPECT_EQ(result.incomplete, 0u);
  EXPECT_TRUE(result.first_rejected.empty());
  EXPECT_EQ(result.frames.count, 7u);
  EXPECT_EQ(result.frames.max_pulses, 5u);
  EXPECT_EQ(result.frames.min_start_spacing, 40 * kMicrosecond);
  EXPECT_EQ(result.frames.max_start_spacing, 80 * kMicrosecond);  // across the idle slot
}

TEST(CaptureDecoder, PulsesStretchedByACableDecodeTheSame) {
  for (SimTime stretch : {100, 250, 400}) {
    const EncodedCapture capture = encode_rounds(kRounds, stretch);
    const DecodeResult result = decode_step_dir(capture.wave.step, capture.wave.dir, DecodeOptions{});
    expect_round_counts(result);
    EXPECT_EQ(result.counts.too_short + result.counts.too_long, 0u) << stretch;
    EXPECT_EQ(result.frames.count, 7u) << stretch;
  }
}

TEST(CaptureDecoder, GlitchesAreTooShortAndAnEightMicrosecondPulseIsTooLong) {
  EncodedCapture capture = encode_rounds(kRounds);
  // The idle slot 5 (300..340 µs) gets two glitches; an 8 µs pulse follows the last frame.
  append_pulse(capture.wave.step, 310 * kMicrosecond, 500);
  append_pulse(capture.wave.step, 315 * kMicrosecond, 900);
  std::sort(capture.wave.step.begin(), capture.wave.step.end(),
            [](const Edge& a, const Edge& b) { return a.time < b.time; });
  append_pulse(capture.wave.step, 500 * kMicrosecond, 8 * kMicrosecond);
  const DecodeResult result = decode_step_dir(capture.wave.step, capture.wave.dir, DecodeOptions{});
  expect_round_counts(result);
  EXPECT_EQ(result.counts.too_short, 2u);
  EXPECT_EQ(result.counts.too_long, 1u);
  ASSERT_EQ(result.first_rejected.size(), 3u);
  EXPECT_EQ(result.first_rejected[0].rise, 310000);
  EXPECT_EQ(result.first_rejected[0].fall, 310500);
  EXPECT_EQ(result.first_rejected[0].width_us, 0);  // 0.5 µs: a tie, rounds down
  EXPECT_EQ(result.first_rejected[0].reason, PulseVerdict::kTooShort);
  EXPECT_EQ(result.first_rejected[1].rise, 315000);
  EXPECT_EQ(result.first_rejected[1].width_us, 1);
  EXPECT_EQ(result.first_rejected[1].reason, PulseVerdict::kTooShort);
  EXPECT_EQ(result.first_rejected[2].rise, 500000);
  EXPECT_EQ(result.first_rejected[2].width_us, 8);
  EXPECT_EQ(result.first_rejected[2].reason, PulseVerdict::kTooLong);
  EXPECT_EQ(result.frames.count, 7u);  // rejected pulses are not frame content

  DecodeOptions few;
  few.max_rejected_examples = 1;
  const DecodeResult limited = decode_step_dir(capture.wave.step, capture.wave.dir, few);
  EXPECT_EQ(limited.first_rejected.size(), 1u);
  EXPECT_EQ(limited.counts.too_short + limited.counts.too_long, 3u);
}

TEST(CaptureDecoder, WidthsRoundInCaptureTicksLikeTheFirmware) {
  EdgeList step;
  append_pulse(step, 10 * kMicrosecond, 1500);      // 225 ticks = 1.5 µs → 1 (ties down): too short
  append_pulse(step, 20 * kMicrosecond, 1507);      // 226 ticks → 2: X
  append_pulse(step, 30 * kMicrosecond, 7500);      // 1125 ticks → 7: E
  append_pulse(step, 40 * kMicrosecond, 7507);      // 1126 ticks → 8: too long
  append_pulse(step, 50 * kMicrosecond + 3, 1504);  // ticks round(7500.45)=7500 … round(7726.05)=7726: 226 → X
  const DecodeResult result = decode_step_dir(step, EdgeList{}, DecodeOptions{});
  EXPECT_EQ(result.counts[SIGNAL_X], (DirectionCounts{0, 2}));
  EXPECT_EQ(result.counts[SIGNAL_E], (DirectionCounts{0, 1}));
  EXPECT_EQ(result.counts.too_short, 1u);
  EXPECT_EQ(result.counts.too_long, 1u);
}

TEST(CaptureDecoder, CaptureTicksRoundHalfUp) {
  EXPECT_EQ(capture_ticks(0, 150), 0u);
  EXPECT_EQ(capture_ticks(3, 150), 0u);   // 0.45
  EXPECT_EQ(capture_ticks(4, 150), 1u);   // 0.6
  EXPECT_EQ(capture_ticks(10, 150), 2u);  // 1.5 → 2
  EXPECT_EQ(capture_ticks(1000, 150), 150u);
  EXPECT_EQ(capture_ticks(600 * kSecond, 150), 90'000'000'000u);
}

TEST(CaptureDecoder, PulsesPastTheCounterWrapAreMeasuredWholeLikeTheFirmware) {
  EdgeList step;
  append_pulse(step, 10 * kSecond + 123, 2 * kMicrosecond);  // far into the run: still X
  append_pulse(step, 11 * kSecond, 437 * kMicrosecond);      // 65550 ticks (wrapped alone: 14, "too short")
  append_pulse(step, 12 * kSecond, 439 * kMicrosecond);      // 65850 ticks (wrapped alone: 314, an X)
  append_pulse(step, 13 * kSecond, 500 * kMicrosecond);      // 75000 ticks (wrapped alone: 63 µs)
  const DecodeResult result = decode_step_dir(step, EdgeList{}, DecodeOptions{});
  EXPECT_EQ(result.counts[SIGNAL_X], (DirectionCounts{0, 1}));
  EXPECT_EQ(result.counts.too_short, 0u);
  EXPECT_EQ(result.counts.too_long, 3u);
  for (const RejectedPulse& pulse : result.first_rejected) EXPECT_EQ(pulse.width_us, 255);  // saturated
}

// DIR low; pulses at 10 (2 µs), 21 (2 µs, DIR high since 20), 31..33 (DIR falls at 32 inside
// the pulse), 40 (1 µs), 50 (0.4 µs), 60 (10 µs).
PortWaveform mixed_step_dir() {
  PortWaveform wave;
  append_pulse(wave.step, 10 * kMicrosecond, 2 * kMicrosecond);
  append_pulse(wave.step, 21 * kMicrosecond, 2 * kMicrosecond);
  append_pulse(wave.step, 31 * kMicrosecond, 2 * kMicrosecond);
  append_pulse(wave.step, 40 * kMicrosecond, 1 * kMicrosecond);
  append_pulse(wave.step, 50 * kMicrosecond, 400);
  append_pulse(wave.step, 60 * kMicrosecond, 10 * kMicrosecond);
  wave.dir = {{20 * kMicrosecond, true}, {32 * kMicrosecond, false}};
  return wave;
}

TEST(CaptureDecoder, StepDirModeSamplesDirAtTheRisingEdgeAndCountsOneSignal) {
  const PortWaveform wave = mixed_step_dir();
  DecodeOptions options;
  options.mode = INPUT_MODE_STEP_DIR;
  options.step_dir_signal = SIGNAL_Z;
  const DecodeResult result = decode_step_dir(wave.step, wave.dir, options);
  EXPECT_EQ(result.counts[SIGNAL_Z], (DirectionCounts{2, 3}));
  EXPECT_EQ(result.counts[SIGNAL_X], (DirectionCounts{0, 0}));
  EXPECT_EQ(result.accepted, 5u);
  EXPECT_EQ(result.counts.too_short, 1u);
  EXPECT_EQ(result.counts.too_long, 0u);
  // Frames: {10} then a 9 µs gap, {21, 31, 40} (gaps 8 and 7 µs), then a 19 µs gap, {60}.
  EXPECT_EQ(result.frames.count, 3u);
  EXPECT_EQ(result.frames.max_pulses, 3u);
  EXPECT_EQ(result.frames.min_start_spacing, 11 * kMicrosecond);
  EXPECT_EQ(result.frames.max_start_spacing, 39 * kMicrosecond);
}

TEST(CaptureDecoder, StepdanceModeSamplesDirAtTheFallingEdge) {
  const PortWaveform wave = mixed_step_dir();
  const DecodeResult result = decode_step_dir(wave.step, wave.dir, DecodeOptions{});
  EXPECT_EQ(result.counts[SIGNAL_X], (DirectionCounts{1, 2}));
  EXPECT_EQ(result.counts.too_short, 2u);
  EXPECT_EQ(result.counts.too_long, 1u);
}

TEST(CaptureDecoder, ADirEdgeAtTheSamplingInstantHasAlreadyHappened) {
  PortWaveform wave;
  append_pulse(wave.step, 10 * kMicrosecond, 2 * kMicrosecond);
  wave.dir = {{12 * kMicrosecond, true}};
  EXPECT_EQ(decode_step_dir(wave.step, wave.dir, DecodeOptions{}).counts[SIGNAL_X], (DirectionCounts{1, 0}));
  DecodeOptions step_dir;
  step_dir.mode = INPUT_MODE_STEP_DIR;
  wave.dir = {{10 * kMicrosecond, true}};
  EXPECT_EQ(decode_step_dir(wave.step, wave.dir, step_dir).counts[SIGNAL_X], (DirectionCounts{1, 0}));
}

TEST(CaptureDecoder, InitialLevelsAndPulsesCutByTheCapture) {
  PortWaveform wave;
  wave.step = {{1 * kMicrosecond, false},
               {10 * kMicrosecond, true},
               {13 * kMicrosecond, false},
               {13 * kMicrosecond, false},
               {20 * kMicrosecond, true}};
  const DecodeResult result = decode_step_dir(wave.step, wave.dir, DecodeOptions{}, InitialLevels{true, true});
  EXPECT_EQ(result.incomplete, 2u);
  EXPECT_EQ(result.counts[SIGNAL_Y], (DirectionCounts{1, 0}));
  EXPECT_EQ(result.accepted, 1u);
}

TEST(CaptureDecoder, FramesSplitOnGapsOverEightAndRisesOverThirtyTwoMicroseconds) {
  EdgeList step;
  // Gap of exactly 8 µs stays in the frame; 8.001 µs starts a new one.
  append_pulse(step, 0, 2 * kMicrosecond);
  append_pulse(step, 10 * kMicrosecond, 2 * kMicrosecond);
  append_pulse(step, 20 * kMicrosecond + 1, 2 * kMicrosecond);
  // A continuous train from 1000 µs, a 2 µs pulse every 4 µs, 20 pulses: the rise 32 µs after a
  // frame's first stays in it, the next starts a new frame.
  for (int i = 0; i < 20; ++i) append_pulse(step, 1000 * kMicrosecond + i * 4 * kMicrosecond, 2 * kMicrosecond);
  const DecodeResult result = decode_step_dir(step, EdgeList{}, DecodeOptions{});
  EXPECT_EQ(result.accepted, 23u);
  // Frames: {0, 10}, {20.001}, {1000..1032} (9), {1036..1068} (9), {1072, 1076}.
  EXPECT_EQ(result.frames.count, 5u);
  EXPECT_EQ(result.frames.max_pulses, 9u);
  EXPECT_EQ(result.frames.min_start_spacing, 20 * kMicrosecond + 1);
  EXPECT_EQ(result.frames.max_start_spacing, 980 * kMicrosecond - 1);
}

// Every set of signals, once, forward, encoded back to back in frames of `period_us` with the
// port's whole-frame layout (carried signals first), from 100 µs.
EncodedCapture encode_every_set(uint32_t period_us) {
  const protocol::FrameLayout layout = protocol::layout_for_period(period_us);
  EncodedCapture capture;
  uint8_t pending = 0;
  uint8_t next_set = 1;
  for (int slot = 0; pending != 0 || next_set <= kAllSignalsMask; ++slot) {
    if (pending == 0) pending = next_set++;
    protocol::FrameRequest request;
    request.active_mask = pending;
    request.forward_mask = pending;
    request.priority_mask = pending;
    const protocol::EncodedFrame frame = protocol::encode_frame(request, layout);
    const SimTime start = 100 * kMicrosecond + slot * SimTime{period_us} * kMicrosecond;
    append_word(capture.wave.step, frame.words.step_bits, start);
    append_word(capture.wave.dir, frame.words.dir_bits, start);
    capture.pulses_per_frame.push_back(__builtin_popcount(frame.sent_mask));
    pending = frame.carried_mask;
  }
  return capture;
}

TEST(CaptureDecoder, FramesGroupByTheSendersPeriod) {
  for (const uint32_t period_us : {10u, 20u, 25u, 40u}) {
    const EncodedCapture capture = encode_every_set(period_us);
    DecodeOptions options;
    options.frame_period_us = period_us;
    const DecodeResult result = decode_step_dir(capture.wave.step, capture.wave.dir, options);
    EXPECT_EQ(result.accepted, 6u * 32u) << period_us;  // each signal is in 32 of the 63 sets
    EXPECT_EQ(result.frames.count, capture.pulses_per_frame.size()) << period_us;
    EXPECT_EQ(result.frames.max_pulses, static_cast<uint32_t>(*std::max_element(capture.pulses_per_frame.begin(),
                                                                                capture.pulses_per_frame.end())))
        << period_us;
    EXPECT_EQ(result.frames.min_start_spacing, SimTime{period_us} * kMicrosecond) << period_us;
    EXPECT_EQ(result.frames.max_start_spacing, SimTime{period_us} * kMicrosecond) << period_us;
  }
  // Grouped as 40 µs frames, a 10 µs stream's frames run together (why decode asks the period).
  const EncodedCapture fast = encode_every_set(10);
  const DecodeResult as_if_40 = decode_step_dir(fast.wave.step, fast.wave.dir, DecodeOptions{});
  EXPECT_LT(as_if_40.frames.count, fast.pulses_per_frame.size());
}

TEST(CaptureDecoder, EmptyCapture) {
  const DecodeResult result = decode_step_dir(EdgeList{}, EdgeList{}, DecodeOptions{});
  EXPECT_EQ(result.accepted, 0u);
  EXPECT_EQ(result.frames.count, 0u);
  EXPECT_EQ(result.frames.min_start_spacing, 0);
}

// StepDirDecoder, the streaming decoder behind `stepdance decode`: a reader hands it each line's
// edges as the file has them, so a DIR edge may come after a STEP edge of the same time. DIR's
// level at a time counts its edges at that time (decode_step_dir's rule), whatever the order.
TEST(StepDirDecoder, ADirEdgeAfterAStepEdgeOfTheSameTimeStillCounts) {
  for (const InputMode mode : {INPUT_MODE_STEPDANCE, INPUT_MODE_STEP_DIR}) {
    DecodeOptions options;
    options.mode = mode;
    StepDirDecoder decoder(options, InitialLevels{false, false});
    // STEPDANCE samples DIR at the fall (3 µs), STEP_DIR at the rise (1 µs): DIR rises at both.
    decoder.step_edge(1000, true);
    decoder.dir_edge(1000, true);
    decoder.step_edge(3000, false);
    decoder.dir_edge(3000, true);
    const DecodeResult result = decoder.finish();
    EXPECT_EQ(result.counts[SIGNAL_X], (DirectionCounts{1, 0})) << int(mode);
  }
}

TEST(StepDirDecoder, PulsesWithinOneTimestampAreZeroWideAndEachCounted) {
  StepDirDecoder decoder(DecodeOptions{}, InitialLevels{false, false});
  for (int i = 0; i < 1000; ++i) {
    decoder.step_edge(5000, true);
    decoder.step_edge(5000, false);
  }
  decoder.step_edge(5000, false);  // no change: ignored
  const DecodeResult result = decoder.finish();
  EXPECT_EQ(result.counts.too_short, 1000u);
  EXPECT_EQ(result.first_rejected.size(), 10u);
  EXPECT_EQ(result.incomplete, 0u);
}

// Random waveforms with many edges at equal times: fed DIR-first (decode_step_dir's merge) or
// STEP-first, the streaming decoder gives the same result field by field.
TEST(StepDirDecoder, TheOrderOfEdgesAtOneTimeDoesNotMatter) {
  std::mt19937_64 random(27);
  for (int round = 0; round < 200; ++round) {
    EdgeList step, dir;
    bool step_level = false, dir_level = false;
    SimTime time = 0;
    for (int i = 0; i < 60; ++i) {
      time += static_cast<SimTime>(random() % 4) * 1000 + static_cast<SimTime>(random() % 2) * 333;
      if (random() % 3 != 0) step.push_back(Edge{time, step_level = !step_level});
      if (random() % 3 == 0) dir.push_back(Edge{time, dir_level = !dir_level});
    }
    for (const InputMode mode : {INPUT_MODE_STEPDANCE, INPUT_MODE_STEP_DIR}) {
      DecodeOptions options;
      options.mode = mode;
      const DecodeResult merged = decode_step_dir(step, dir, options);
      StepDirDecoder decoder(options, InitialLevels{});
      size_t next_dir = 0;
      for (const Edge& edge : step) {
        while (next_dir < dir.size() && dir[next_dir].time < edge.time) {  // equal times: STEP first
          decoder.dir_edge(dir[next_dir].time, dir[next_dir].level);
          ++next_dir;
        }
        decoder.step_edge(edge.time, edge.level);
      }
      for (; next_dir < dir.size(); ++next_dir) decoder.dir_edge(dir[next_dir].time, dir[next_dir].level);
      const DecodeResult streamed = decoder.finish();
      EXPECT_EQ(streamed.counts, merged.counts) << round;
      EXPECT_EQ(streamed.counts.too_short, merged.counts.too_short) << round;
      EXPECT_EQ(streamed.counts.too_long, merged.counts.too_long) << round;
      EXPECT_EQ(streamed.incomplete, merged.incomplete) << round;
      EXPECT_EQ(streamed.frames.count, merged.frames.count) << round;
      ASSERT_EQ(streamed.first_rejected.size(), merged.first_rejected.size()) << round;
    }
  }
}

}  // namespace
}  // namespace stepdance::sim
