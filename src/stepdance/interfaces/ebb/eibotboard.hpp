// Eibotboard: an EiBotBoard (AxiDraw controller) that plotter software drives over USB serial.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/byte_stream.hpp"
#include "stepdance/core/counters.hpp"
#include "stepdance/core/spsc_queue.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/interfaces/ebb/ebb_motion.hpp"
#include "stepdance/interfaces/ebb/ebb_parameters.hpp"
#include "stepdance/interfaces/ebb/ebb_pins.hpp"
#include "stepdance/interfaces/link/command_table.hpp"
#include "stepdance/interfaces/link/line_reader.hpp"
#include "stepdance/interfaces/link/reply_ring.hpp"
#include "stepdance/interfaces/link/serial_link.hpp"
#include "stepdance/motion/move_output_ports.hpp"
#include "stepdance/core/text_writer.hpp"

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
/// Context: the loop (dance_loop serves the link); run() is the frame.
class Eibotboard : public Block, public MoveOutputPorts, public link::LinkedProtocol<Eibotboard> {
 public:
  /// The class name, for reports. Context: any.
  const char* type_name() const override { return "Eibotboard"; }
  /// Motion FIFO capacity (QU,2); the EBB starts with a depth of 1 (CU,4 changes it).
  static constexpr uint32_t kFifoCapacity = 64;
  /// Longest command accepted, bytes (without the line ending).
  static constexpr size_t kMaxLineBytes = 255;
  /// The version reply: ≥ 2.5.3 makes clients use LM, ≥ 2.6.0 SR (see set_version_string()).
  static constexpr const char* kDefaultVersion = "EBBv13_and_above EB Firmware Version 2.8.1";

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
  void set_version_string(const char* version) { version_ = version; }

  // output_x … output_t, output_parameter, output_duration: MoveOutputPorts.

  /// Commands refused with an error reply since begin. Context: any.
  uint32_t errors_replied() const { return errors_replied_; }
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
  enum class Control : uint8_t { kStop, kStopDisable, kClearSteps, kReset, kPenUpNow };
  static constexpr size_t kReplyBufferBytes = 512;
  static constexpr size_t kLargestReplyBytes = 160;
  static constexpr uint32_t kUnstretchedQ16 = 65536;               // a stretch factor of 1 in Q16
  static constexpr const char* kWarningSource = "Eibotboard";

  /// What the dispatcher checks before a handler runs.
  enum CommandFlags : uint8_t {
    kMovesMotors = 1,   // refused with !9 while an alarm is raised (the fault path)
    kNoParameters = 2,  // any parameter is an error (the parser's reply), the handler is not called
  };
  /// A command's handler: false while the FIFO has no room (the line waits), true once answered.
  struct CommandHandler {
    bool (Eibotboard::*run)(ebb::EbbParameters&) = nullptr;
    uint8_t flags = 0;
  };
  static const link::Command<CommandHandler>* find_command(const char* name);  // eibotboard_commands.cpp

  Status begin_stream(ByteStream& stream);
  // Link (eibotboard.cpp)
  void read_lines(ByteStream& stream);
  void execute_line();
  size_t take_command_name();
  void finish_line();
  // Dispatch and motion commands (eibotboard_commands.cpp); a handler returns false while the
  // FIFO has no room (the line waits), true once the command is answered.
  bool dispatch(const char* name, ebb::EbbParameters& parameters);
  bool queue(const ebb::EbbMove& move);
  bool queue_and_reply(const ebb::EbbMove& move);
  bool command_sm(ebb::EbbParameters& p);
  bool command_xm(ebb::EbbParameters& p);
  bool stepper_move(ebb::EbbParameters& p, bool mixed);
  bool steps_move(const int64_t (&steps)[2], int64_t duration_ms, bool mixed, ebb::EbbMove& move);
  bool command_lm(ebb::EbbParameters& p);
  bool command_lt(ebb::EbbParameters& p);
  bool low_level_move(ebb::EbbParameters& p, bool timed);
  bool command_hm(ebb::EbbParameters& p);
  bool command_em(ebb::EbbParameters& p);
  bool command_sp(ebb::EbbParameters& p);
  bool command_s2(ebb::EbbParameters& p);
  bool command_tp(ebb::EbbParameters& p);
  ebb::EbbMove servo_move(bool up, uint32_t delay_ms) const;
  void servo_now(uint16_t target, uint16_t rate);
  // Settings and queries, answered at once (eibotboard_queries.cpp)
  bool command_sc(ebb::EbbParameters& p);
  bool command_cu(ebb::EbbParameters& p);
  bool switch_syntax(int64_t value);
  bool command_qu(ebb::EbbParameters& p);
  bool command_es(ebb::EbbParameters& p);
  bool command_v(ebb::EbbParameters& p);
  bool command_qm(ebb::EbbParameters& p);
  bool command_qg(ebb::EbbParameters& p);
  bool command_sr(ebb::EbbParameters& p);
  bool command_sl(ebb::EbbParameters& p);
  bool command_ql(ebb::EbbParameters& p);
  bool command_st(ebb::EbbParameters& p);
  bool command_qt(ebb::EbbParameters& p);
  bool command_qs(ebb::EbbParameters& p);
  bool command_cs(ebb::EbbParameters& p);
  bool command_qp(ebb::EbbParameters& p);
  bool command_qb(ebb::EbbParameters& p);
  bool command_qc(ebb::EbbParameters& p);
  bool command_qe(ebb::EbbParameters& p);
  bool command_qr(ebb::EbbParameters& p);
  bool command_r(ebb::EbbParameters& p);
  // Pins (eibotboard_pins.cpp)
  bool read_pin(ebb::EbbParameters& p, int& port, int& pin);
  bool command_pd(ebb::EbbParameters& p);
  bool command_po(ebb::EbbParameters& p);
  bool command_pi(ebb::EbbParameters& p);
  bool command_pc(ebb::EbbParameters& p);
  bool command_pg(ebb::EbbParameters& p);
  // Replies (eibotboard_replies.cpp)
  void reply_ok();
  void reply_data(const char* data, bool ok_after, const char* legacy_ending = "\r\n");
  void reply_error(ebb::EbbError error, const char* name, char offending = ' ');
  bool reply_parameter_error(const ebb::EbbParameters& parameters);
  void send(const char* text) { replies_.send(text); }
  // Frame (eibotboard_frame.cpp)
  void apply_controls();
  void flush_fifo();
  void stop_motion_for_alarm();
  void load_next_move();
  void tick_ebb_time();
  void publish_frame_state();
  void update_outputs();
  double move_duration_s(const ebb::EbbMove& move) const;
  void fit_move_to_step_rate();
  void describe_stretch(double asked_per_s, double carried_per_s);

