// EBB pen: servo settings and the servo moves of SP, TP and S2 (ebb-protocol.md).
#include "stepdance/interfaces/ebb/ebb_pen.hpp"

namespace stepdance::ebb {

namespace {
constexpr uint32_t kTicksPerMs = kTicksPerSecond / 1000;
constexpr double kNeutralSteps = 1500.0;   // servo-board steps (µs) at the neutral 1.5 ms
constexpr double kTwelfthsPerStep = 12.0;  // 1/12 µs per servo-board step
}  // namespace

// SC,4/5 set the positions, SC,10 both rates, SC,11/12 one each (ebb-protocol.md "SC").
bool EbbPen::configure(int64_t parameter, uint16_t value) {
  switch (parameter) {
    case 4: up_ = value; return true;
    case 5: down_ = value; return true;
    case 10: rate_up_ = rate_down_ = value; return true;
    case 11: rate_up_ = value; return true;
    case 12: rate_down_ = value; return true;
    default: return false;
  }
}

// Pen up goes to the SC,4 position at the SC,11 rate, down to SC,5 at SC,12; the delay holds the FIFO
// so the next move waits for the pen.
EbbMove EbbPen::move(bool up, uint32_t delay_ms) const {
  EbbMove servo;
  servo.kind = EbbMove::Kind::kServo;
  servo.servo_target = up ? up_ : down_;
  servo.servo_rate = up ? rate_up_ : rate_down_;
  servo.pen_up = up;
  servo.ticks = delay_ms * kTicksPerMs;
  return servo;
}

// Up is the side of the pen-up position (SC,4) away from the pen-down one (SC,5): the positions may
// be either way round on a given lift.
EbbMove EbbPen::position_move(uint16_t position, uint16_t rate, uint32_t delay_ms) const {
  EbbMove servo;
  servo.kind = EbbMove::Kind::kServo;
  servo.servo_target = position;
  servo.servo_rate = rate;
  const int32_t middle = (int32_t{up_} + down_) / 2;
  servo.pen_up = up_ >= down_ ? position > middle : position < middle;
  servo.ticks = delay_ms * kTicksPerMs;
  return servo;
}

void EbbPen::lift_now(bool down_becomes_up) {
  if (down_becomes_up) down_ = up_;
  commanded_up_ = true;
}

double EbbPen::steps_from_neutral(double position_twelfths_us) {
  return position_twelfths_us / kTwelfthsPerStep - kNeutralSteps;
}

}  // namespace stepdance::ebb
