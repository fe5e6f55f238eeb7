// Test helper: motion-stream frames through the cable model, decoded at the far end in both
// input modes, with the expected steps counted from the requests.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>

#include "models/cable.hpp"
#include "stepdance/protocol/frame_encoder.hpp"
#include "stepdance/protocol/frame_format.hpp"
#include "stepdance/protocol/pulse_decoder.hpp"

namespace stepdance::sim {

inline constexpr protocol::CaptureClock kClock{150, 0xFFFFu};  // the Teensy's 150 MHz capture counter

// The edges of one frame's words played from start_ns, 1 µs per bit (built here, not by the
// simulator's own frame_waveform, so the test does not check the code with itself).
inline PortWaveform frame_edges(SimTime start_ns, const protocol::FrameWords& words) {
  PortWaveform out;
  auto line = [&](uint32_t bits, EdgeList& edges) {
    bool level = false;
    for (int bit = 0; bit <= 32; ++bit) {
      const bool high = bit < 32 && ((bits >> bit) & 1u);
      if (high != level) edges.push_back({start_ns + SimTime{bit} * kMicrosecond, high});
      level = high;
    }
  };
  line(words.step_bits, out.step);
  line(words.dir_bits, out.dir);
  return out;
}

// Pairs the far end's STEP edges into pulses (across windows), samples DIR at the edge the input
// mode needs and decodes each pulse as an input port does.
class FarEnd {
 public:
  explicit FarEnd(InputMode mode) : mode_(mode) {}
  void receive(const PortWaveform& wave) {
    size_t next_dir = 0;
    auto dir_at = [&](SimTime time) {
      while (next_dir < wave.dir.size() && wave.dir[next_dir].time <= time) dir_ = wave.dir[next_dir++].level;
      return dir_;
    };
    for (const Edge& edge : wave.step) {
      if (edge.level) {
        open_ = true;
        rise_ns_ = edge.time;
        dir_at_rise_ = dir_at(edge.time);
        continue;
      }
      if (!open_) continue;
      open_ = false;
      const bool dir_at_fall = dir_at(edge.time);
      const bool dir =
          protocol::dir_sample_edge(mode_) == protocol::DirSampleEdge::kRising ? dir_at_rise_ : dir_at_fall;
      // 150 capture ticks per µs: 3 ticks per 20 ns.
      const auto pulse = protocol::captured_from_ticks(rise_ns_ * 3 / 20, edge.time * 3 / 20, dir, kClock);
      const auto decoded = protocol::decode_pulse(pulse, kClock, mode_, SIGNAL_X);
      if (decoded.verdict == protocol::PulseVerdict::kAccepted) {
        net[decoded.signal] += decoded.direction;
        ++accepted;
      } else {
        ++rejected;
      }
    }
    dir_at(INT64_MAX);
  }
  int64_t net[kNumSignals] = {};
  uint64_t accepted = 0;
  uint64_t rejected = 0;

 private:
  InputMode mode_;
  bool open_ = false;
  bool dir_ = false;
  bool dir_at_rise_ = false;
  SimTime rise_ns_ = 0;
};

// Streams `frames` frames of period_us through a cable into both input modes. Frame k carries
// the signals of request(k); returns the expected net steps per signal (counted here).
struct StreamResult {
  FarEnd stepdance{INPUT_MODE_STEPDANCE};
  FarEnd step_dir{INPUT_MODE_STEP_DIR};
  int64_t expected[kNumSignals] = {};
  CableCounters cable;
};

template <typename Request>
StreamResult stream(uint32_t period_us, uint64_t frames, const CableSettings& settings, Request&& request) {
  StreamResult result;
  Cable cable(settings);
  const protocol::FrameLayout layout = protocol::layout_for_period(period_us);
  const SimTime period_ns = SimTime{period_us} * kMicrosecond;
  for (uint64_t k = 0; k < frames; ++k) {
    const protocol::FrameRequest wanted = request(k);
    const protocol::EncodedFrame frame = protocol::encode_frame(wanted, layout);
    EXPECT_EQ(frame.carried_mask, 0) << "the request must fit the frame";
    for (uint8_t s = 0; s < kNumSignals; ++s) {
      if (frame.sent_mask & (1u << s)) result.expected[s] += (wanted.forward_mask & (1u << s)) ? 1 : -1;
    }
    const SimTime start = static_cast<SimTime>(k) * period_ns;
    const PortWaveform out = cable.transmit(frame_edges(start, frame.words), start, start + period_ns);
    result.stepdance.receive(out);
    result.step_dir.receive(out);
  }
  result.cable = cable.counters();
  return result;
}

// X in every frame; forward for 1000 frames, then reverse for 700, and again.
inline protocol::FrameRequest x_every_frame(uint64_t k) {
  const bool forward = (k % 1700) < 1000;
  return protocol::FrameRequest{1u << SIGNAL_X, forward ? uint8_t{1u << SIGNAL_X} : uint8_t{0}, 0};
}

}  // namespace stepdance::sim