  // loop side
  // ASCII lines ended by CR or LF (CR LF and LF CR end one; empty lines are skipped), control and
  // non-ASCII bytes dropped; a line waits in the reader while its motion command finds the FIFO full.
  link::LineReader<kMaxLineBytes> lines_{link::LineRules{true, false, true, true}};
  link::ReplyRing<kReplyBufferBytes> replies_;
  bool waiting_for_room_ = false;
  uint32_t commands_done_ = 0;
  uint32_t fifo_full_waits_ = 0;
  char command_name_[3] = {};
  bool future_syntax_ = false;
  bool ack_enabled_ = true;
  uint32_t fifo_depth_ = 1;
  uint16_t servo_up_ = 20000;    // SC,4 (1/12 µs): 1.667 ms, pen up on an AxiDraw-style lift
  uint16_t servo_down_ = 16000;  // SC,5: 1.333 ms
  uint16_t servo_rate_up_ = 0;   // SC,11 / SC,10 (1/12 µs per 24 ms; 0 = at once)
  uint16_t servo_rate_down_ = 0; // SC,12 / SC,10
  bool pen_commanded_up_ = true;  // the pen state the last queued pen command asked for (TP toggles it)
  bool button_pressed_ = false;
  uint8_t variables_[32] = {};
  char tag_[17] = {};
  ebb::EbbPins pins_;
  uint32_t servo_timeout_ms_ = 60000;
  bool motors_enabled_[2] = {};  // as the last queued EM or ES,1 left them (EM's default for motor 2)
  const char* version_ = kDefaultVersion;
  EbbKinematics kinematics_ = EBB_KINEMATICS_COREXY;
  uint32_t errors_replied_ = 0;
  // loop → frame
  SpscQueue<ebb::EbbMove, kFifoCapacity> fifo_;
  SpscQueue<Control, 8> controls_;
  volatile uint32_t moves_queued_ = 0;    // loop: moves pushed
  volatile uint32_t moves_started_ = 0;   // frame: moves taken from the FIFO
  volatile uint32_t alarm_stops_ = 0;     // frame: motor moves stopped or skipped while an alarm is raised
  // frame side
  ebb::EbbMotionExecutor executor_;
  uint32_t tick_time_q16_ = 0;  // frame time not yet spent on an EBB tick, µs·2^16 (< one tick)
  uint32_t stretch_q16_ = kUnstretchedQ16;  // the current move's tick length over 40 µs, ·2^16 (≥ 1)
  double move_stretch_ = 1.0;               // the same as a factor
  bool stretch_named_ = false;   // frame: the first stretch was reported with its move and rates
  char stretch_detail_[192] = {};  // that report's detail (the fault path keeps the pointer)
  volatile uint32_t moves_stretched_ = 0;   // frame: moves slowed down to the step rate
  double mm_per_sixteenth_ = 25.4 / 2032.0;
  bool ratio_xy_given_ = false;  // set_ratio_xy() was called: the channels must agree with it
  double z_units_per_step_ = 1.0 / 50.0;
  uint32_t move_ticks_done_ = 0;
  double move_duration_s_ = 0.0;
  volatile bool frame_busy_ = false;
  volatile bool frame_motor_moving_[2] = {};
  volatile int32_t frame_global_steps_[2] = {};
  volatile bool frame_pen_up_ = true;
  volatile bool frame_servo_settled_ = true;
  volatile uint8_t frame_motor_resolution_[2] = {};  // QE: 16 … 1 (1/16 … full step) when enabled, else 0
  volatile uint8_t frame_microstep_mode_ = 1;         // PI's MS1 … MS3: EM's mode, 1 … 5
  volatile uint16_t pen_now_target_ = 0;  // SP,2/3: written before kPenUpNow is queued
  volatile uint16_t pen_now_rate_ = 0;
  double last_output_[3] = {};  // x, y, z as last set, world units
  DecimalPosition state_[8] = {};
};

}  // namespace stepdance
