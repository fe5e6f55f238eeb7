// The Grbl link's `$` commands: reports, unlock, homing, check mode and jogging (settings: grbl_setting_commands.cpp).
#include <string.h>

#include "stepdance/interfaces/gcode/grbl_protocol.hpp"

namespace stepdance::gcode {

GrblProtocol::LinkState GrblProtocol::link_state() {
  if (alarm_ != 0) return LinkState::kAlarm;
  if (check_mode_) return LinkState::kCheck;
  switch (machine_->motion_state()) {
    case MotionState::kRun: return LinkState::kRun;
    case MotionState::kHolding: return LinkState::kHold;
    case MotionState::kJog: return LinkState::kJog;
    case MotionState::kIdle: break;
  }
  return LinkState::kIdle;
}

// `text` follows the `$`, upper-cased and without blanks (the receiver's work). The state rules
// and error numbers are Grbl 1.1h's system_execute_line: `$J=` in Idle or Jog; `$$ $G $C $X`
// (one letter) in any state but `$$` not while running or holding; everything else in Idle or
// Alarm only.
GrblError GrblProtocol::execute_system(const char* text, size_t length) {
  if (length == 0) {
    send_text("[HLP:$$ $# $G $I $N $x=val $Nx=line $J=line $SLP $C $X $H ~ ! ? ctrl-x]");
    return GrblError::kOk;
  }
  const char command = text[0];
  if (command == 'J') {
    const LinkState state = link_state();
    if (state != LinkState::kIdle && state != LinkState::kJog) return GrblError::kNotIdle;
    if (length < 2 || text[1] != '=') return GrblError::kInvalidDollarStatement;
    return execute_jog(text + 2, length - 2);
  }
  if (command == '$' || command == 'G' || command == 'C' || command == 'X') {
    return length == 1 ? execute_any_state_command(command) : GrblError::kInvalidDollarStatement;
  }
  const LinkState state = link_state();
  if (state != LinkState::kIdle && state != LinkState::kAlarm) return GrblError::kNotIdle;
  return execute_idle_command(text, length);
}

GrblError GrblProtocol::execute_any_state_command(char command) {
  const LinkState state = link_state();
  switch (command) {
    case '$':
      if (state == LinkState::kRun || state == LinkState::kHold) return GrblError::kNotIdle;
      report_settings();
      break;
    case 'G': report_parser_state(); break;
    case 'C': return toggle_check_mode();
    default:  // 'X'
      if (alarm_ != 0) send_text("[MSG:Caution: Unlocked]");
      alarm_ = 0;
      break;
  }
  return GrblError::kOk;
}

GrblError GrblProtocol::toggle_check_mode() {
  if (check_mode_) {
    send_text("[MSG:Disabled]");
    reset_requested_ = true;  // as Grbl: leaving check mode resets the parser
    return GrblError::kOk;
  }
  if (link_state() != LinkState::kIdle) return GrblError::kNotIdle;  // not in alarm either
  check_mode_ = true;
  send_text("[MSG:Enabled]");
  return GrblError::kOk;
}

GrblError GrblProtocol::execute_idle_command(const char* text, size_t length) {
  const bool alone = length == 1;
  switch (text[0]) {
    case '#':
      if (!alone) return GrblError::kInvalidDollarStatement;
      report_parameters();
      return GrblError::kOk;
    case 'H': return execute_homing(length);
    case 'I':
      if (!alone) return GrblError::kInvalidDollarStatement;
      report_build_info();
      return GrblError::kOk;
    case 'N':
      if (!alone) return GrblError::kInvalidDollarStatement;  // startup lines are not stored
      send_text("$N0=");
      send_text("$N1=");
      return GrblError::kOk;
    case 'S': return GrblError::kInvalidDollarStatement;  // `$SLP`: no sleep mode here
    case 'R':
      if (length < 4 || strncmp(text, "RST=", 4) != 0) return GrblError::kInvalidDollarStatement;
      return execute_restore(text + 4, length - 4);
    default: return execute_setting_write(text, length);
  }
}

GrblError GrblProtocol::execute_homing(size_t length) {
  if (!settings_.homing_enabled()) return GrblError::kHomingDisabled;
  if (length != 1) return GrblError::kInvalidDollarStatement;
  const GrblError error = machine_->home();
  if (error == GrblError::kOk) {
    alarm_ = 0;
    homing_reply_pending_ = machine_->homing_in_progress();
  }
  if (error == GrblError::kHomingDisabled) send_text("[MSG:Homing is not set up on this machine]");
  return error;
}

GrblError GrblProtocol::execute_jog(const char* text, size_t length) {
  GcodeBlock block;
  const GrblError syntax = parse_line(text, length, block, parser_options_);
  if (syntax != GrblError::kOk) return syntax;
  constexpr uint32_t kAllowedWords = (1u << word_index('X')) | (1u << word_index('Y')) |
                                     (1u << word_index('Z')) | (1u << word_index('F')) |
                                     (1u << word_index('N'));
  constexpr uint16_t kAllowedGroups = (1u << static_cast<int>(GGroup::kUnits)) |
                                      (1u << static_cast<int>(GGroup::kDistance)) |
                                      (1u << static_cast<int>(GGroup::kNonModal));
  const bool only_g53 = !block.has_g(GGroup::kNonModal) || block.g_code(GGroup::kNonModal) == 530;
  if ((block.words_present & ~kAllowedWords) != 0 || (block.g_groups_present & ~kAllowedGroups) != 0 ||
      block.m_groups_present != 0 || !only_g53 || block.ignored) {
    return GrblError::kInvalidJogCommand;
  }
  if (!block.has_word('F')) return GrblError::kUndefinedFeedRate;
  if ((block.words_present & ~((1u << word_index('F')) | (1u << word_index('N')))) == 0) {
    return GrblError::kInvalidJogCommand;  // no axis word
  }
  // A jog is a G1 at its own feed that leaves the parser's modes as they were.
  block.g[static_cast<int>(GGroup::kMotion)] = 10;
  block.g[static_cast<int>(GGroup::kFeedMode)] = 940;
  block.g_groups_present |= (1u << static_cast<int>(GGroup::kMotion)) | (1u << static_cast<int>(GGroup::kFeedMode));
  sync_position_when_idle();
  GcodeInterpreter trial = interpreter_;
  struct JogCapture final : GcodeSink {
    Motion motion;
    bool has_motion = false;
    void on_motion(const Motion& m) override {
      motion = m;
      has_motion = true;
    }
    void on_dwell(double) override {}
  } capture;
  const GrblError error = trial.execute(block, capture);
  if (error != GrblError::kOk) return error;
  if (!capture.has_motion) return GrblError::kInvalidJogCommand;
  if (!within_travel(capture.motion)) return GrblError::kTravelExceeded;
  machine_->jog(capture.motion);
  return GrblError::kOk;
}

}  // namespace stepdance::gcode
