// Fault fixture for image boards: recursion without end, whose stack grows down past its bottom
// into the variables below it (the Teensy's MPU guard region sits there).
#include <stdint.h>

volatile uint32_t depth_limit = 0xFFFFFFFFu;

__attribute__((noinline)) uint32_t recurse(uint32_t depth) {
  volatile uint8_t frame[64];
  frame[0] = static_cast<uint8_t>(depth);
  if (depth >= depth_limit) return frame[0];
  return recurse(depth + 1) + frame[0];
}

void setup() { depth_limit = recurse(0); }
void loop() {}
