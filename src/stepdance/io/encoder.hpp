// Encoder: a hardware quadrature decoder (knob, hand wheel, joint sensor) as a BlockPort source.
#pragma once

#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"

namespace stepdance {

/// Encoder selectors: the ENC1 and ENC2 connectors. ENCODER_A (the original's third decoder on
/// the INPUT_A pins) is kept so old sketches compile; no backend offers it, so begin() returns
/// the HAL's refusal (kNoSuchPin).
enum EncoderId : uint8_t { ENCODER_1 = 0, ENCODER_2 = 1, ENCODER_A = 2 };

/// A quadrature encoder counting x4 edges (a 600-line encoder gives 2400 counts per turn).
///
/// Each frame (pre-channel stage): read the hardware count, negate it if inverted, clamp it to
/// the latches (writing a clamped count back to the hardware first), then output.set(count) and
/// output.push(). Block units are counts; set_ratio() gives world units.
///
/// Fixed against the original: set() with invert() on no longer makes the output jump, and a
/// knob turned past a latch no longer drags the downstream target backwards.
class Encoder : public Block {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "Encoder"; }
  Encoder() = default;

  /// Starts decoder `index` (ENCODER_1 or ENCODER_2) and registers in the pre-channel stage.
  /// The output starts at the current count without pushing it as motion. Errors come from the
  /// HAL (kNoSuchPin for a decoder the board lacks). Context: loop.
  Status begin(uint8_t index);

  /// world_units per `counts` (e.g. set_ratio(24, 2400): 24 mm per 2400-count turn). A single
  /// argument is world units per count, which the original sketches call from loop() to rescale
  /// a knob live; the output's position is re-expressed, no motion results. Context: loop.
  void set_ratio(double world_units, double counts = 1.0) { output.set_ratio(world_units, counts); }

  /// Inverts the counting direction (calling it again changes nothing; the original toggled,
  /// which made a re-run setup() undo it). The current reading is kept (the hardware count is
  /// negated), so inverting never moves anything downstream. Context: loop.
  void invert() { invert(true); }
  /// Sets the counting direction: true counts backwards. Context: loop.
  void invert(bool inverted);
  /// True while the counting direction is inverted. Context: any.
  bool is_inverted() const { return inverted_; }

  /// Position in world units (as of the last frame, or the last set()). Context: any.
  double read() const { return output.read(ABSOLUTE); }
  /// Same as set(0). Context: loop.
  void reset() { set(0.0); }
  /// Makes the encoder read `world_value` without producing motion downstream. The hardware
  /// count becomes the nearest whole count (with the sign the inversion needs), so the reading
  /// afterwards is world_value rounded to the nearest count. Context: loop.
  void set(double world_value);

  /// Limits travel: with MIN, counts below round(world_value / ratio) are clamped to it; with
  /// MAX, counts above. An over-travelling knob is written back to the latch, so turning back
  /// moves away from the latch at once. Uses the ratio in force when called. Context: loop.
  void set_latch(double world_value, LatchSide side);
  /// Removes a latch. Context: loop.
  void clear_latch(LatchSide side);

  /// Frame work: read, invert, latch, set, push. Called by the engine. Context: frame ISR.
  void run() override { sample_and_push(); }

  /// The encoder's position, in counts inside and world units outside.
  BlockPort output;

  /// Latch state, public as in the original. Values are counts after inversion.
  bool min_latch_enabled = false;
  bool max_latch_enabled = false;
  int32_t min_latch_value = 0;
  int32_t max_latch_value = 0;

  /// Publishes its names under "<instance_name>." in `registry`, an RPC, which lists them
  /// (docs/rpc.md): the same as registry->enroll(instance_name, *this). Context: loop (setup).
  template <class Registry>
  void enroll(Registry* registry, const char* instance_name) {
    registry->enroll(instance_name, *this);
  }

 private:
  // Virtuals stay inline (no key function): see Block.
  void sample_and_push();
  bool begun() const;
  int32_t read_count() const;
  void write_count(int32_t count);
  int32_t latched(int32_t count) const;
  int32_t world_to_counts(double world_value) const;

  DecimalPosition position_counts_ = 0;
  uint8_t index_ = 255;
  bool inverted_ = false;
};

}  // namespace stepdance
