// EBB motion queue: the FIFO from the loop's commands to the frame, executed tick by tick there.
#pragma once

#include <stdint.h>

#include "stepdance/core/spsc_queue.hpp"
#include "stepdance/interfaces/ebb/ebb_motion.hpp"
#include "stepdance/interfaces/ebb/ebb_tick_clock.hpp"

namespace stepdance::ebb {

/// What bypasses the FIFO, as on the EBB: applied by the frame before its next tick.
enum class EbbControl : uint8_t {
  kStop,         ///< ES: abandon the move, flush the FIFO
  kStopDisable,  ///< ES,1: and disable the drivers
  kClearSteps,   ///< CS: zero the global step counters
  kReset,        ///< R: flush and back to power-on
  kPenUpNow,     ///< SP,2/3: the pen up at once
};

/// The EBB's motion FIFO and its executor. The loop pushes moves (within the depth CU,4 set) and
/// controls and reads the state the frame published (QM, QG, QS, QP, QE); the frame takes the
/// moves and ticks them at the EBB's 40 µs, stretched when a channel could not keep up. Loop and
/// frame meet only in the two single-producer queues and the published words.
/// Context: each method says loop or frame.
class EbbMotionQueue {
 public:
  /// FIFO capacity (QU,2); the depth a client sees starts at 1 (CU,4 changes it).
  static constexpr uint32_t kCapacity = 64;

  // ---- loop side ----
  /// Queues `move`, named by `command` (two characters, for the stretch report); false while
  /// the depth is reached (the command waits). Context: loop.
  bool push(const EbbMove& move, const char* command);
  /// CU,4: the depth clients see, 1 … kCapacity (clamped). Context: loop.
  void set_depth(uint32_t moves) { depth_ = moves < 1 ? 1 : (moves > kCapacity ? kCapacity : moves); }
  uint32_t depth() const { return depth_; }
  /// Moves queued and not yet taken by the frame. Context: loop.
  uint32_t waiting() const { return moves_queued_ - moves_started_; }
  /// Sends a control to the frame (ES, CS). Context: loop.
  void control(EbbControl control);
  /// SP,2/3: the servo to `target` at `rate` now (1/12 µs, 1/12 µs per 24 ms). Context: loop.
  void pen_now(uint16_t target, uint16_t rate);
  /// R: depth 1 again, and the frame flushes and resets with the pen at `servo_up`. Context: loop.
  void reset(uint16_t servo_up);
  /// True while a move runs or waits: what QM and QG call "executing". Context: loop.
  bool executing() const { return frame_busy_ || waiting() != 0; }
  /// Nothing runs, waits or is pending, and the servo has settled. Context: loop.
  bool idle() const;

  /// The state the frame published last (its executor's, see EbbMotionExecutor). Context: loop.
  bool busy() const { return frame_busy_; }
  bool motor_moving(int motor) const { return frame_motor_moving_[motor]; }
  int32_t global_steps(int motor) const { return frame_global_steps_[motor]; }
  bool pen_up() const { return frame_pen_up_; }
  /// QE's resolution: 16 … 1 (1/16 … full step) while enabled, else 0.
  uint8_t motor_resolution(int motor) const { return frame_motor_resolution_[motor]; }
  uint8_t microstep_mode() const { return frame_microstep_mode_; }

  /// Moves the frame took (run, dropped by an alarm or flushed), motor moves an alarm stopped
  /// or skipped, moves stretched to the channels' step rate. Context: any.
  uint32_t moves_started() const { return moves_started_; }
  uint32_t alarm_stops() const { return alarm_stops_; }
  uint32_t moves_stretched() const { return moves_stretched_; }

  // ---- frame side ----
  /// Power-on state with the pen at `servo_up`. Context: loop, before the frame runs.
  void begin(uint16_t servo_up) { executor_.reset(servo_up); }
  /// One frame of `period_us`: controls, the alarm, the next move, a tick if one is due, then
  /// publishes the state. Context: frame ISR.
  void run_frame(uint32_t period_us);
  /// The executor (positions, servo). Context: frame.
  const EbbMotionExecutor& executor() const { return executor_; }
  /// The current move's length in seconds (stretch included; 0 for HM until known), and the
  /// share of it done, 0 … 1 (1 when idle). Context: frame.
  double move_duration_s() const { return move_duration_s_; }
  double progress() const;

 private:
  void apply_controls();
  void flush();
  void stop_for_alarm();
  void load_next_move(uint32_t period_us);
  void tick(uint32_t period_us);
  void publish();
  void fit_to_step_rate(uint32_t period_us);
  void describe_stretch(double asked_per_s, double carried_per_s, uint32_t period_us);

  // loop → frame
  SpscQueue<EbbMove, kCapacity> fifo_;
  SpscQueue<EbbControl, 8> controls_;
  uint32_t depth_ = 1;
  volatile uint32_t moves_queued_ = 0;    // loop: moves pushed
  volatile uint32_t moves_started_ = 0;   // frame: moves taken from the FIFO
  volatile uint16_t pen_now_target_ = 0;  // written before kPenUpNow is queued
  volatile uint16_t pen_now_rate_ = 0;
  volatile uint16_t reset_servo_ = 0;  // written before kReset is queued
  // frame side
  EbbMotionExecutor executor_;
  EbbTickClock clock_;
  uint32_t move_ticks_done_ = 0;
  double move_duration_s_ = 0.0;
  volatile uint32_t alarm_stops_ = 0;
  volatile uint32_t moves_stretched_ = 0;
  bool stretch_named_ = false;     // the first stretch was reported with its move and rates
  char stretch_detail_[192] = {};  // that report's detail (the fault path keeps the pointer)
  // frame → loop
  volatile bool frame_busy_ = false;
  volatile bool frame_motor_moving_[2] = {};
  volatile int32_t frame_global_steps_[2] = {};
  volatile bool frame_pen_up_ = true;
  volatile bool frame_servo_settled_ = true;
  volatile uint8_t frame_motor_resolution_[2] = {};
  volatile uint8_t frame_microstep_mode_ = 1;
};

}  // namespace stepdance::ebb
