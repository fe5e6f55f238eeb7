// EiBotBoard motion: the FIFO entries and their tick-by-tick execution (one tick = one 40 µs frame).
#pragma once

#include <stdint.h>

namespace stepdance::ebb {

/// Rate value of one step per tick: the accumulator steps each time it reaches 2^31.
constexpr int64_t kStepThreshold = int64_t{1} << 31;
/// Ticks per second (the EBB's 25 kHz motion interrupt, Stepdance's frame rate).
constexpr uint32_t kTicksPerSecond = 25000;
/// One tick in microseconds: the emulation ticks once per 40 µs of frames at any frame period.
constexpr uint32_t kTickPeriodUs = 1000000u / kTicksPerSecond;

/// One entry of the EBB motion FIFO. Everything is in motor steps and 40 µs ticks; the protocol
/// layer converts SM/XM/HM/SP/S2/EM parameters into these.
struct EbbMove {
  enum class Kind : uint8_t {
    kSteps,   ///< LM/SM/XM: each axis takes |steps| steps, accumulator algorithm; ends when both are done
    kTime,    ///< LT: both axes run the accumulator algorithm for `ticks` ticks
    kHome,    ///< HM: to target[] (global step counters) at `frequency` steps/s, computed when it starts
    kDelay,   ///< SM with no steps, or a pen command's delay: `ticks` ticks of nothing
    kServo,   ///< SP/S2/TP: servo to `servo_target` at `servo_rate`, then `ticks` ticks of delay
    kEnable,  ///< EM: microstep mode and enables; clears the global step counters and accumulators
  };
  Kind kind = Kind::kDelay;
  int64_t rate[2] = {};    ///< accumulator increment per tick, ≥ 0 (direction in `direction`)
  int64_t accel[2] = {};   ///< added to rate every tick (the first tick starts from rate − accel/2)
  uint32_t steps[2] = {};  ///< kSteps: steps each axis takes
  int8_t direction[2] = {1, 1};
  uint32_t ticks = 0;          ///< kTime / kDelay / kServo: duration in ticks
  uint8_t clear = 0;           ///< bit 0: zero axis 1's accumulator first; bit 1: axis 2's
  int32_t target[2] = {};      ///< kHome: destination in global steps
  uint32_t frequency = 0;      ///< kHome: step frequency of the longer axis, steps/s
  uint16_t servo_target = 0;   ///< kServo: pulse width in 1/12 µs (83.3 ns)
  uint16_t servo_rate = 0;     ///< kServo: pulse-width change per 24 ms, 1/12 µs (0 = at once)
  bool pen_up = false;         ///< kServo: the pen state this move stands for
  uint8_t microstep_mode = 1;  ///< kEnable: 1 = 1/16 … 5 = full step; 0 = leave it
  bool enable[2] = {true, true};
  char command[2] = {};  ///< the command that queued it ("SM", "LM", "HM"…), for reports
};

/// Ticks a step-limited axis of `move` needs to cover its steps: steps·2^31 = rate·T + accel·T²/2
/// solved for T (0 when it never gets there). Context: any (pure).
double ticks_to_cover(const EbbMove& move, int axis);

/// Executes EBB moves one tick at a time. It keeps the accumulators, the global step counters
/// (QS), each motor's position in 1/16-microsteps (exact whatever the microstep mode) and the
/// servo's pulse width. Context: frame ISR for tick(), start() and stop(); readers may run in the
/// loop (values are word-sized or copied under the caller's critical section).
class EbbMotionExecutor {
 public:
  /// Makes `move` the current move (the previous one must have finished). kHome computes its
  /// distances now, from the global step counters; kEnable and kServo take effect now.
  void start(const EbbMove& move);
  /// Advances one tick. Returns true while the current move still runs after this tick.
  bool tick();
  /// Abandons the current move (ES). Returns true if one was running.
  bool stop();
  /// Disables both drivers (ES,1): unlike EM, the step counters and accumulators stay.
  void disable_motors() { enabled_[0] = enabled_[1] = false; }
  /// Sends the servo toward `target` at `rate` now, whatever the FIFO does (SP,2 and SP,3).
  void servo_now(uint16_t target, uint16_t rate, bool pen_up);

  bool busy() const { return busy_; }
  /// The move started last. Context: frame.
  const EbbMove& move() const { return move_; }
  /// The most steps any motor takes in one tick of the current move, 0 … 1: its larger rate, on
  /// the first or the last tick, over 2^31 (a rate that would roll over counts as 1). 0 for moves
  /// that turn no motor. Context: frame, after start().
  double peak_steps_per_tick() const;
  bool motor_moving(int axis) const { return busy_ && axis_active_[axis]; }
  int32_t global_steps(int axis) const { return global_steps_[axis]; }
  /// CS: zeroes the global step counters and both accumulators.
  void clear_global_steps();
  /// Motor position in 1/16 microsteps since power-on (never cleared).
  int64_t position_sixteenths(int axis) const { return position_16_[axis]; }
  /// Microstep mode (1 = 1/16 … 5 = full) and what one step is worth in 1/16 microsteps.
  uint8_t microstep_mode() const { return microstep_mode_; }
  int32_t sixteenths_per_step() const { return int32_t{1} << (microstep_mode_ - 1); }
  bool motor_enabled(int axis) const { return enabled_[axis]; }
  /// Servo pulse width now, 1/12 µs (slewing toward its target at its rate).
  double servo_position() const { return servo_position_; }
  /// True once the servo has reached its target (no slewing left).
  bool servo_settled() const { return servo_position_ == servo_target_; }
  bool pen_up() const { return pen_up_; }
  uint32_t accumulator(int axis) const { return static_cast<uint32_t>(accumulator_[axis]); }
  /// Back to power-on: pen position `servo_reset` (up), mode 1/16, counters zero, idle.
  void reset(uint16_t servo_reset);

 private:
  void step_axis(int axis);
  void begin_accumulated(const EbbMove& move);
  void begin_home(const EbbMove& move);
  void slew_servo();

  EbbMove move_;
  bool busy_ = false;
  bool axis_active_[2] = {};
  int64_t rate_[2] = {};
  int64_t accumulator_[2] = {};
  uint32_t steps_left_[2] = {};
  uint32_t ticks_left_ = 0;
  int32_t global_steps_[2] = {};
  int64_t position_16_[2] = {};
  uint8_t microstep_mode_ = 1;
  bool enabled_[2] = {};
  double servo_position_ = 0.0;
  double servo_target_ = 0.0;
  double servo_rate_per_tick_ = 0.0;  // 0: at once
  bool pen_up_ = true;
};

}  // namespace stepdance::ebb
