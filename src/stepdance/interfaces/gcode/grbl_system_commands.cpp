// The Grbl link's `$` commands: reports, unlock, homing, check mode and jogging (settings: grbl_setting_commands.cpp).
#include <string.h>

#include "stepdance/interfaces/gcode/grbl_protocol.hpp"

namespace stepdance::gcode {
namespace {

bool equals(const char* text, size_t length, const char* expected) {
  return strlen(expected) == length && strncmp(text, expected, length) == 0;
}

char upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }

}  // namespace

GrblError GrblProtocol::execute_system(const char* text, size_t length) {
  char command[8] = {};
  for (size_t i = 0; i < length && i < sizeof(command) - 1; ++i) command[i] = upper(text[i]);
  const bool idle = machine_->motion_state() == MotionState::kIdle;
  if (length == 0) {
    send_text("[HLP:$$ $# $G $I $N $x=val $Nx=line $J=line $SLP $C $X $H ~ ! ? ctrl-x]");
  } else if (equals(command, length, "$")) {
    report_settings();
  } else if (equals(command, length, "#")) {
    report_parameters();
  } else if (equals(command, length, "G")) {
    report_parser_state();
  } else if (equals(command, length, "I")) {
    report_build_info();
  } else if (equals(command, length, "N")) {
    send_text("$N0=");  // startup lines are not stored: nothing runs at reset
    send_text("$N1=");
  } else if (equals(command, length, "X")) {
    if (alarm_ != 0) send_text("[MSG:Caution: Unlocked]");
    alarm_ = 0;
  } else if (equals(command, length, "H")) {
    if (!idle) return GrblError::kNotIdle;
    const GrblError error = machine_->home();
    if (error == GrblError::kOk) {
      alarm_ = 0;
      homing_reply_pending_ = machine_->homing_in_progress();
    }
    if (error == GrblError::kHomingDisabled) send_text("[MSG:Homing is not set up on this machine]");
    return error;
  } else if (equals(command, length, "C")) {
    if (!idle) return GrblError::kNotIdle;
    check_mode_ = !check_mode_;
    send_text(check_mode_ ? "[MSG:Enabled]" : "[MSG:Disabled]");
    if (!check_mode_) reset_requested_ = true;  // as Grbl: leaving check mode resets the parser
  } else if (length > 4 && strncmp(command, "RST=", 4) == 0) {
    if (!idle) return GrblError::kNotIdle;
    return execute_restore(text + 4, length - 4);
  } else if (length > 2 && upper(text[0]) == 'J' && text[1] == '=') {
    return execute_jog(text + 2, length - 2);
  } else if (length > 1 && text[0] >= '0' && text[0] <= '9') {
    if (!idle) return GrblError::kNotIdle;
    return execute_setting_write(text, length);
  } else {
    return GrblError::kInvalidDollarStatement;
  }
  return GrblError::kOk;
}

GrblError GrblProtocol::execute_jog(const char* text, size_t length) {
  if (alarm_ != 0) return GrblError::kLocked;
  const MotionState state = machine_->motion_state();
  if (state != MotionState::kIdle && state != MotionState::kJog) return GrblError::kNotIdle;
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
