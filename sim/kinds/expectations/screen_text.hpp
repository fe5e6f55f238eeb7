// Expectation kind "screen": screen = "<oled device>", shows = "text", row = 0..3 (optional) —
// the OLED shows a line of text at the end of the run, read back in Stepdance's font.
#pragma once

#include <cstdint>
#include <string>

#include "kinds/expectation_kind.hpp"

namespace stepdance::sim {

/// The OLED device, the text a row must show (trailing blanks ignored), and the row (0..3;
/// −1 = any row).
struct ScreenTextCheck {
  std::string screen;
  std::string shows;
  int64_t row = -1;
};

const ExpectationKind& screen_text_expectation();

}  // namespace stepdance::sim
