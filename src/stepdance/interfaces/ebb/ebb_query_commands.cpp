// EBB settings and queries: answered at once from the loop, from what the frame published.
#include <string.h>

#include "stepdance/interfaces/ebb/ebb_commands.hpp"

namespace stepdance::ebb {

namespace {

constexpr int64_t kUint32Max = 4294967295LL;
constexpr char kHex[] = "0123456789ABCDEF";

}  // namespace

// SC,Parameter,Value (ebb-protocol.md): 4 pen-up servo position, 5 pen-down, 10 both slew rates, 11
// up rate, 12 down rate. The others configure hardware we do not have; they are accepted with OK so
// clients that send them at start-up carry on.
bool EbbCommands::command_sc(EbbParameters& p) {
  int64_t parameter = 0, value = 0;
  p.integer(0, 255, true, parameter);
  p.integer(0, 65535, true, value);
  if (!p.finish()) return replies_.parameter_error(p), true;
  // The pen's parameters go to the pen; solenoid, driver routing, S2 channels, alternate button:
  // nothing to do here.
  pen_.configure(parameter, static_cast<uint16_t>(value));
  replies_.ok();
  return true;
}

// CU,Parameter,Value: 1 acks (OK lines) on/off, 4 FIFO depth (clamped to ours), 10 the future reply
// syntax, 54 checksums (only "off" is supported, so "on" is refused rather than silently ignored).
bool EbbCommands::command_cu(EbbParameters& p) {
  int64_t parameter = 0, value = 0;
  p.integer(0, 255, true, parameter);
  p.integer(-32768, 32767, true, value);
  if (!p.finish()) return replies_.parameter_error(p), true;
  const bool boolean = value == 0 || value == 1;
  switch (parameter) {
    case 1:
      if (!boolean) return replies_.error(EbbError::kInvalid), true;
      replies_.set_acks(value == 1);
      break;
    case 4:
      if (value < 1) return replies_.error(EbbError::kInvalid), true;
      queue_.set_depth(static_cast<uint32_t>(value > int64_t{EbbMotionQueue::kCapacity} ? EbbMotionQueue::kCapacity
                                                                                        : value));  // clamped to ours
      break;
    case 10:
      if (!boolean) return replies_.error(EbbError::kInvalid), true;
      if (replies_.switch_syntax(value == 1)) return true;
      break;
    case 54:
      if (value != 0) return replies_.error(EbbError::kInvalid), true;  // no checksums here
      break;
    default: break;  // limit checks, LED, motor auto-enable, limit switches, thresholds: accepted
  }
  replies_.ok();
  return true;
}

// QU,2 FIFO capacity, QU,3 configured depth, QU,6 moves waiting (at least two digits).
bool EbbCommands::command_qu(EbbParameters& p) {
  int64_t parameter = 0;
  p.integer(0, 255, true, parameter);
  if (!p.finish()) return replies_.parameter_error(p), true;
  char data[32];
  TextWriter text(data, sizeof(data));
  text.text("QU,");
  switch (parameter) {
    case 2: text.unsigned_number(EbbMotionQueue::kCapacity); break;
    case 3: text.unsigned_number(queue_.depth()); break;
    case 6: {
      const uint32_t waiting = queue_.waiting();
      if (waiting < 10) text.character('0');
      text.unsigned_number(waiting);
      break;
    }
    default: text.character('0'); break;
  }
  replies_.send(data);
  if (replies_.future_syntax()) {
    replies_.send("\n");
  } else {
    replies_.send(replies_.acks() ? "\r\nOK\r\n" : "\r\n\r\n");
  }
  return true;
}

// ES[,DisableMotors]: abort the current move and flush the FIFO (ebb-protocol.md). The reply says
// whether anything was interrupted, judged from the loop's view (the frame applies the stop next
// frame); it ends "\n\r" like the EBB's legacy query lines.
bool EbbCommands::command_es(EbbParameters& p) {
  int64_t disable = 0;
  p.integer(0, 1, false, disable);
  if (!p.finish()) return replies_.parameter_error(p), true;
  const bool interrupted = queue_.executing();
  queue_.control(disable == 1 ? EbbControl::kStopDisable : EbbControl::kStop);
  if (disable == 1) motors_enabled_[0] = motors_enabled_[1] = false;
  replies_.data(interrupted ? "1" : "0", true, "\n\r");
  return true;
}

// Clients switch command sets on this version number (ebb-protocol.md "Settings and queries"): at
// 2.5.3 saxi uses LM, at 2.6.0 SR. The sketch may choose the string (set_version_string()).
bool EbbCommands::command_v(EbbParameters&) {
  replies_.data(version_, false);
  return true;
}

// QM,CommandExecuting,Motor1Moving,Motor2Moving,FIFOStatus: clients poll it to wait for idle, so
// "executing" includes moves still waiting in the FIFO. The legacy line ends "\n\r" and has no OK,
// exactly as the EBB prints it (ebb-protocol.md).
bool EbbCommands::command_qm(EbbParameters&) {
  const bool fifo = queue_.waiting() != 0;
  char data[24];
  TextWriter text(data, sizeof(data));
  text.character(queue_.busy() || fifo ? '1' : '0').character(',');
  text.character(queue_.motor_moving(0) ? '1' : '0').character(',');
  text.character(queue_.motor_moving(1) ? '1' : '0').character(',');
  text.character(fifo ? '1' : '0');
  if (replies_.future_syntax()) {
    replies_.data(data, false);
  } else {
    replies_.send("QM,");
    replies_.send(data);
    replies_.send("\n\r");
  }
  return true;
}

// QG status byte in hex (ebb-protocol.md): b5 PRG button, b4 pen up, b3 command executing, b2/b1
// motor 1/2 moving, b0 FIFO not empty; b7 limit switch and b6 power lost are never set here. Reading
// it clears the button flag, like QB.
bool EbbCommands::command_qg(EbbParameters&) {
  const bool fifo = queue_.waiting() != 0;
  uint8_t status = 0;
  if (button_pressed_) status |= 0x20;
  if (queue_.pen_up()) status |= 0x10;
  if (queue_.busy() || fifo) status |= 0x08;
  if (queue_.motor_moving(0)) status |= 0x04;
  if (queue_.motor_moving(1)) status |= 0x02;
  if (fifo) status |= 0x01;
  button_pressed_ = false;
  const char data[3] = {kHex[status >> 4], kHex[status & 0x0F], '\0'};
  replies_.data(data, false);
  return true;
}

// SR,Timeout[,State]: the servo power-off timeout is stored but not acted on: the pen "servo" here is
// an output port's Z position, which has no servo power to switch off.
bool EbbCommands::command_sr(EbbParameters& p) {
  int64_t timeout = 0, state = 0;
  p.integer(0, kUint32Max, true, timeout);
  p.integer(0, 1, false, state);
  if (!p.finish()) return replies_.parameter_error(p), true;
  servo_timeout_ms_ = static_cast<uint32_t>(timeout);
  replies_.ok();
  return true;
}

// SL,Value[,Index] / QL[,Index]: 32 bytes of user variables (the AxiDraw software keeps state there).
bool EbbCommands::command_sl(EbbParameters& p) {
  int64_t value = 0, index = 0;
  p.integer(0, 255, true, value);
  p.integer(0, 31, false, index);
  if (!p.finish()) return replies_.parameter_error(p), true;
  variables_[index] = static_cast<uint8_t>(value);
  replies_.ok();
  return true;
}

bool EbbCommands::command_ql(EbbParameters& p) {
  int64_t index = 0;
  p.integer(0, 31, false, index);
  if (!p.finish()) return replies_.parameter_error(p), true;
  char data[8];
  TextWriter text(data, sizeof(data));
  text.unsigned_number(variables_[index]);
  replies_.data(text.c_str(), true);
  return true;
}

bool EbbCommands::command_st(EbbParameters& p) {
  char tag[sizeof(tag_)] = {};
  p.text(tag, sizeof(tag), false);
  if (!p.finish()) return replies_.parameter_error(p), true;
  memcpy(tag_, tag, sizeof(tag_));
  replies_.ok();
  return true;
}

bool EbbCommands::command_qt(EbbParameters&) {
  replies_.data(tag_, true);
  return true;
}

// QS: the global signed 32-bit step counters as the frame last published them.
bool EbbCommands::command_qs(EbbParameters&) {
  char data[32];
  TextWriter text(data, sizeof(data));
  text.signed_number(queue_.global_steps(0)).character(',').signed_number(queue_.global_steps(1));
  replies_.data(text.c_str(), true, "\n\r");
  return true;
}

// CS goes through the control queue so the counters are cleared between two ticks, never during one.
bool EbbCommands::command_cs(EbbParameters&) {
  queue_.control(EbbControl::kClearSteps);
  replies_.ok();
  return true;
}

// The pen as executed: a pen command still waiting in the FIFO does not show yet.
bool EbbCommands::command_qp(EbbParameters&) {
  replies_.data(queue_.pen_up() ? "1" : "0", true, "\n\r");
  return true;
}

bool EbbCommands::command_qb(EbbParameters&) {
  replies_.data(button_pressed_ ? "1" : "0", true);
  button_pressed_ = false;
  return true;
}

// A 1.27 V current reference and a 12 V supply (clients check the supply is there).
bool EbbCommands::command_qc(EbbParameters&) {
  replies_.data("0394,0394", true);
  return true;
}

// The drivers as the frame has set them (EM runs from the FIFO; motion enables them too).
bool EbbCommands::command_qe(EbbParameters&) {
  char data[16];
  TextWriter text(data, sizeof(data));
  text.unsigned_number(queue_.motor_resolution(0)).character(',').unsigned_number(queue_.motor_resolution(1));
  replies_.data(text.c_str(), true);
  return true;
}

bool EbbCommands::command_qr(EbbParameters&) {
  replies_.data("1", true, "\n\r");
  return true;
}

// R: back to the power-on state (legacy syntax, acks on, FIFO depth 1, pen up, motors off). The OK is
// sent first, in the syntax in force when R arrived.
bool EbbCommands::command_r(EbbParameters&) {
  replies_.ok();
  queue_.reset(pen_.up_position());
  replies_.reset();
  pen_.reset();
  motors_enabled_[0] = motors_enabled_[1] = false;
  pins_.reset();
  return true;
}

}  // namespace stepdance::ebb
