// The cable between the emulated USB host and the device controller: tokens one way, handshakes back.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace stepdance::sim::image::usb {

/// How the device answered a transaction (USB 2.0 §8.4.5 handshake packets; kNoResponse is a
/// timeout: wrong address, endpoint not enabled).
enum class Handshake : uint8_t { kAck, kNak, kStall, kNoResponse };

/// The bus speed the reset handshake settled on (USB 2.0 §7.1.7.5 chirp: high speed unless the
/// device forces full speed).
enum class BusSpeed : uint8_t { kFull, kHigh };

const char* handshake_name(Handshake handshake);

/// What the host reaches across the cable: a device controller in device mode. Every call runs
/// on the simulator's thread at the ChipContext's current time, between CPU runs.
class UsbDevicePort {
 public:
  virtual ~UsbDevicePort() = default;
  /// True while the device presents its pull-up (USBCMD.RS in device mode, PHY powered).
  virtual bool attached() const = 0;
  /// Why the device is not attached, in a few words ("USBCMD.RS is 0", …); "" when attached.
  virtual std::string detached_reason() const = 0;
  /// The host starts driving bus reset (SE0).
  virtual void bus_reset_begin() = 0;
  /// The host ends bus reset; returns the speed the chirp handshake settled on.
  virtual BusSpeed bus_reset_end() = 0;
  /// A SETUP transaction to endpoint 0 of device `address`: the 8-byte request.
  virtual Handshake setup(uint8_t address, const uint8_t request[8]) = 0;
  /// An OUT transaction (one data packet of `length` bytes, ≤ the endpoint's max packet size).
  virtual Handshake out(uint8_t address, uint8_t endpoint, const uint8_t* data, size_t length) = 0;
  /// An IN transaction: on kAck, `length` bytes (≤ `capacity`) of one data packet are in `data`.
  virtual Handshake in(uint8_t address, uint8_t endpoint, uint8_t* data, size_t capacity, size_t& length) = 0;
};

}  // namespace stepdance::sim::image::usb
