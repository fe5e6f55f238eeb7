// Encoder: hardware count ↔ logical count (inversion, latches) and the per-frame push.
#include "stepdance/io/encoder.hpp"

#include <math.h>

#include "stepdance/hal/hal.hpp"

namespace stepdance {

// The output port starts at the current hardware count (reset, not pushed as motion), so a knob
// turned before begin() does not jump the machine. Runs before the channels each frame
// (kPreChannel) so a turn reaches the motors in the same frame.
Status Encoder::begin(uint8_t index) {
  const Status started = hal::quadrature_begin(index);
  if (started != Status::kOk) return started;
  index_ = index;
  output.begin(&position_counts_, BLOCKPORT_UNDEFINED, this);
  output.reset(read_count(), true);
  return register_in(Stage::kPreChannel);
}

bool Encoder::begun() const { return index_ != 255; }

// Logical count: inversion is applied in software because the hardware counter has no direction
// setting on every backend.
int32_t Encoder::read_count() const {
  if (!begun()) return 0;
  const int32_t hardware = hal::quadrature_read(index_);
  return inverted_ ? -hardware : hardware;
}

void Encoder::write_count(int32_t count) {
  if (begun()) hal::quadrature_write(index_, inverted_ ? -count : count);
}

// World units (e.g. mm) → encoder counts through the output BlockPort's ratio, rounded to nearest.
int32_t Encoder::world_to_counts(double world_value) const {
  return static_cast<int32_t>(lround(output.convert_world_to_block_units(world_value)));
}

// Latches are soft end stops in counts: the knob keeps turning but the position stops at them.
int32_t Encoder::latched(int32_t count) const {
  if (min_latch_enabled && count < min_latch_value) return min_latch_value;
  if (max_latch_enabled && count > max_latch_value) return max_latch_value;
  return count;
}

void Encoder::invert(bool inverted) {
  hal::CriticalSection guard;  // the frame must not see the flag and the count disagree
  const int32_t count = read_count();
  inverted_ = inverted;
  write_count(count);
}

// Redefines where the knob is (like a homing offset); output.reset() moves the port's reference
// with it so the change is not sent downstream as motion.
void Encoder::set(double world_value) {
  const int32_t count = world_to_counts(world_value);
  hal::CriticalSection guard;
  write_count(count);
  output.reset(count, true);
}

// The count is computed outside the critical section (floating point), the limit stored inside it
// because the frame reads value and enable flag together.
void Encoder::set_latch(double world_value, LatchSide side) {
  const int32_t count = world_to_counts(world_value);
  hal::CriticalSection guard;
  if (side == MIN) {
    min_latch_value = count;
    min_latch_enabled = true;
  } else {
    max_latch_value = count;
    max_latch_enabled = true;
  }
}

void Encoder::clear_latch(LatchSide side) {
  if (side == MIN) {
    min_latch_enabled = false;
  } else {
    max_latch_enabled = false;
  }
}

// Frame context (kPreChannel). When a latch holds, the hardware count is written back to the limit
// so turning back from over-travel moves at once instead of first unwinding the extra counts.
void Encoder::sample_and_push() {
  const int32_t raw = read_count();
  const int32_t count = latched(raw);
  if (count != raw) write_count(count);  // the hardware forgets the over-travel first
  output.set(count);
  output.push();
}

}  // namespace stepdance
