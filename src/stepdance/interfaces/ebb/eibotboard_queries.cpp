// Eibotboard settings and queries: answered at once from the loop, from what the frame published.
#include <string.h>

#include "stepdance/interfaces/ebb/eibotboard.hpp"

namespace stepdance {

using ebb::EbbError;
using ebb::EbbParameters;

namespace {

constexpr int64_t kUint32Max = 4294967295LL;
constexpr char kHex[] = "0123456789ABCDEF";

}  // namespace

// SC,Parameter,Value (ebb-protocol.md): 4 pen-up servo position, 5 pen-down, 10 both slew rates, 11
// up rate, 12 down rate. The others configure hardware we do not have; they are accepted with OK so
// clients that send them at start-up carry on.
bool Eibotboard::command_sc(EbbParameters& p) {
  int64_t parameter = 0, value = 0;
  p.integer(0, 255, true, parameter);
  p.integer(0, 65535, true, value);
  if (!p.finish()) return reply_parameter_error(p), true;
  switch (parameter) {
    case 4: servo_up_ = static_cast<uint16_t>(value); break;
    case 5: servo_down_ = static_cast<uint16_t>(value); break;
    case 10: servo_rate_up_ = servo_rate_down_ = static_cast<uint16_t>(value); break;
    case 11: servo_rate_up_ = static_cast<uint16_t>(value); break;
    case 12: servo_rate_down_ = static_cast<uint16_t>(value); break;
    default: break;  // solenoid, driver routing, S2 channels, alternate button: nothing to do here
  }
  reply_ok();
  return true;
}

// CU,Parameter,Value: 1 acks (OK lines) on/off, 4 FIFO depth (clamped to ours), 10 the future reply
// syntax, 54 checksums (only "off" is supported, so "on" is refused rather than silently ignored).
bool Eibotboard::command_cu(EbbParameters& p) {
  int64_t parameter = 0, value = 0;
  p.integer(0, 255, true, parameter);
  p.integer(-32768, 32767, true, value);
  if (!p.finish()) return reply_parameter_error(p), true;
  const bool boolean = value == 0 || value == 1;
  switch (parameter) {
    case 1:
      if (!boolean) return reply_error(EbbError::kInvalid, command_name_), true;
      ack_enabled_ = value == 1;
      break;
    case 4:
      if (value < 1) return reply_error(EbbError::kInvalid, command_name_), true;
      fifo_depth_ = static_cast<uint32_t>(value > static_cast<int64_t>(kFifoCapacity) ? kFifoCapacity : value);
      break;
    case 10:
      if (!boolean) return reply_error(EbbError::kInvalid, command_name_), true;
      if (switch_syntax(value)) return true;
      break;
    case 54:
      if (value != 0) return reply_error(EbbError::kInvalid, command_name_), true;  // no checksums here
      break;
    default:
      break;  // limit checks, LED, motor auto-enable, limit switches, thresholds: accepted
  }
  reply_ok();
  return true;
}

// CU,10: the reply is made half before and half after the switch, as on the EBB. True when the
// syntax changed (and the reply is sent); false when it stays (an ordinary reply follows).
bool Eibotboard::switch_syntax(int64_t value) {
  if (!future_syntax_ && value == 1) {
    future_syntax_ = true;
    send("\n");
    return true;
  }
  if (future_syntax_ && value == 0) {
    future_syntax_ = false;
    send("CU");  // the future half; the legacy ending follows (its OK only while acks are on)
    send(ack_enabled_ ? "OK\r\n" : "\r\n");
    return true;
  }
  return false;
}

// QU,2 FIFO capacity, QU,3 configured depth, QU,6 moves waiting (at least two digits).
bool Eibotboard::command_qu(EbbParameters& p) {
  int64_t parameter = 0;
  p.integer(0, 255, true, parameter);
  if (!p.finish()) return reply_parameter_error(p), true;
  char data[32];
  TextWriter text(data, sizeof(data));
  text.text("QU,");
  switch (parameter) {
    case 2: text.unsigned_number(kFifoCapacity); break;
    case 3: text.unsigned_number(fifo_depth_); break;
    case 6: {
      const uint32_t waiting = moves_queued_ - moves_started_;
      if (waiting < 10) text.character('0');
      text.unsigned_number(waiting);
      break;
    }
    default: text.character('0'); break;
  }
  send(data);
  if (future_syntax_) {
    send("\n");
  } else {
    send(ack_enabled_ ? "\r\nOK\r\n" : "\r\n\r\n");
  }
  return true;
}

// ES[,DisableMotors]: abort the current move and flush the FIFO (ebb-protocol.md). The reply says
// whether anything was interrupted, judged from the loop's view (the frame applies the stop next
// frame); it ends "\n\r" like the EBB's legacy query lines.
bool Eibotboard::command_es(EbbParameters& p) {
  int64_t disable = 0;
  p.integer(0, 1, false, disable);
  if (!p.finish()) return reply_parameter_error(p), true;
  const bool interrupted = frame_busy_ || moves_queued_ != moves_started_;
  controls_.push(disable == 1 ? Control::kStopDisable : Control::kStop);
  if (disable == 1) motors_enabled_[0] = motors_enabled_[1] = false;
  reply_data(interrupted ? "1" : "0", true, "\n\r");
  return true;
}

// Clients switch command sets on this version number (ebb-protocol.md "Settings and queries"): at
// 2.5.3 saxi uses LM, at 2.6.0 SR. The sketch may choose the string (set_version_string()).
bool Eibotboard::command_v(EbbParameters&) {
  reply_data(version_, false);
  return true;
}

// QM,CommandExecuting,Motor1Moving,Motor2Moving,FIFOStatus: clients poll it to wait for idle, so
// "executing" includes moves still waiting in the FIFO. The legacy line ends "\n\r" and has no OK,
// exactly as the EBB prints it (ebb-protocol.md).
bool Eibotboard::command_qm(EbbParameters&) {
  const bool fifo = moves_queued_ != moves_started_;
  char data[24];
  TextWriter text(data, sizeof(data));
  text.character(frame_busy_ || fifo ? '1' : '0').character(',');
  text.character(frame_motor_moving_[0] ? '1' : '0').character(',');
  text.character(frame_motor_moving_[1] ? '1' : '0').character(',');
  text.character(fifo ? '1' : '0');
  if (future_syntax_) {
    reply_data(data, false);
  } else {
    send("QM,");
    send(data);
    send("\n\r");
  }
  return true;
}

// QG status byte in hex (ebb-protocol.md): b5 PRG button, b4 pen up, b3 command executing, b2/b1
// motor 1/2 moving, b0 FIFO not empty; b7 limit switch and b6 power lost are never set here. Reading
// it clears the button flag, like QB.
bool Eibotboard::command_qg(EbbParameters&) {
  const bool fifo = moves_queued_ != moves_started_;
  uint8_t status = 0;
  if (button_pressed_) status |= 0x20;
  if (frame_pen_up_) status |= 0x10;
  if (frame_busy_ || fifo) status |= 0x08;
  if (frame_motor_moving_[0]) status |= 0x04;
  if (frame_motor_moving_[1]) status |= 0x02;
  if (fifo) status |= 0x01;
  button_pressed_ = false;
  const char data[3] = {kHex[status >> 4], kHex[status & 0x0F], '\0'};
  reply_data(data, false);
  return true;
}

// SR,Timeout[,State]: the servo power-off timeout is stored but not acted on: the pen "servo" here is
// an output port's Z position, which has no servo power to switch off.
bool Eibotboard::command_sr(EbbParameters& p) {
  int64_t timeout = 0, state = 0;
  p.integer(0, kUint32Max, true, timeout);
  p.integer(0, 1, false, state);
  if (!p.finish()) return reply_parameter_error(p), true;
  servo_timeout_ms_ = static_cast<uint32_t>(timeout);
  reply_ok();
  return true;
}

// SL,Value[,Index] / QL[,Index]: 32 bytes of user variables (the AxiDraw software keeps state there).
bool Eibotboard::command_sl(EbbParameters& p) {
  int64_t value = 0, index = 0;
  p.integer(0, 255, true, value);
  p.integer(0, 31, false, index);
  if (!p.finish()) return reply_parameter_error(p), true;
  variables_[index] = static_cast<uint8_t>(value);
  reply_ok();
  return true;
}

bool Eibotboard::command_ql(EbbParameters& p) {
  int64_t index = 0;
  p.integer(0, 31, false, index);
  if (!p.finish()) return reply_parameter_error(p), true;
  char data[8];
  TextWriter text(data, sizeof(data));
  text.unsigned_number(variables_[index]);
  reply_data(text.c_str(), true);
  return true;
}

bool Eibotboard::command_st(EbbParameters& p) {
  char tag[sizeof(tag_)] = {};
  p.text(tag, sizeof(tag), false);
  if (!p.finish()) return reply_parameter_error(p), true;
  memcpy(tag_, tag, sizeof(tag_));
  reply_ok();
  return true;
}

bool Eibotboard::command_qt(EbbParameters&) {
  reply_data(tag_, true);
  return true;
}

// QS: the global signed 32-bit step counters as the frame last published them.
bool Eibotboard::command_qs(EbbParameters&) {
  char data[32];
  TextWriter text(data, sizeof(data));
  text.signed_number(frame_global_steps_[0]).character(',').signed_number(frame_global_steps_[1]);
  reply_data(text.c_str(), true, "\n\r");
  return true;
}

// CS goes through the control queue so the counters are cleared between two ticks, never during one.
bool Eibotboard::command_cs(EbbParameters&) {
  controls_.push(Control::kClearSteps);
  reply_ok();
  return true;
}

// The pen as executed: a pen command still waiting in the FIFO does not show yet.
bool Eibotboard::command_qp(EbbParameters&) {
  reply_data(frame_pen_up_ ? "1" : "0", true, "\n\r");
  return true;
}

bool Eibotboard::command_qb(EbbParameters&) {
  reply_data(button_pressed_ ? "1" : "0", true);
  button_pressed_ = false;
  return true;
}

// A 1.27 V current reference and a 12 V supply (clients check the supply is there).
bool Eibotboard::command_qc(EbbParameters&) {
  reply_data("0394,0394", true);
  return true;
}

// The drivers as the frame has set them (EM runs from the FIFO; motion enables them too).
bool Eibotboard::command_qe(EbbParameters&) {
  char data[16];
  TextWriter text(data, sizeof(data));
  text.unsigned_number(frame_motor_resolution_[0]).character(',').unsigned_number(frame_motor_resolution_[1]);
  reply_data(text.c_str(), true);
  return true;
}

bool Eibotboard::command_qr(EbbParameters&) {
  reply_data("1", true, "\n\r");
  return true;
}

// R: back to the power-on state (legacy syntax, acks on, FIFO depth 1, pen up, motors off). The OK is
// sent first, in the syntax in force when R arrived.
bool Eibotboard::command_r(EbbParameters&) {
  reply_ok();
  controls_.push(Control::kReset);
  future_syntax_ = false;
  ack_enabled_ = true;
  fifo_depth_ = 1;
  pen_commanded_up_ = true;
  motors_enabled_[0] = motors_enabled_[1] = false;
  pins_.reset();
  return true;
}

}  // namespace stepdance
