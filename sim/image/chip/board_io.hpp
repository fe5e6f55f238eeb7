// What the chip's pins, ports and serial reach in the rest of the simulation: the world side of
// a board, in Teensy pin numbers. SimBoard implements it for image boards; tests fake it.
#pragma once

#include <cstddef>
#include <cstdint>

#include "board/host/wire.hpp"
#include "common/sim_time.hpp"
#include "stepdance/protocol/signals.hpp"

namespace stepdance::sim::image {

/// Pin configurations (the same values as StepdancePinMode in board/abi/board_abi.h).
enum class PinConfig : uint8_t { kInput = 0, kInputPullup = 1, kInputPulldown = 2, kOutput = 3 };

/// The world as the RT1062's pads see it. Every call carries the simulated time it happens at.
class BoardIo {
 public:
  virtual ~BoardIo() = default;

  // ---- digital pins (Teensy pin numbers 0..54) ----
  virtual void pin_config(SimTime now_ns, uint8_t pin, PinConfig config) = 0;
  virtual void pin_drive(SimTime now_ns, uint8_t pin, bool high) = 0;
  /// The level on the pin now: what an outside device drives, or the pull, or the pin's own drive.
  virtual bool pin_level(SimTime now_ns, uint8_t pin) = 0;

  // ---- the motion-stream ports (0..3 = A..D) ----
  /// An output port's STEP/DIR words begin playing at `start_ns` (bit n = level during
  /// [start + n µs, start + (n+1) µs)); the next frame starts `frame_ns` later.
  virtual void port_frame(uint8_t port, SimTime start_ns, const protocol::FrameWords& words, SimTime frame_ns) = 0;

  // ---- knobs and pots ----
  /// Quadrature counts of the encoder on ENC `index` (0 = ENC1) now, as its A/B edges count.
  virtual int64_t encoder_counts(SimTime now_ns, uint8_t index) = 0;
  /// The analog level on `pin` now, 0..1023 of the 3.3 V reference.
  virtual uint16_t analog_level(SimTime now_ns, uint8_t pin) = 0;

  // ---- QWIIC I2C (bus 0 = QWIIC0 on LPI2C1, 1 = QWIIC1 on LPI2C3) ----
  /// One whole transfer: write, then (read_length > 0) a repeated start and read. Returns the
  /// stepdance::hal::I2cResult value (2 ok, 3 address NACK, …) and the wire time at `clock_hz`.
  virtual int i2c_transfer(SimTime now_ns, uint8_t bus, uint32_t clock_hz, uint8_t address, const uint8_t* write,
                           size_t write_length, uint8_t* read, size_t read_length, SimTime& wire_ns) = 0;

  // ---- the USB serial's bytes ----
  /// The host has sent these bytes and the device took them; returns how many were taken.
  virtual size_t serial_from_device(SimTime now_ns, const uint8_t* data, size_t length) = 0;
  /// Bytes the host has for the device: copies up to `capacity`, returns how many.
  virtual size_t serial_to_device(SimTime now_ns, uint8_t* data, size_t capacity) = 0;
};

}  // namespace stepdance::sim::image
