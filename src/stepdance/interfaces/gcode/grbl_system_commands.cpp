// The Grbl link's `$` commands: reports, unlock, homing, check mode and jogging (settings: grbl_setting_commands.cpp).
#include <string.h>

#include "stepdance/interfaces/gcode/grbl_protocol.hpp"
#include "stepdance/interfaces/gcode/travel_check.hpp"

namespace stepdance::gcode {

GrblProtocol::LinkState GrblProtocol::link_state() {
  if (alarm_ != 0) return LinkState::kAlarm;
  if (interpreting_.check_mode()) return LinkState::kCheck;
  switch (machine_->motion_state()) {
    case MotionState::kRun: return LinkState::kRun;
    case MotionState::kHolding: return LinkState::kHold;
    case MotionState::kJog: return LinkState::kJog;
    case MotionState::kIdle: break;
  }
  return LinkState::kIdle;
}

// Grbl 1.1h's system_execute_line dispatches on the letter after the `$`: `$J=` runs in Idle or
// Jog; `$$ $G $C $X` (the letter alone, error:3 otherwise) in any state, but `$$` not while
// running or holding; every other command, and `$N=v` settings (no letter in the table), only in
// Idle or Alarm.
constexpr GrblProtocol::DollarTable GrblProtocol::kDollarCommands = link::make_command_table<DollarCommand>({
    {"J", {&GrblProtocol::dollar_jog, kIdleOrJog}},
    {"$", {&GrblProtocol::dollar_settings, kAnyState}},
    {"G", {&GrblProtocol::dollar_parser_state, kAnyState}},
    {"C", {&GrblProtocol::dollar_check_mode, kAnyState}},
    {"X", {&GrblProtocol::dollar_unlock, kAnyState}},
    {"#", {&GrblProtocol::dollar_parameters, kIdleOrAlarm}},
    {"H", {&GrblProtocol::dollar_homing, kIdleOrAlarm}},
    {"I", {&GrblProtocol::dollar_build_info, kIdleOrAlarm}},
    {"N", {&GrblProtocol::dollar_startup_lines, kIdleOrAlarm}},
    {"S", {&GrblProtocol::dollar_sleep, kIdleOrAlarm}},
    {"R", {&GrblProtocol::dollar_restore, kIdleOrAlarm}},
});

// `text` follows the `$`, upper-cased and without blanks (the receiver's work).
// A bare `$` prints Grbl's help line. The state check comes before the command, so a refused command
// has no effect at all.
GrblError GrblProtocol::execute_system(const char* text, size_t length) {
  if (length == 0) {
    send_text("[HLP:$$ $# $G $I $N $x=val $Nx=line $J=line $SLP $C $X $H ~ ! ? ctrl-x]");
    return GrblError::kOk;
  }
  static_assert(kDollarCommands.names_unique(), "each `$` letter once");
  const char letter[2] = {text[0], '\0'};
  const auto* command = kDollarCommands.find(letter);
  const uint8_t states = command != nullptr ? command->handler.states : kIdleOrAlarm;  // `$N=v`: a setting
  if ((states & state_bit(link_state())) == 0) return GrblError::kNotIdle;
  if (command == nullptr) return execute_setting_write(text, length);
  return (this->*command->handler.run)(text + 1, length - 1);
}

GrblError GrblProtocol::dollar_jog(const char* rest, size_t length) {
  if (length == 0 || rest[0] != '=') return GrblError::kInvalidDollarStatement;
  return execute_jog(rest + 1, length - 1);
}

GrblError GrblProtocol::dollar_settings(const char*, size_t length) {
  if (length != 0) return GrblError::kInvalidDollarStatement;
  const LinkState state = link_state();
  if (state == LinkState::kRun || state == LinkState::kHold) return GrblError::kNotIdle;
  report_settings();
  return GrblError::kOk;
}

GrblError GrblProtocol::dollar_parser_state(const char*, size_t length) {
  if (length != 0) return GrblError::kInvalidDollarStatement;
  report_parser_state();
  return GrblError::kOk;
}

GrblError GrblProtocol::dollar_check_mode(const char*, size_t length) {
  if (length != 0) return GrblError::kInvalidDollarStatement;
  if (interpreting_.check_mode()) {
    send_text("[MSG:Disabled]");
    reset_requested_ = true;  // as Grbl: leaving check mode resets the parser
    return GrblError::kOk;
  }
  if (link_state() != LinkState::kIdle) return GrblError::kNotIdle;  // not in alarm either
  interpreting_.set_check_mode(true);
  send_text("[MSG:Enabled]");
  return GrblError::kOk;
}

// $X (kill alarm lock): the machine is trusted without homing, with Grbl's caution message.
GrblError GrblProtocol::dollar_unlock(const char*, size_t length) {
  if (length != 0) return GrblError::kInvalidDollarStatement;
  if (alarm_ != 0) send_text("[MSG:Caution: Unlocked]");
  alarm_ = 0;
  return GrblError::kOk;
}

GrblError GrblProtocol::dollar_parameters(const char*, size_t length) {
  if (length != 0) return GrblError::kInvalidDollarStatement;
  report_parameters();
  return GrblError::kOk;
}

// $H answers only when the homing routine ends (answer_homing_when_done); a successful start clears
// the alarm, as Grbl's homing cycle does.
GrblError GrblProtocol::dollar_homing(const char*, size_t length) {
  if (!settings_.homing_enabled()) return GrblError::kHomingDisabled;
  if (length != 0) return GrblError::kInvalidDollarStatement;
  const GrblError error = machine_->home();
  if (error == GrblError::kOk) {
    alarm_ = 0;
    homing_reply_pending_ = machine_->homing_in_progress();
  }
  if (error == GrblError::kHomingDisabled) send_text("[MSG:Homing is not set up on this machine]");
  return error;
}

GrblError GrblProtocol::dollar_build_info(const char*, size_t length) {
  if (length != 0) return GrblError::kInvalidDollarStatement;
  report_build_info();
  return GrblError::kOk;
}

GrblError GrblProtocol::dollar_startup_lines(const char*, size_t length) {
  if (length != 0) return GrblError::kInvalidDollarStatement;  // startup lines are not stored
  send_text("$N0=");
  send_text("$N1=");
  return GrblError::kOk;
}

GrblError GrblProtocol::dollar_sleep(const char*, size_t) {
  return GrblError::kInvalidDollarStatement;  // `$SLP`: no sleep mode here
}

GrblError GrblProtocol::dollar_restore(const char* rest, size_t length) {
  if (length < 3 || strncmp(rest, "ST=", 3) != 0) return GrblError::kInvalidDollarStatement;
  return execute_restore(rest + 3, length - 3);
}

namespace {

constexpr uint32_t word_bit(char letter) { return 1u << word_index(letter); }
constexpr uint16_t group_bit(GGroup group) { return static_cast<uint16_t>(1u << static_cast<int>(group)); }

/// Grbl's jog rules: X Y Z F N words, G20/G21, G90/G91 and G53 only (error:16), a feed
/// (error:22) and an axis word (error:16).
GrblError check_jog_words(const GcodeBlock& block) {
  constexpr uint32_t kAxes = word_bit('X') | word_bit('Y') | word_bit('Z');
  constexpr uint32_t kAllowedWords = kAxes | word_bit('F') | word_bit('N');
  constexpr uint16_t kAllowedGroups =
      group_bit(GGroup::kUnits) | group_bit(GGroup::kDistance) | group_bit(GGroup::kNonModal);
  const bool only_g53 = !block.has_g(GGroup::kNonModal) || block.g_code(GGroup::kNonModal) == 530;
  if ((block.words_present & ~kAllowedWords) != 0 || (block.g_groups_present & ~kAllowedGroups) != 0 ||
      block.m_groups_present != 0 || !only_g53 || block.printer_housekeeping) {
    return GrblError::kInvalidJogCommand;
  }
  if (!block.has_word('F')) return GrblError::kUndefinedFeedRate;
  return (block.words_present & kAxes) == 0 ? GrblError::kInvalidJogCommand : GrblError::kOk;
}

}  // namespace

// $J= (Grbl 1.1 jogging): the motion is checked against the travel and refused with error:15 rather
// than raising an alarm, so a jogging dial can run into the limit safely.
GrblError GrblProtocol::execute_jog(const char* text, size_t length) {
  GcodeBlock block;
  GrblError error = parse_line(text, length, block, parsing_.options());
  if (error == GrblError::kOk) error = check_jog_words(block);
  if (error != GrblError::kOk) return error;
  // A jog is a G1 at its own feed that leaves the parser's modes as they were: planned, never
  // committed.
  block.g[static_cast<int>(GGroup::kMotion)] = 10;
  block.g[static_cast<int>(GGroup::kFeedMode)] = 940;
  block.g_groups_present |= group_bit(GGroup::kMotion) | group_bit(GGroup::kFeedMode);
  interpreting_.adopt_position_when_idle();
  LinePlan plan;
  error = interpreting_.interpreter().plan(block, plan);
  if (error != GrblError::kOk) return error;
  if (plan.motion_count == 0) return GrblError::kInvalidJogCommand;
  if (!within_travel(settings_, plan.motions[0])) return GrblError::kTravelExceeded;
  machine_->jog(plan.motions[0]);
  return GrblError::kOk;
}

}  // namespace stepdance::gcode
