// Pulse decoder: jittered encode→wire→capture→decode round trips, rounding, modes, counter wrap.
#include <gtest/gtest.h>

#include <stdint.h>

#include <algorithm>
#include <random>
#include <utility>
#include <vector>

#include "stepdance/protocol/frame_encoder.hpp"
#include "stepdance/protocol/pulse_decoder.hpp"

namespace stepdance::protocol {
namespace {

constexpr CaptureClock kClock{150, 0xFFFFu};
constexpr int64_t kNsPerUs = 1000;
constexpr int64_t kFramePeriodNs = 40 * kNsPerUs;

// A high interval of a line, in ns from the start of the capture.
struct Interval {
  int64_t rise_ns;
  int64_t fall_ns;
};

// (signal, direction) pairs, sorted, so two lists compare as multisets.
using SignalList = std::vector<std::pair<int, int>>;

// High runs of a frame word as intervals; bit n covers [n, n+1) µs after frame_start_ns.
std::vector<Interval> word_to_intervals(uint32_t word, int64_t frame_start_ns) {
  std::vector<Interval> runs;
  for (int t = 0; t < 32; ++t) {
    const bool now = (word >> t) & 1u;
    const bool before = t > 0 && ((word >> (t - 1)) & 1u);
    const int64_t edge_ns = frame_start_ns + t * kNsPerUs;
    if (now && !before) runs.push_back({edge_ns, edge_ns + kNsPerUs});
    if (now) runs.back().fall_ns = edge_ns + kNsPerUs;
  }
  return runs;
}

// Moves every edge by an independent random amount in [−max_ns, +max_ns].
void jitter(std::vector<Interval>& runs, std::mt19937& rng, int max_ns) {
  std::uniform_int_distribution<int> offset(-max_ns, max_ns);
  for (Interval& run : runs) {
    run.rise_ns += offset(rng);
    run.fall_ns += offset(rng);
  }
}

bool level_at(const std::vector<Interval>& runs, int64_t time_ns) {
  return std::any_of(runs.begin(), runs.end(),
                     [&](const Interval& run) { return run.rise_ns <= time_ns && time_ns < run.fall_ns; });
}

// A 16-bit counter at 150 ticks/µs that read start_ticks at time 0.
uint32_t ticks_at(int64_t time_ns, uint32_t start_ticks) {
  return static_cast<uint32_t>((start_ticks + time_ns * 150 / kNsPerUs) & 0xFFFF);
}

SignalList expected_signals(const EncodedFrame& frame, uint8_t forward_mask) {
  SignalList out;
  for (int signal = 0; signal < 6; ++signal) {
    if (!((frame.sent_mask >> signal) & 1u)) continue;
    out.push_back({signal, ((forward_mask >> signal) & 1u) ? 1 : -1});
  }
  return out;
}

// Sends one frame over a jittered wire and decodes what a STEPDANCE-mode input port captures;
// any rejected pulse is a test failure.
SignalList wire_round_trip(const EncodedFrame& frame, int64_t frame_start_ns, uint32_t start_ticks, std::mt19937& rng) {
  std::vector<Interval> step = word_to_intervals(frame.words.step_bits, frame_start_ns);
  std::vector<Interval> dir = word_to_intervals(frame.words.dir_bits, frame_start_ns);
  jitter(step, rng, 200);
  jitter(dir, rng, 200);
  SignalList decoded;
  for (const Interval& pulse : step) {
    CapturedPulse captured;
    captured.rise_ticks = ticks_at(pulse.rise_ns, start_ticks);
    captured.fall_ticks = ticks_at(pulse.fall_ns, start_ticks);
    captured.dir_high = level_at(dir, pulse.fall_ns);  // STEPDANCE: sampled at the falling edge
    const DecodedPulse result = decode_pulse(captured, kClock, INPUT_MODE_STEPDANCE, 0);
    EXPECT_EQ(result.verdict, PulseVerdict::kAccepted) << "width " << int(result.width_us);
    if (result.verdict == PulseVerdict::kAccepted) {
      decoded.push_back({result.signal, result.direction});
    }
  }
  std::sort(decoded.begin(), decoded.end());
  return decoded;
}

CapturedPulse pulse_of(uint32_t ticks, bool dir_high = true, uint32_t rise = 1000) {
  CapturedPulse pulse;
  pulse.rise_ticks = rise;
  pulse.fall_ticks = (rise + ticks) & 0xFFFF;
  pulse.dir_high = dir_high;
  return pulse;
}

DecodedPulse decode_stepdance(const CapturedPulse& pulse) {
  return decode_pulse(pulse, kClock, INPUT_MODE_STEPDANCE, 0);
}

// Runs every (combination, direction pattern) `passes` times as consecutive frames.
void run_round_trips(uint32_t start_ticks, int passes, uint32_t seed) {
  std::mt19937 rng(seed);
  int64_t frame_start_ns = 0;
  int frames = 0;
  for (int pass = 0; pass < passes; ++pass) {
    for (uint8_t active = 1; active < 64; ++active) {
      for (uint8_t forward = 0; forward < 64; ++forward) {
        if (forward & ~active) continue;
        FrameRequest request;
        request.active_mask = active;
        request.forward_mask = forward;
        const EncodedFrame frame = encode_frame(request);
        const SignalList got = wire_round_trip(frame, frame_start_ns, start_ticks, rng);
        ASSERT_EQ(got, expected_signals(frame, forward))
            << "frame " << frames << " active " << int(active) << " forward " << int(forward);
        frame_start_ns += kFramePeriodNs;
        ++frames;
      }
    }
  }
  EXPECT_EQ(frames, passes * 728);
}

// ---- Round trip ---------------------------------------------------------------------------

TEST(PulseDecoderRoundTrip, JitteredFramesDecodeWithoutMiscount) {
  run_round_trips(0, 20, 20240501u);  // 14 560 frames, the counter wraps every ~11 frames
}

TEST(PulseDecoderRoundTrip, CounterStartingJustBeforeTheWrap) {
  run_round_trips(65536 - 400, 5, 7u);  // the first frame's pulses straddle the wrap
}

TEST(PulseDecoderRoundTrip, RandomFramesWithRandomCounterPhase) {
  std::mt19937 rng(12345u);
  std::uniform_int_distribution<int> mask(1, 63);
  std::uniform_int_distribution<uint32_t> phase(0, 0xFFFF);
  for (int frame_index = 0; frame_index < 5000; ++frame_index) {
    FrameRequest request;
    request.active_mask = static_cast<uint8_t>(mask(rng));
    request.forward_mask = static_cast<uint8_t>(mask(rng) & request.active_mask);
    const EncodedFrame frame = encode_frame(request);
    const SignalList got = wire_round_trip(frame, 0, phase(rng), rng);
    ASSERT_EQ(got, expected_signals(frame, request.forward_mask)) << "frame " << frame_index;
  }
}

// ---- Rounding boundaries (150 ticks per µs, nearest, ties down) ----------------------------

TEST(PulseDecoderRounding, ExactBoundaries) {
  EXPECT_EQ(rounded_width_us(pulse_of(225), kClock), 1);  // 1.5 µs: tie rounds down
  EXPECT_EQ(decode_stepdance(pulse_of(225)).verdict, PulseVerdict::kTooShort);

  const DecodedPulse x = decode_stepdance(pulse_of(226));
  EXPECT_EQ(x.width_us, 2);
  EXPECT_EQ(x.verdict, PulseVerdict::kAccepted);
  EXPECT_EQ(x.signal, SIGNAL_X);

  const DecodedPulse e = decode_stepdance(pulse_of(1125));  // 7.5 µs: tie rounds down
  EXPECT_EQ(e.width_us, 7);
  EXPECT_EQ(e.verdict, PulseVerdict::kAccepted);
  EXPECT_EQ(e.signal, SIGNAL_E);

  const DecodedPulse too_long = decode_stepdance(pulse_of(1126));
  EXPECT_EQ(too_long.width_us, 8);
  EXPECT_EQ(too_long.verdict, PulseVerdict::kTooLong);
}

TEST(PulseDecoderRounding, EveryTickCountUpToTenMicroseconds) {
  // Nearest whole µs with ties down is (ticks + 74) / 150 in integers.
  for (uint32_t ticks = 0; ticks <= 1500; ++ticks) {
    const uint32_t us = (ticks + 74) / 150;
    const DecodedPulse decoded = decode_stepdance(pulse_of(ticks));
    ASSERT_EQ(decoded.width_us, us) << ticks << " ticks";
    if (us < 2) {
      ASSERT_EQ(decoded.verdict, PulseVerdict::kTooShort) << ticks << " ticks";
    } else if (us > 7) {
      ASSERT_EQ(decoded.verdict, PulseVerdict::kTooLong) << ticks << " ticks";
    } else {
      ASSERT_EQ(decoded.verdict, PulseVerdict::kAccepted) << ticks << " ticks";
      ASSERT_EQ(decoded.signal, us - 2) << ticks << " ticks";
    }
  }
}

TEST(PulseDecoderRounding, NominalWidthsMapToSignals) {
  for (uint32_t signal = 0; signal < 6; ++signal) {
    const DecodedPulse decoded = decode_stepdance(pulse_of((signal + 2) * 150));
    EXPECT_EQ(decoded.verdict, PulseVerdict::kAccepted);
    EXPECT_EQ(decoded.signal, signal);
  }
}

TEST(PulseDecoderRounding, GlitchesAndOverlongPulses) {
  for (uint32_t ticks : {0u, 1u, 74u, 75u, 76u, 149u, 150u}) {  // all under 1.5 µs
    EXPECT_EQ(decode_stepdance(pulse_of(ticks)).verdict, PulseVerdict::kTooShort) << ticks;
  }
  for (uint32_t ticks : {1200u, 1500u, 6000u, 65535u}) {  // 8 µs, 10 µs, 40 µs, 436.9 µs
    EXPECT_EQ(decode_stepdance(pulse_of(ticks)).verdict, PulseVerdict::kTooLong) << ticks;
  }
  EXPECT_EQ(rounded_width_us(pulse_of(65535), kClock), 255);  // 437 µs saturates at 255
}

TEST(PulseDecoderRounding, DirectionFollowsTheSampledLevel) {
  EXPECT_EQ(decode_stepdance(pulse_of(450, true)).direction, 1);
  EXPECT_EQ(decode_stepdance(pulse_of(450, false)).direction, -1);
}

TEST(PulseDecoderRounding, CounterWrapInsideAPulse) {
  CapturedPulse pulse;
  pulse.rise_ticks = 65500;
  pulse.fall_ticks = 65500 + 300 - 65536;  // 264: 300 ticks = 2 µs later
  pulse.dir_high = true;
  const DecodedPulse decoded = decode_stepdance(pulse);
  EXPECT_EQ(decoded.width_us, 2);
  EXPECT_EQ(decoded.verdict, PulseVerdict::kAccepted);
  EXPECT_EQ(decoded.signal, SIGNAL_X);
  EXPECT_EQ(decoded.direction, 1);
}

// ---- Long pulses: the counter wraps (2^16 ticks = 436.9 µs at 150 ticks/µs) ----------------

// A pulse of `width_ns` rising at `rise_ns` on an unwrapped time line, as a backend that counts
// counter wraps (or the simulator) reports it.
CapturedPulse long_pulse(int64_t width_ns, int64_t rise_ns = 3 * kNsPerUs) {
  const auto ticks = [](int64_t ns) { return static_cast<uint64_t>(ns) * 150 / 1000; };
  return captured_from_ticks(ticks(rise_ns), ticks(rise_ns + width_ns), true, kClock);
}

// 8 µs, 437 µs (just over one counter period), 439 µs (its wrapped rest would be 2.09 µs, an X),
// 1 ms and 1 s.
constexpr int64_t kLongWidthsNs[] = {8 * kNsPerUs, 437 * kNsPerUs, 439 * kNsPerUs, 1000 * kNsPerUs, 1000000 * kNsPerUs};

TEST(PulseDecoderLongPulses, CaptureKeepsTheWholeCounterPeriods) {
  // 439 µs = 65,850 ticks = one period of 65,536 + 314.
  const CapturedPulse pulse = long_pulse(439 * kNsPerUs, 0);
  EXPECT_EQ(pulse.extra_periods, 1u);
  EXPECT_EQ((pulse.fall_ticks - pulse.rise_ticks) & 0xFFFFu, 314u);
  EXPECT_EQ(width_ticks(pulse, kClock), 65850u);
  // 1 s = 150,000,000 ticks = 2,288 periods + 58,432 ticks (2,288 × 65,536 = 149,946,368).
  const CapturedPulse second = long_pulse(1000000 * kNsPerUs, 0);
  EXPECT_EQ(second.extra_periods, 2288u);
  EXPECT_EQ(width_ticks(second, kClock), 150000000u);
}

TEST(PulseDecoderLongPulses, StepdanceModeRejectsEveryLongPulseAsTooLong) {
  for (int64_t width_ns : kLongWidthsNs) {
    for (int64_t rise_ns : {int64_t{0}, 400 * kNsPerUs, 436 * kNsPerUs}) {  // rises before and near a wrap
      const DecodedPulse decoded = decode_stepdance(long_pulse(width_ns, rise_ns));
      EXPECT_EQ(decoded.verdict, PulseVerdict::kTooLong) << width_ns << " ns rising at " << rise_ns;
    }
  }
  EXPECT_EQ(rounded_width_us(long_pulse(1000 * kNsPerUs), kClock), 255);  // saturates
}

TEST(PulseDecoderLongPulses, StepDirModeCountsEveryLongPulseAsOneStep) {
  for (int64_t width_ns : kLongWidthsNs) {
    const DecodedPulse decoded = decode_pulse(long_pulse(width_ns), kClock, INPUT_MODE_STEP_DIR, SIGNAL_R);
    EXPECT_EQ(decoded.verdict, PulseVerdict::kAccepted) << width_ns;
    EXPECT_EQ(decoded.signal, SIGNAL_R) << width_ns;
    EXPECT_EQ(decoded.direction, 1) << width_ns;
  }
}

// ---- STEP_DIR mode -------------------------------------------------------------------------

DecodedPulse decode_step_dir(uint32_t ticks, uint8_t signal, bool dir_high = true) {
  return decode_pulse(pulse_of(ticks, dir_high), kClock, INPUT_MODE_STEP_DIR, signal);
}

TEST(PulseDecoderStepDir, SamplesDirAtTheRisingEdge) {
  EXPECT_EQ(dir_sample_edge(INPUT_MODE_STEP_DIR), DirSampleEdge::kRising);
  EXPECT_EQ(dir_sample_edge(INPUT_MODE_STEPDANCE), DirSampleEdge::kFalling);
}

TEST(PulseDecoderStepDir, AnyPulseOfAtLeastOneMicrosecondIsOneStep) {
  // 76 ticks rounds to 1 µs; 3 µs would be Y and 20 µs too long in STEPDANCE mode.
  for (uint32_t ticks : {76u, 150u, 225u, 450u, 1126u, 3000u, 65535u}) {
    const DecodedPulse decoded = decode_step_dir(ticks, SIGNAL_Z);
    EXPECT_EQ(decoded.verdict, PulseVerdict::kAccepted) << ticks;
    EXPECT_EQ(decoded.signal, SIGNAL_Z) << ticks;
  }
}

TEST(PulseDecoderStepDir, GlitchesUnderHalfAMicrosecondAreTooShort) {
  for (uint32_t ticks : {0u, 30u, 75u}) {
    EXPECT_EQ(decode_step_dir(ticks, SIGNAL_Y).verdict, PulseVerdict::kTooShort) << ticks;
  }
}

TEST(PulseDecoderStepDir, DirectionAndConfiguredSignal) {
  for (uint8_t signal = 0; signal < 6; ++signal) {
    const DecodedPulse forward = decode_step_dir(300, signal, true);
    const DecodedPulse reverse = decode_step_dir(300, signal, false);
    EXPECT_EQ(forward.signal, signal);
    EXPECT_EQ(forward.direction, 1);
    EXPECT_EQ(reverse.signal, signal);
    EXPECT_EQ(reverse.direction, -1);
  }
}

}  // namespace
}  // namespace stepdance::protocol
