// EBB command set: each EBB command's parameters read, checked, acted on and answered.
#pragma once

#include <stdint.h>

#include "stepdance/interfaces/ebb/ebb_motion.hpp"
#include "stepdance/interfaces/ebb/ebb_motion_queue.hpp"
#include "stepdance/interfaces/ebb/ebb_parameters.hpp"
#include "stepdance/interfaces/ebb/ebb_pen.hpp"
#include "stepdance/interfaces/ebb/ebb_pins.hpp"
#include "stepdance/interfaces/ebb/ebb_replies.hpp"
#include "stepdance/interfaces/link/command_table.hpp"

namespace stepdance::ebb {

/// The EBB's commands (ebb-protocol.md): motion commands (SM, XM, LM, LT, HM, EM, SP, S2, TP) go
/// to the motion queue, settings and queries are answered at once from what the queue published,
/// pin commands act on the emulated ports. Every command is answered through the replies; an
/// unknown one gets the EBB's error, never a bare OK. It keeps the board's small settings of its
/// own: user variables (SL/QL), the tag (ST/QT), the servo timeout (SR), the pins, the version.
/// Context: loop.
class EbbCommands {
 public:
  /// The version reply: ≥ 2.5.3 makes clients use LM, ≥ 2.6.0 SR.
  static constexpr const char* kDefaultVersion = "EBBv13_and_above EB Firmware Version 2.8.1";

  /// Answers through `replies`, queues motion in `queue`, keeps the pen in `pen`; all three must
  /// outlive the command set.
  EbbCommands(EbbReplies& replies, EbbMotionQueue& queue, EbbPen& pen) : replies_(replies), queue_(queue), pen_(pen) {}

  /// Runs command `name` (upper case, as the replies were told with set_command()) with its
  /// parameters. False only when it is a motion command and the queue has no room: nothing was
  /// done or answered, and the line waits; true once the command is answered.
  bool execute(const char* name, EbbParameters& parameters);

  /// The V reply (without line ending); the text must outlive the command set.
  void set_version(const char* version) { version_ = version; }
  /// The SL/QL user variable at `index` (0 … 31); the servo power timeout SR set, ms.
  uint8_t variable(int index) const { return variables_[index]; }
  uint32_t servo_timeout_ms() const { return servo_timeout_ms_; }

 private:
  /// What the dispatcher checks before a handler runs.
  enum Flags : uint8_t {
    kMovesMotors = 1,   // refused with !9 while an alarm is raised (the fault path)
    kNoParameters = 2,  // any parameter is an error (the parser's reply), the handler is not called
  };
  /// A command's handler: false while the queue has no room (the line waits), true once answered.
  struct Handler {
    bool (EbbCommands::*run)(EbbParameters&) = nullptr;
    uint8_t flags = 0;
  };
  static const link::Command<Handler>* find(const char* name);  // ebb_commands.cpp

  bool queue_and_reply(const EbbMove& move);
  // Motion (ebb_motion_commands.cpp)
  bool command_sm(EbbParameters& p);
  bool command_xm(EbbParameters& p);
  bool stepper_move(EbbParameters& p, bool mixed);
  bool steps_move(const int64_t (&steps)[2], int64_t duration_ms, bool mixed, EbbMove& move);
  bool command_lm(EbbParameters& p);
  bool command_lt(EbbParameters& p);
  bool low_level_move(EbbParameters& p, bool timed);
  bool command_hm(EbbParameters& p);
  bool command_em(EbbParameters& p);
  bool command_sp(EbbParameters& p);
  bool command_s2(EbbParameters& p);
  bool command_tp(EbbParameters& p);
  // Settings and queries (ebb_query_commands.cpp)
  bool command_sc(EbbParameters& p);
  bool command_cu(EbbParameters& p);
  bool command_qu(EbbParameters& p);
  bool command_es(EbbParameters& p);
  bool command_v(EbbParameters& p);
  bool command_qm(EbbParameters& p);
  bool command_qg(EbbParameters& p);
  bool command_sr(EbbParameters& p);
  bool command_sl(EbbParameters& p);
  bool command_ql(EbbParameters& p);
  bool command_st(EbbParameters& p);
  bool command_qt(EbbParameters& p);
  bool command_qs(EbbParameters& p);
  bool command_cs(EbbParameters& p);
  bool command_qp(EbbParameters& p);
  bool command_qb(EbbParameters& p);
  bool command_qc(EbbParameters& p);
  bool command_qe(EbbParameters& p);
  bool command_qr(EbbParameters& p);
  bool command_r(EbbParameters& p);
  // Pins (ebb_pin_commands.cpp)
  bool read_pin(EbbParameters& p, int& port, int& pin);
  bool command_pd(EbbParameters& p);
  bool command_po(EbbParameters& p);
  bool command_pi(EbbParameters& p);
  bool command_pc(EbbParameters& p);
  bool command_pg(EbbParameters& p);

  EbbReplies& replies_;
  EbbMotionQueue& queue_;
  EbbPen& pen_;
  const char* version_ = kDefaultVersion;
  bool button_pressed_ = false;
  uint8_t variables_[32] = {};
  char tag_[17] = {};
  EbbPins pins_;
  uint32_t servo_timeout_ms_ = 60000;
  bool motors_enabled_[2] = {};  // as the last queued EM or ES,1 left them (EM's default for motor 2)
};

}  // namespace stepdance::ebb
