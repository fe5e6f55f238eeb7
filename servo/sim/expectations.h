// expectations.h: what the firmware under test must produce, derived by hand from its build settings.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>

namespace servo_sim {

// Given on the command line so that the harness does not reuse the firmware's own arithmetic.
struct Expectations {
  std::string elf_path;
  std::string position_symbol = "step_input_position_steps";
  std::int32_t top_limit_steps = 500;
  std::int32_t bottom_limit_steps = -500;
  std::int32_t neutral_width_us = 1540;  // midpoint 1500 + width offset 40
  std::int32_t period_us = 24850;        // 24000 + period offset 850
  std::array<std::uint8_t, 3> fuses{0xE2, 0xDD, 0xFF};

  // Width in us for a position: 1 us per step, held inside the step window.
  std::int32_t width_us(std::int32_t steps) const {
    return neutral_width_us + std::clamp(steps, bottom_limit_steps, top_limit_steps);
  }

  // OCR1B for a position: the pulse is high for OCR1B + 1 ticks of 1 us.
  std::uint16_t compare(std::int32_t steps) const { return static_cast<std::uint16_t>(width_us(steps) - 1); }

  // ICR1: a fast-PWM period lasts TOP + 1 ticks of 1 us.
  std::uint16_t top() const { return static_cast<std::uint16_t>(period_us - 1); }
};

}  // namespace servo_sim
