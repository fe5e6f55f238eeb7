// GCodeInterface: a Grbl 1.1 compatible G-code link driving its own TimeBasedInterpolator.
#pragma once

#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/byte_stream.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/interfaces/gcode/arc_geometry.hpp"
#include "stepdance/interfaces/gcode/grbl_machine.hpp"
#include "stepdance/interfaces/gcode/grbl_protocol.hpp"
#include "stepdance/interfaces/link/serial_link.hpp"
#include "stepdance/motion/time_based_interpolator.hpp"

namespace stepdance {

class Homing;

/// Lets a G-code sender (gSender, cncjs, bCNC, UGS, or `screen`) drive the sketch over a serial
/// port, speaking Grbl 1.1: `ok`/`error:N` per line after validation, `?` status reports,
/// `!` feed hold, `~` resume, Ctrl-X reset, `$` settings and jogging (see docs/gcode.md for the
/// codes understood). Motion goes through the interface's own TimeBasedInterpolator with
/// look-ahead; its outputs (machine coordinates, mm) are summed with live inputs downstream.
///
/// Planner limits come from the Grbl settings: $110–$112 max rates (mm/min; E uses $110),
/// $120–$122 accelerations (mm/s²), $11 junction deviation (mm), $12 arc tolerance (mm).
/// The feed override and a feed hold act live on the planned speed; the rapid override applies
/// to rapids queued after it changes. Context: everything from the loop (dance_loop runs it).
class GCodeInterface : public Block, public link::LinkedProtocol<GCodeInterface>, private gcode::GrblMachine {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "GCodeInterface"; }
  GCodeInterface() = default;

  // begin(), begin(&Serial), begin(&Serial1, baud[, format]): from link::LinkedProtocol, which
  // starts the link on the board's console or the port (kFull if a registry is full).

  BlockPort& output_x = interpolator_.output_x;
  BlockPort& output_y = interpolator_.output_y;
  BlockPort& output_z = interpolator_.output_z;
  BlockPort& output_e = interpolator_.output_e;
  BlockPort& output_r = interpolator_.output_r;
  BlockPort& output_t = interpolator_.output_t;
  /// Fraction of the current move done (0 → 1).
  BlockPort& output_parameter = interpolator_.output_parameter;
  /// Planned duration of the current move, seconds.
  BlockPort& output_duration = interpolator_.output_duration;

  /// The Grbl settings. `$100`–`$102` (steps/mm, reported to senders) come from the channels at
  /// start (see check_wiring); the sketch needs to set them with set_from_sketch() only
  /// for an axis that drives no channel. Context: loop.
  gcode::GrblSettings& settings() { return protocol_.settings(); }
  /// The planner behind the link (limits, underruns, refused moves). Context: loop.
  TimeBasedInterpolator& interpolator() { return interpolator_; }
  /// The protocol (alarm state, replies dropped). Context: loop.
  const gcode::GrblProtocol& protocol() const { return protocol_; }

  /// Called for M3 (on, clockwise), M4 (on, counter-clockwise) and M5 (off) once the moves
  /// before it have finished, as Grbl syncs spindle changes: a pen lift, a laser, a motor.
  /// `speed` is the S word in force. Context: loop.
  using SpindleCallback = void (*)(bool on, bool clockwise, double speed);
  void set_spindle_callback(SpindleCallback callback) { spindle_callback_ = callback; }

  /// `$H` runs `homing` (its status reads Run until it ends; the interface then adopts the
  /// homed machine position). Without one `$H` answers error:5. Context: loop.
  /// Setting it turns `$22` (homing enabled) on by default, as `$H` and `$20` need.
  void set_homing(Homing* homing) {
    homing_ = homing;
    settings().set_from_sketch(22, homing != nullptr ? 1.0 : 0.0);
  }

  /// Serves the link: reads, executes and replies; feeds pending arc chords. Context: loop.
  void loop() override;
  /// At start: `$100`–`$102` become the steps/mm of the channels G-code X, Y and Z drive
  /// (through a kinematics or directly), as the EBB takes its ratio. A value the sketch also set
  /// with set_from_sketch() must agree, and channels of one axis must agree with each other: else
  /// a kBadConfiguration fault naming the setting and both values, and the engine does not
  /// start. An axis that reaches no channel keeps the sketch's value. Context: loop.
  bool check_wiring() override;

