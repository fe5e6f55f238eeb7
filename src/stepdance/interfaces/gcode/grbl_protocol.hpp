// Grbl 1.1 over a byte stream: realtime bytes, `ok`/`error:N` per line, `$` commands, reports.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/byte_stream.hpp"
#include "stepdance/core/nonvolatile_store.hpp"
#include "stepdance/core/text_writer.hpp"
#include "stepdance/interfaces/gcode/gcode_interpreter_stage.hpp"
#include "stepdance/interfaces/gcode/gcode_parser_stage.hpp"
#include "stepdance/interfaces/gcode/grbl_line_reply.hpp"
#include "stepdance/interfaces/gcode/grbl_machine.hpp"
#include "stepdance/interfaces/gcode/grbl_receiver.hpp"
#include "stepdance/interfaces/gcode/grbl_settings.hpp"
#include "stepdance/interfaces/link/command_table.hpp"
#include "stepdance/interfaces/link/reply_ring.hpp"

namespace stepdance::gcode {

/// Speaks Grbl 1.1 so G-code senders work unmodified. Each poll() reads what the stream has
/// (realtime bytes act at once, even while the motion queue is full), executes complete lines
/// while the machine has room, and replies `ok` or `error:N` only after a line is validated.
/// Replies wait in a 1 KiB link::ReplyRing; a line is taken only when its largest reply fits, so
/// nothing is torn or dropped when the host reads slowly. A G-code line goes one way: the
/// receiver hands it out, the link hands it to the ParserStage, which hands its block to the
/// InterpreterStage (plan, travel check, commit), which hands its requests to the machine's
/// planner; whichever stage finishes with it answers through the line's GrblLineReply (never
/// back into the link), and the link writes that reply out, or starts the soft-limit alarm for a
/// line out of travel. Context: loop only.
class GrblProtocol final : private RealtimeHandler {
 public:
  /// Starts the link: loads the settings the host stored earlier (if a store is given), sends
  /// the welcome line and, if the store could not be used, a `[MSG:…]` saying why the defaults
  /// apply. Settings the host writes are saved to the store. The stream, machine and store must
  /// outlive the protocol.
  void begin(ByteStream& stream, GrblMachine& machine, NonvolatileStore* store = nullptr);
  /// Serves the link once; call every loop pass.
  void poll();

  GrblSettings& settings() { return settings_; }
  /// The G-code lines' interpreter (modes, offsets, position). Context: loop.
  const GcodeInterpreter& interpreter() const { return interpreting_.interpreter(); }
  /// True while an alarm locks out G-code (cleared by `$X`, `$H` or a reset that was not moving).
  bool alarm_active() const { return alarm_ != 0; }
  /// Raises a Grbl alarm (ALARM:N is sent); e.g. a limit or fault from the machine.
  void raise_alarm(uint8_t code);

  /// Replies that found no room (should stay 0: lines are taken only when their reply fits).
  uint32_t replies_dropped() const { return replies_.dropped(); }

  static constexpr size_t kReplyBufferBytes = 1024;

 private:
  void on_realtime(uint8_t byte) override;
  void handle_override(uint8_t byte);
  /// Grbl's states as its `$` commands tell them apart (one at a time, alarm first).
  enum class LinkState : uint8_t { kIdle, kAlarm, kCheck, kRun, kHold, kJog };
  /// A soft-limit violation's course: the machine stops, ALARM:2, then only a reset is heard.
  enum class SoftLimit : uint8_t { kNone, kStopping, kLocked };

  LinkState link_state();
  void serve_lines();
  bool answer_homing_when_done();
  void route_line(const ReceivedLine& line);
  void answer(GrblError error);
  void begin_soft_limit_alarm();
  void finish_soft_limit_stop();
  /// A `$` command: its handler gets what follows the command letter; `states` (a bit per
  /// LinkState) are those it runs in, error:8 in the others.
  struct DollarCommand {
    GrblError (GrblProtocol::*run)(const char* rest, size_t length) = nullptr;
    uint8_t states = 0;
  };
  using DollarTable = link::CommandTable<DollarCommand, 11>;
  static constexpr uint8_t state_bit(LinkState state) {
    return static_cast<uint8_t>(1u << static_cast<uint8_t>(state));
  }
  static constexpr uint8_t kAnyState = 0xFF;
  static constexpr uint8_t kIdleOrJog =
      (1u << static_cast<uint8_t>(LinkState::kIdle)) | (1u << static_cast<uint8_t>(LinkState::kJog));
  static constexpr uint8_t kIdleOrAlarm =
      (1u << static_cast<uint8_t>(LinkState::kIdle)) | (1u << static_cast<uint8_t>(LinkState::kAlarm));
  static const DollarTable kDollarCommands;

  GrblError execute_system(const char* text, size_t length);
  GrblError dollar_jog(const char* rest, size_t length);
  GrblError dollar_settings(const char* rest, size_t length);
  GrblError dollar_parser_state(const char* rest, size_t length);
  GrblError dollar_check_mode(const char* rest, size_t length);
  GrblError dollar_unlock(const char* rest, size_t length);
  GrblError dollar_parameters(const char* rest, size_t length);
  GrblError dollar_homing(const char* rest, size_t length);
  GrblError dollar_build_info(const char* rest, size_t length);
  GrblError dollar_startup_lines(const char* rest, size_t length);
  GrblError dollar_sleep(const char* rest, size_t length);
  GrblError dollar_restore(const char* rest, size_t length);
  GrblError execute_jog(const char* text, size_t length);
  GrblError execute_setting_write(const char* text, size_t length);
  GrblError execute_restore(const char* text, size_t length);
  void load_stored_settings();
  void save_stored_settings();
  void soft_reset();

  void send_line(const TextWriter& line);
  void send_text(const char* text);
  void flush_replies();
  size_t reply_space() const { return replies_.space(); }

  void report_status();
  void append_position(TextWriter& line, const double (&offset)[kOffsetAxisCount]);
  void append_buffer_and_feed(TextWriter& line);
  void append_offsets_and_overrides(TextWriter& line, const double (&offset)[kOffsetAxisCount], bool busy);
  void report_welcome();
  void report_settings();
  void report_parameters();
  void report_parser_state();
  void report_build_info();
  void append_axes(TextWriter& line, const double* values_mm, int count);

  ByteStream* stream_ = nullptr;
  GrblMachine* machine_ = nullptr;
  NonvolatileStore* store_ = nullptr;
  GrblReceiver receiver_;
  GrblSettings settings_;
  InterpreterStage interpreting_;
  ParserStage parsing_{interpreting_};
  uint8_t alarm_ = 0;
  SoftLimit soft_limit_ = SoftLimit::kNone;
  bool homing_reply_pending_ = false;  // `$H` is answered when its routine ends, as Grbl does
  bool status_requested_ = false;
  bool reset_requested_ = false;
  uint8_t feed_override_percent_ = 100;
  uint8_t rapid_override_percent_ = 100;
  uint8_t spindle_override_percent_ = 100;
  uint8_t reports_until_wco_ = 0;
  uint8_t reports_until_overrides_ = 0;
  double last_wco_mm_[kOffsetAxisCount] = {};
  link::ReplyRing<kReplyBufferBytes> replies_;
  GrblLineReply line_reply_{replies_};  // the G-code line down its path, until it is answered
};

}  // namespace stepdance::gcode
