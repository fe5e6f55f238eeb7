// Registration of the RT1062 blocks that carry motion and inputs: FLEXIO3 (output ports), and
// (as they land) FlexPWM input capture, ENC1/ENC2, XBAR1 and LPI2C1/LPI2C3.
#pragma once

#include <memory>

#include "image/chip/board_io.hpp"
#include "image/chip/chip_context.hpp"
#include "image/chip/peripheral_bus.hpp"
#include "image/rt1062/enc.hpp"
#include "image/rt1062/flexio3.hpp"
#include "image/rt1062/flexpwm.hpp"
#include "image/rt1062/input_capture.hpp"
#include "image/rt1062/lpi2c.hpp"
#include "image/rt1062/teensy_model.hpp"
#include "image/rt1062/xbar1.hpp"

namespace stepdance::sim::image {

/// Owns the motion blocks of one chip. The bus refers to them, so this must outlive the bus's use.
class MotionBlocks {
 public:
  MotionBlocks(const PeripheralBus& bus, ChipContext& chip, BoardIo& io, TeensyModel model);
  Flexio3& flexio3() { return flexio3_; }
  /// PWM1..PWM4 by index 0..3.
  FlexPwm& flexpwm(unsigned index) { return pwm_[index]; }
  /// Where the lead delivers input-port pulses (InputCapture::pulse_arrived).
  InputCapture& capture() { return capture_; }
  const InputCapture& capture() const { return capture_; }
  Xbar1& xbar1() { return xbar1_; }
  /// ENC1, ENC2 by index 0, 1.
  Enc& enc(unsigned index) { return enc_[index]; }
  /// LPI2C1 (QWIIC0, index 0) and LPI2C3 (QWIIC1, index 1).
  Lpi2c& lpi2c(unsigned index) { return lpi2c_[index]; }

 private:
  Flexio3 flexio3_;
  FlexPwm pwm_[4];
  InputCapture capture_;
  Xbar1 xbar1_;
  Enc enc_[2];
  Lpi2c lpi2c_[2];
};

/// Creates the motion blocks (FLEXIO3, PWM1..4, XBARA1, ENC1/2, LPI2C1/3) and adds them to `bus`.
/// Returns their owner, whose capture() takes the input ports' pulses; null, with nothing added,
/// if a block's window overlaps one already on the bus.
/// Context: board construction, before the image runs.
std::unique_ptr<MotionBlocks> add_motion_blocks(PeripheralBus& bus, ChipContext& chip, BoardIo& io, TeensyModel model);

}  // namespace stepdance::sim::image
