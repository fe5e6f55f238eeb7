// Eibotboard: an EiBotBoard (AxiDraw controller) that plotter software drives over USB serial.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/byte_stream.hpp"
#include "stepdance/core/counters.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/interfaces/ebb/ebb_commands.hpp"
#include "stepdance/interfaces/ebb/ebb_motion_queue.hpp"
#include "stepdance/interfaces/ebb/ebb_pen.hpp"
#include "stepdance/interfaces/ebb/ebb_replies.hpp"
#include "stepdance/interfaces/link/line_reader.hpp"
#include "stepdance/interfaces/link/serial_link.hpp"
#include "stepdance/motion/move_output_ports.hpp"

namespace stepdance {

/// How the EBB's two motors make X and Y.
enum EbbKinematics : uint8_t {
  EBB_KINEMATICS_COREXY = 0,  ///< AxiDraw: motor1 = x + y, motor2 = x − y (default)
  EBB_KINEMATICS_XY = 1,      ///< motor1 = x, motor2 = y
};

/// Speaks the EiBotBoard (EBB) command set so the AxiDraw software (Inkscape extension, Python
/// API), saxi and other plotter programs drive a Stepdance machine, while live inputs mix in.
///
/// Motion commands (SM, XM, LM, LT, HM, EM, SP, S2, TP) go through a FIFO to the frame, which
/// executes them tick for tick as an EBB does (the 40 µs accumulator algorithm, not re-planned;
/// a move faster than the channels' one step per frame runs on a slower clock, counted and reported);
/// queries and settings act at once. While the FIFO is full the next motion command waits and
/// nothing more is read (USB flow control), so no command is ever dropped. Both reply syntaxes
/// (legacy and CU,10,1 "future") and the EBB's error replies are exact. See docs/axidraw.md.
///
/// Outputs: x and y in mm from the motors' positions through the chosen kinematics and the steps/mm
/// of the channels they drive (one 1/16 step is one channel step; see set_ratio_xy), scaled by the
/// EM mode; z the pen servo as pulse-width offset from 1.5 ms in servo-board steps (1 step = 1 µs)
/// times the z ratio.
///
/// It composes four objects and keeps the link and the outputs: ebb::EbbCommands (the command
/// set), ebb::EbbMotionQueue (the FIFO and its execution in the frame), ebb::EbbPen (the servo
/// settings and pen moves) and ebb::EbbReplies (both reply syntaxes).
/// Context: the loop (dance_loop serves the link); run() is the frame.
class Eibotboard : public Block, public MoveOutputPorts, public link::LinkedProtocol<Eibotboard> {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "Eibotboard"; }
  /// Motion FIFO capacity (QU,2); the EBB starts with a depth of 1 (CU,4 changes it).
  static constexpr uint32_t kFifoCapacity = ebb::EbbMotionQueue::kCapacity;
  /// Longest command accepted, bytes (without the line ending).
  static constexpr size_t kMaxLineBytes = 255;
  /// The version reply: ≥ 2.5.3 makes clients use LM, ≥ 2.6.0 SR (see set_version_string()).
  static constexpr const char* kDefaultVersion = ebb::EbbCommands::kDefaultVersion;

  Eibotboard();

  // begin() on the board's console (USB Serial), begin(&Serial) on a port (any Arduino Stream),
  // begin(&Serial1, baud) on a hardware UART: link::LinkedProtocol. kFull if a registry is full.
  // Context: loop.

  /// mm per motor step at 1/16 microstepping, as output_units_mm per input_units_steps. Optional:
  /// at start the board takes the ratio of the channels its x and y drive (one EBB 1/16 step is
  /// one channel step), and refuses to start if this one disagrees with them; it is used as it is
  /// only when no channel is reached (default 25.4 mm per 2032 steps = 80 steps/mm). Context: loop.
  void set_ratio_xy(float output_units_mm, float input_units_steps);
  /// Output units of z per servo step (µs of pulse width); default 1 per 50 (the original's).
  void set_ratio_z(float output_units_mm, float input_units_steps);
  /// How motor positions become X and Y (default CoreXY). Context: loop, while idle.
  void set_kinematics(EbbKinematics kinematics) { kinematics_ = kinematics; }
  /// The V reply (without line ending); e.g. "... Firmware Version 2.5.2" makes saxi use XM.
  /// The text must outlive the block. Context: loop.
  void set_version_string(const char* version) { commands_.set_version(version); }

  // output_x … output_t, output_parameter, output_duration: MoveOutputPorts.

  /// Commands refused with an error reply since begin. Context: any.
  uint32_t errors_replied() const { return replies_.errors(); }
  /// Replies that found no room (should stay 0: a line is taken only when its reply fits).
  uint32_t replies_dropped() const { return replies_.dropped(); }

  /// commands (lines answered), fifo_full_waits (motion commands that found the FIFO full and
  /// waited, unread input behind them), moves_started (FIFO entries the frame took),
  /// errors_replied, replies_dropped. Context: loop.
  void report_counters(CounterSink& sink) const override;

  /// True when the frame has nothing left to do: no move runs or waits in the FIFO, no stop or
  /// pen command waits for it, and the pen servo has reached its position, so the outputs stay
  /// as they are until the next command (one that waited for FIFO room is queued at the next
  /// loop pass). Context: loop.
  bool is_idle() const;

  /// At start (dance_start), after the frame period: takes steps/mm from the channels output_x
  /// and output_y reach, directly or through the block they feed (a kinematics); false, with a
  /// kBadConfiguration fault saying why, when those channels differ or set_ratio_xy() disagrees
  /// with them. Context: loop.
  bool check_wiring() override;
  /// Serves the link: reads commands while the FIFO has room, replies. Context: loop.
  void loop() override;
  /// One tick of EBB motion; sets and pushes the outputs. Context: frame ISR.
  void run() override;

 private:
  friend class link::LinkedProtocol<Eibotboard>;
  Status begin_stream(ByteStream& stream);
  // The link (eibotboard.cpp)
  void read_lines(ByteStream& stream);
  void execute_line();
  size_t take_command_name();
  void finish_line();
  // The frame's outputs (eibotboard_frame.cpp)
  void update_outputs();

  // loop side
  // ASCII lines ended by CR or LF (CR LF and LF CR end one; empty lines are skipped), control and
  // non-ASCII bytes dropped; a line waits in the reader while its motion command finds the FIFO full.
  link::LineReader<kMaxLineBytes> lines_{link::LineRules{true, false, true, true}};
  ebb::EbbReplies replies_;
  ebb::EbbPen pen_;
  ebb::EbbMotionQueue queue_;
  ebb::EbbCommands commands_{replies_, queue_, pen_};
  bool waiting_for_room_ = false;
  uint32_t commands_done_ = 0;
  uint32_t fifo_full_waits_ = 0;
  char command_name_[3] = {};
  EbbKinematics kinematics_ = EBB_KINEMATICS_COREXY;
  double mm_per_sixteenth_ = 25.4 / 2032.0;
  bool ratio_xy_given_ = false;  // set_ratio_xy() was called: the channels must agree with it
  double z_units_per_step_ = 1.0 / 50.0;
  // frame side
  double last_output_[3] = {};  // x, y, z as last set, world units
  DecimalPosition state_[8] = {};
};

}  // namespace stepdance
