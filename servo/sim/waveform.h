// waveform.h: STEP/DIR stimulus for the servo board, built frame by frame with microsecond timing.
#pragma once

#include <cstdint>
#include <vector>

namespace servo_sim {

enum class Line : std::uint8_t { step, dir };

// One level change on STEP or DIR at an absolute time.
struct PinEvent {
  std::uint64_t time_us;
  Line line;
  bool high;
};

// Appends pulses to a time line that starts at start_us with STEP and DIR low, and keeps the step
// position a correct firmware must reach (+1 per STEP rising edge with DIR high, -1 with DIR low).
class Waveform {
 public:
  // Stepdance frame timing: a 40 us frame (25 kHz); DIR settles 1 us before STEP rises.
  static constexpr std::uint32_t kFrameUs = 40;
  static constexpr std::uint32_t kDirLeadUs = 1;

  explicit Waveform(std::uint64_t start_us);

  // Appends |steps| frames, one STEP pulse of pulse_us each, in the direction of steps' sign.
  void stepdance_steps(std::int32_t steps, std::uint32_t pulse_us = 7);

  // Appends one frame per entry of directions (+1 or -1), changing DIR only where needed.
  void stepdance_frames(const std::vector<std::int8_t>& directions, std::uint32_t pulse_us = 7);

  // Appends one frame whose DIR flips flip_after_us into a pulse_us STEP pulse; the step counts
  // in the direction DIR had at the rising edge (dir_high_at_rise).
  void frame_with_dir_flip_mid_pulse(bool dir_high_at_rise, std::uint32_t pulse_us, std::uint32_t flip_after_us);

  // Appends one STEP pulse rising at rise_us (no earlier than end_us() + kDirLeadUs), DIR set
  // kDirLeadUs before it; end_us() becomes the falling edge.
  void step_at_us(std::uint64_t rise_us, std::int8_t direction, std::uint32_t pulse_us = 7);

  // Appends idle frames (keeps later frames on the 40 us grid).
  void pause_frames(std::uint64_t frames);

  // End of everything appended so far, us.
  std::uint64_t end_us() const { return now_us_; }

  // Position after every rising edge at or before time_us.
  std::int32_t position_at_us(std::uint64_t time_us) const;

  // Position after all pulses.
  std::int32_t final_position_steps() const;

  const std::vector<PinEvent>& events() const { return events_; }

 private:
  struct Rise {
    std::uint64_t time_us;
    std::int8_t direction;
  };

  void set_dir(std::uint64_t time_us, bool high);
  void pulse(std::uint64_t rise_us, std::uint32_t width_us);

  std::vector<PinEvent> events_;
  std::vector<Rise> rises_;
  std::uint64_t now_us_;
  bool dir_high_ = false;
};

}  // namespace servo_sim
