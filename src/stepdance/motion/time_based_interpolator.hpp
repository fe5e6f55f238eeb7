// TimeBasedInterpolator (TBI): queued straight moves, planned with look-ahead, executed in the frame.
#pragma once

#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/spsc_queue.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"
#include "stepdance/motion/move_output_ports.hpp"
#include "stepdance/motion/planner/block_executor.hpp"
#include "stepdance/motion/planner/lookahead_planner.hpp"
#include "stepdance/motion/planner/motion_limits.hpp"

// The original library's axis numbers of the TBI.
constexpr uint8_t TBI_AXIS_X = 0;
constexpr uint8_t TBI_AXIS_Y = 1;
constexpr uint8_t TBI_AXIS_Z = 2;
constexpr uint8_t TBI_AXIS_E = 3;
constexpr uint8_t TBI_AXIS_R = 4;
constexpr uint8_t TBI_AXIS_T = 5;

namespace stepdance {

/// Pre-planned motion for sketches, G-code, EBB and RPC: straight moves to positions on six axes
/// (X, Y, Z, E in mm, R and T in the sketch's units), in order, summed with live inputs downstream.
///
/// Unlike the original (constant speed per move, no acceleration), moves are planned in the loop
/// with look-ahead: trapezoidal speed profiles within an acceleration limit, corner speeds by
/// junction deviation, and speed/acceleration limits that hold at the motors (see limits(): per
/// axis, or per joint such as CoreXY's x ± y). Move time comes from the XYZ path length (E-only
/// moves from |E|, R/T-only moves from their own length). Only blocks whose speeds are final go to
/// the frame, through a 32-block queue; the planner holds 32 more (slots_remaining counts those).
/// Every move ends exactly on its target whatever the override did.
///
/// Contexts: add_*, reset_block_queue, limits and setters from the loop; run() is the frame.
class TimeBasedInterpolator : public Block, public MoveOutputPorts {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "TimeBasedInterpolator"; }
  /// The original's raw block layout, for sketches that call add_block().
  struct position {
    double x_mm;
    double y_mm;
    double z_mm;
    double e_mm;
    double r_mm;
    double t_rad;
  };
  struct motion_block {
    uint8_t block_type;  ///< a PositionMode: INCREMENTAL, ABSOLUTE or GLOBAL
    uint32_t block_id;
    float block_time_s;          ///< > 0: a timed move (or a dwell when nothing moves)
    float block_velocity_per_s;  ///< used when block_time_s is 0
    struct position block_position;
  };

  /// Path acceleration used until the sketch sets its own limits, units/s².
  static constexpr double kDefaultAccelerationPerS2 = 2000.0;
  /// Blocks are handed to the frame once their speeds are final, or when the frame holds less
  /// than this much motion (so it never runs dry while the loop keeps up), microseconds.
  static constexpr uint32_t kCommitAheadUs = 10000;
  /// The last waiting block (planned to stop) is handed over only when the frame holds less.
  static constexpr uint32_t kLastBlockAheadUs = 3000;
  /// A block counts as at most this long (16.7 min) on the commit clock, µs.
  static constexpr uint32_t kMaxCommitAheadUs = 1000000000;
  /// From rest, the first move waits this long for followers to plan with, microseconds.
  static constexpr uint32_t kStartDelayUs = 20000;

  TimeBasedInterpolator();

  /// Begins the outputs and registers the block in the pre-channel stage (execution) and the
  /// loop (planning). kFull if a registry is full. Context: loop.
  Status begin();

  /// Queues a move at velocity_per_s (path units/s) to (x…t): INCREMENTAL values are distances,
  /// ABSOLUTE targets are positions in the TBI's own coordinates, GLOBAL adopts the machine
  /// position first when idle. Returns the planner slots left, or −1 if the queue is full, a
  /// stop is in progress, an alarm is active, or a value is not finite (refusals are counted and
  /// reported as warnings). A move that goes nowhere is accepted and skipped. Context: loop.
  int16_t add_move(uint8_t mode, float velocity_per_s, DecimalPosition x, DecimalPosition y, DecimalPosition z,
                   DecimalPosition e, DecimalPosition r, DecimalPosition t);
  /// As add_move, lasting time_s (the speed is path length / time_s; a warning is reported when
  /// the machine's limits make it slower). Nothing moving: a dwell of time_s. Context: loop.
  int16_t add_timed_move(uint8_t mode, float time_s, DecimalPosition x, DecimalPosition y, DecimalPosition z,
                         DecimalPosition e, DecimalPosition r, DecimalPosition t);
  /// The original's raw add (block_type is the mode). Returns slots left or −1. Context: loop.
  int16_t add_block(motion_block* block);

