// The EBB's processor pins as PD, PO and PI see them: the driver and pen pins, the rest latched.
#pragma once

#include <stdint.h>

namespace stepdance::ebb {

/// What the emulated board drives on its own pins, as the frame last published it.
struct EbbDriverState {
  bool motor_enabled[2] = {};  ///< EM (or motion) enabled the driver
  uint8_t microstep_mode = 1;  ///< 1 = 1/16 … 5 = full step (EM's Enable1)
  bool pen_up = true;          ///< the pen as executed
};

/// Ports A to E of an EBB v1.3+ (PIC18F46J50), eight pins each. PI reads the pins the EBB drives
/// itself from the emulated state, as the real board's pins read:
///   RE0 motor 1 enable, RC1 motor 2 enable (0 = enabled, the drivers' enable is active low);
///   RE2 MS1, RE1 MS2, RA6 MS3 (1/16: 1 1 1, 1/8: 1 1 0, 1/4: 0 1 0, 1/2: 1 0 0, full: 0 0 0);
///   RB4 the pen-lift solenoid output (1 while the pen is down); RB1 the pen servo's pulse
///   output, low between its 0.5–2.5 ms pulses, so it reads 0.
/// Every other pin reads what PO last wrote if PD made it an output, else 0 (nothing attached).
/// Context: loop.
class EbbPins {
 public:
  static constexpr int kPorts = 5;
  static constexpr int kPinsPerPort = 8;

  /// The port's index for a letter 'A' … 'E' (upper case), or −1.
  static int port_index(char letter) { return letter >= 'A' && letter <= 'E' ? letter - 'A' : -1; }
  /// PD: direction 1 = input, 0 = output. Precondition: port < kPorts, pin < kPinsPerPort.
  void set_direction(int port, int pin, bool input);
  /// PO: the pin's output latch (takes effect on the pin once it is an output).
  void set_output(int port, int pin, bool high);
  /// PI: the pin's level, 0 or 1.
  uint8_t read(int port, int pin, const EbbDriverState& driver) const;
  /// Power-on: every pin an input, every latch low.
  void reset() { *this = EbbPins{}; }

 private:
  bool driver_pin(int port, int pin, const EbbDriverState& driver, uint8_t& level) const;

  uint8_t latch_[kPorts] = {};
  uint8_t input_[kPorts] = {0xFF, 0xFF, 0xFF, 0xFF, 0xFF};
};

}  // namespace stepdance::ebb
