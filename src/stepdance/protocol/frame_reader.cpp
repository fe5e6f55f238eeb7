// Frame reader: STEP/DIR words back into pulses and captures.
#include "stepdance/protocol/frame_reader.hpp"

namespace stepdance::protocol {
namespace {

bool bit_at(uint32_t word, uint8_t us) { return us < kFrameBitsUs && ((word >> us) & 1u); }

}  // namespace

// The inverse of the encoder, for the simulator's wires and the tests: one bit per µs, a pulse is a
// run of high STEP bits, and DIR is sampled at both edges so either receiver convention can be
// modelled. A pulse still high at the window's end ends there.
size_t read_wire_pulses(const FrameWords& words, WirePulse* pulses, size_t capacity) {
  size_t found = 0;
  uint8_t us = 0;
  while (us < kFrameBitsUs && found < capacity) {
    if (!bit_at(words.step_bits, us)) {
      ++us;
      continue;
    }
    WirePulse pulse;
    pulse.rise_us = us;
    while (us < kFrameBitsUs && bit_at(words.step_bits, us)) ++us;
    pulse.fall_us = us;
    pulse.dir_at_rise = bit_at(words.dir_bits, pulse.rise_us);
    pulse.dir_at_fall = bit_at(words.dir_bits, pulse.fall_us);
    pulses[found++] = pulse;
  }
  return found;
}

// What a capture timer would record for the pulse: edge times in ticks of the given clock, wrapped to
// its counter width, and DIR at the edge the port samples.
CapturedPulse capture_wire_pulse(const WirePulse& pulse, const CaptureClock& clock, uint32_t frame_start_ticks,
                                 DirSampleEdge edge) {
  CapturedPulse captured;
  captured.rise_ticks = (frame_start_ticks + pulse.rise_us * clock.ticks_per_us) & clock.counter_mask;
  captured.fall_ticks = (frame_start_ticks + pulse.fall_us * clock.ticks_per_us) & clock.counter_mask;
  captured.dir_high = edge == DirSampleEdge::kRising ? pulse.dir_at_rise : pulse.dir_at_fall;
  return captured;
}

}  // namespace stepdance::protocol