  /// True when nothing is queued, moving or stopping. Context: loop.
  bool is_idle();
  /// True when add_move would refuse for lack of room. Context: loop.
  bool queue_is_full();
  /// Moves (and dwells) not yet finished: waiting in the planner, handed to the frame, and the
  /// one executing. Context: loop.
  size_t moves_held() const { return planner_.size() + committed_.size() + (executor_.idle() ? 0u : 1u); }
  /// Decelerates to rest within the acceleration limit, then drops every queued move. Positions
  /// stay where the deceleration ends. Context: loop.
  void reset_block_queue();
  /// Stops at once and drops every queued move (no deceleration). Context: loop.
  void emergency_stop();
  /// True from a reset_block_queue() or emergency_stop() until the stop completes (moves are
  /// refused meanwhile). Context: loop.
  bool stop_in_progress() const { return stop_pending_; }

  /// Machine limits used for planning. Context: loop (takes effect for moves added later).
  planner::MotionLimits& limits() { return limits_; }
  /// Path acceleration when no axis or joint limit is tighter, units/s². Context: loop.
  void set_acceleration(double units_per_s2) { limits_.set_default_acceleration(units_per_s2); }
  /// Corner tolerance of the junction-deviation model, path units (default 0.02). Context: loop.
  void set_junction_deviation(double units) { planner_.set_junction_deviation(units); }

  /// Speed along the path now, units/s. Context: any.
  double current_speed() const { return executor_.speed(); }
  /// Moves refused since begin (full queue, stop in progress, alarm, bad values). Context: any.
  uint32_t refused_moves() const { return refused_; }
  /// Frames in which a block ended at speed with nothing committed after it. Context: any.
  uint32_t underruns() const { return executor_.underruns(); }
  /// refused_moves, underruns. Context: loop.
  void report_counters(CounterSink& sink) const override {
    sink.counter("refused_moves", refused_);
    sink.counter("underruns", executor_.underruns());
  }
  /// Where the last queued move ends, world units (axis 0..5). Context: loop.
  double planned_position(int axis) const { return planned_end_[axis]; }

  /// Publishes its names under "<instance_name>." in `registry`, an RPC, which lists them
  /// (docs/rpc.md): the same as registry->enroll(instance_name, *this). Context: loop (setup).
  template <class Registry>
  void enroll(Registry* registry, const char* instance_name) {
    registry->enroll(instance_name, *this);
  }
  /// One frame: follow the committed blocks, set and push the outputs. Context: frame ISR.
  void run() override;
  /// Plans and commits final blocks; finishes stops. Context: loop (dance_loop).
  void loop() override;

  /// Multiplies the planned speed live (0 pauses smoothly; up to the machine's limits above 1;
  /// negative values act as 0). Changes are followed within the acceleration limit.
  ControlParameter speed_overide = 1;
  /// Correctly spelt alias of speed_overide.
  ControlParameter& speed_override = speed_overide;
  /// Planner slots left (as returned by add_move).
  volatile uint16_t slots_remaining = planner::LookaheadPlanner::kCapacity;

  // output_x … output_t, output_parameter, output_duration (MoveOutputPorts); the duration is the
  // move's planned duration at override 1.

 private:
  enum class Command : uint8_t { kStop, kStopNow };

  int16_t queue_move(uint8_t mode, double velocity, double time_s, const double (&values)[planner::kPlannerAxes]);
  int16_t refuse(const char* why);
  void adopt_outputs_when_idle();
  void commit_final_blocks();
  bool must_commit_now();
  void apply_commands();
  BlockPort* axis_port(int axis);

  planner::MotionLimits limits_;
  planner::LookaheadPlanner planner_;
  planner::CommittedQueue committed_;
  SpscQueue<Command, 8> commands_;
  planner::BlockExecutor executor_;
  double planned_end_[planner::kPlannerAxes] = {};
  uint32_t next_id_ = 1;
  uint32_t oldest_waiting_since_us_ = 0;  // when the oldest uncommitted block arrived
  uint32_t committed_until_us_ = 0;       // when the frame will finish what it holds (estimate)
  uint32_t refused_ = 0;
  volatile bool stop_pending_ = false;    // loop: a stop was sent and has not completed
  volatile bool frame_stopping_ = false;  // frame: the executor is decelerating for a stop
  DecimalPosition state_[planner::kPlannerAxes] = {};
  DecimalPosition parameter_ = 1;
  DecimalPosition duration_ = 0;
};

}  // namespace stepdance