  /// Most arc chords one loop pass hands to the planner. A longer arc is fed over several
  /// passes (its `ok` waits until all of it is planned, as Grbl's does) while realtime commands
  /// are still served between them; planning one chord costs about 11,000 M7 instructions with
  /// a full look-ahead queue, so this bounds the pass (docs/benchmarks-target.md).
  static constexpr uint32_t kArcChordsPerLoopPass = 16;
  /// Arc chords handed to the planner since begin(). Context: loop.
  uint32_t arc_chords_queued() const { return arc_chords_queued_; }

 private:
  struct Pending {
    /// kSpindle and kPause wait for the planner to be idle (program order), then act; kDwell
    /// waits for it too, then lets its time pass over loop passes (Grbl's mc_dwell).
    enum class Kind : uint8_t { kMotion, kDwell, kJog, kSpindle, kPause } kind = Kind::kMotion;
    gcode::Motion motion;
    double dwell_s = 0.0;         // kDwell; kSpindle: the speed
    gcode::CommandCode code = 0;  // kSpindle: M3/M4/M5 (×10)
  };
  static constexpr int kPendingCapacity = 4;  // a line asks for at most a dwell and two motions

  friend class link::LinkedProtocol<GCodeInterface>;
  Status begin_stream(ByteStream& stream);

  // GrblMachine
  void on_motion(const gcode::Motion& motion) override;
  void on_dwell(double seconds) override;
  void on_spindle(gcode::CommandCode m_code, double speed) override;
  void on_program_flow(gcode::CommandCode m_code) override;
  gcode::MotionState motion_state() override;
  bool hold_complete() override;
  void position_mm(double (&out)[gcode::kAxisCount]) override;
  double feed_now_mm_per_min() override;
  uint16_t queue_slots_free() override;
  uint16_t queue_slots_total() override;
  bool ready_for_line() override;
  void take_line_end(gcode::LineAnswer& answer) override;
  void feed_hold() override;
  void cycle_start() override;
  bool soft_reset() override;
  void jog(const gcode::Motion& motion) override;
  void jog_cancel() override;
  void set_overrides(uint8_t feed_percent, uint8_t rapid_percent) override;
  double steps_per_mm(int axis) override;
  gcode::GrblError home() override;
  bool homing_in_progress() override { return homing_started_; }
  bool homing_succeeded() override;
  void adopt_homed_position();

  void push_pending(const Pending& request);
  void drain_pending();
  bool line_in_progress() const;
  void answer_when_taken();
  bool queue_line_motion(const gcode::Motion& motion, double speed_mm_per_s, double time_s);
  bool feed_arc(const gcode::Motion& arc);
  bool act_when_idle(const Pending& request);
  bool dwell_done(double seconds);
  void apply_settings_to_planner();
  void describe_steps_fault(uint32_t number, char axis, double sketch, double channels);
  void apply_override();

  TimeBasedInterpolator interpolator_;
  gcode::GrblProtocol protocol_;
  Pending pending_[kPendingCapacity];
  int pending_head_ = 0;
  int pending_count_ = 0;
  gcode::LineAnswer* line_answer_ = nullptr;  // the last line's, until its requests are all planned
  uint32_t arc_next_chord_ = 0;               // chords of the pending arc already queued
  uint32_t arc_chords_left_this_pass_ = kArcChordsPerLoopPass;
  uint32_t arc_chords_queued_ = 0;
  bool holding_ = false;
  bool jogging_ = false;
  // G4 at the head of the requests: the planner has drained and the dwell runs (Idle meanwhile).
  bool dwelling_ = false;
  uint32_t dwell_last_us_ = 0;  // hal::micros_now() at the last loop pass of the dwell
  uint64_t dwell_elapsed_us_ = 0;
  uint8_t feed_percent_ = 100;
  uint8_t rapid_percent_ = 100;
  SpindleCallback spindle_callback_ = nullptr;
  Homing* homing_ = nullptr;
  bool homing_started_ = false;
  char steps_fault_text_[200] = {};  // a start fault's detail (the fault path keeps the pointer)
};

}  // namespace stepdance
