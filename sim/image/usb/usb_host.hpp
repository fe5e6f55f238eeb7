// An emulated USB host: it enumerates the device as a PC does and then carries the serial bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <string>
#include <vector>

#include "common/sim_time.hpp"
#include "image/chip/board_io.hpp"
#include "image/chip/chip_context.hpp"
#include "image/usb/usb_bus.hpp"
#include "image/usb/usb_descriptors.hpp"
#include "kernel/scheduler/event.hpp"

namespace stepdance::sim::image::usb {

/// What the host saw of the device.
struct HostRecord {
  BusSpeed speed = BusSpeed::kFull;
  uint8_t address = 0;
  std::vector<uint8_t> device_bytes;         ///< the 18-byte device descriptor as sent
  std::vector<uint8_t> configuration_bytes;  ///< the whole configuration as sent
  DeviceDescriptor device;
  CdcFunction cdc;
  std::string manufacturer, product, serial_number;
  SimTime attached_ns = -1;    ///< when the pull-up appeared
  SimTime configured_ns = -1;  ///< when SET_CONTROL_LINE_STATE (DTR on) completed
};

/// One control transfer in flight (USB 2.0 §8.5.3: setup, optional data, status).
struct ControlTransfer {
  enum class Stage : uint8_t { kSetup, kData, kStatus, kDone };
  std::string name;  ///< for reports, e.g. "GET_DESCRIPTOR(configuration)"
  uint8_t request[8] = {};
  std::vector<uint8_t> data;  ///< OUT: the bytes to send; IN: the bytes received
  size_t out_sent = 0;
  bool tolerate_stall = false;  ///< optional requests (strings): a STALL is an empty answer
  bool stalled = false;
  Stage stage = Stage::kSetup;
  SimTime deadline_ns = 0;  ///< USB 2.0 §9.2.6.4 limits: 500 ms for data, 50 ms for status
};

/// The host's timing and what it sends. Times are simulated ns.
struct HostOptions {
  SimTime attach_debounce_ns = 100 * kMillisecond;     ///< USB 2.0 §7.1.7.3 TATTDB
  SimTime reset_ns = 10 * kMillisecond;                ///< §7.1.7.5 TDRST (root port minimum)
  SimTime reset_recovery_ns = 10 * kMillisecond;       ///< §7.1.7.5 TRSTRCY
  SimTime set_address_recovery_ns = 2 * kMillisecond;  ///< §9.2.6.3
  uint8_t address = 1;
  uint32_t baud = 115200;          ///< SET_LINE_CODING dwDTERate; 8 data bits, 1 stop bit, no parity
  size_t out_buffer_bytes = 4096;  ///< bytes the host takes from the world before the device accepts them
};

/// Drives a UsbDevicePort from events on the chip's scheduler. High speed frames activity at
/// 125 µs microframes, full speed at 1 ms frames (USB 2.0 §8.4.3.1); the host works at the start
/// of each (micro)frame while anything moves, and when all is quiet only once per 1 ms frame,
/// unless the device primes an endpoint (wake()). Per (micro)frame it runs at most 13 (high
/// speed) or 19 (full speed) transactions: the bulk maximums of USB 2.0 tables 5-10 and 5-9.
/// Simulator thread only.
class UsbHost {
 public:
  UsbHost(ChipContext& chip, BoardIo& world, UsbDevicePort& device, HostOptions options = {});
  ~UsbHost();
  UsbHost(const UsbHost&) = delete;
  UsbHost& operator=(const UsbHost&) = delete;

  /// Starts watching the port (first look at time `start_ns`).
  void start(SimTime start_ns);
  /// The device changed something the host may find: look at the next (micro)frame.
  void wake();

  /// Changes the CDC control line state (PSTN 1.2 table 18: DTR, RTS) as a terminal program
  /// does when it opens or closes the port; sent at the next (micro)frame once enumerated (the
  /// enumeration itself sends the latest state, DTR and RTS on unless changed before).
  void set_line_state(bool dtr, bool rts);
  /// True once the CDC function is configured and the first line state was sent.
  bool enumerated() const { return phase_ == Phase::kRunning; }
  const HostRecord& record() const { return record_; }
  /// The enumeration failure in one line ("" if none), e.g. "usb host at 0.312 s: …".
  const std::string& failure() const { return failure_; }
  /// Called once with failure() when enumeration fails.
  void set_failure_listener(std::function<void(const std::string&)> listener) { on_failure_ = std::move(listener); }
  /// Where the host is, in one line: not attached (and why), enumerating (which request, which
  /// stage), configured (speed, VID:PID, product), or the failure.
  std::string describe() const;
  /// Bytes the host holds for the device that the device has not accepted yet (it NAKs).
  size_t out_pending() const { return out_.size(); }

 private:
  enum class Phase : uint8_t { kDetached, kDebounce, kReset, kRecovery, kEnumerating, kRunning, kFailed };
  struct Tick : Event {
    explicit Tick(UsbHost& owner);
    UsbHost& host;
  };
  static void on_tick(Event& event, Scheduler& scheduler);

  void run_tick();
  void advance_phase();
  bool run_control(int& budget);
  bool send_line_state();
  bool control_setup(ControlTransfer& transfer);
  bool control_data(ControlTransfer& transfer, int& budget);
  bool control_status(ControlTransfer& transfer);
  void control_done(ControlTransfer& transfer);
  void begin_next_request();
  bool handle_answer(const ControlTransfer& transfer);
  bool handle_late_answer(const ControlTransfer& transfer);
  bool run_bulk(int& budget);
  bool bulk_in(int& budget);
  bool bulk_out(int& budget);
  void queue_request(const char* name, uint8_t type, uint8_t request, uint16_t value, uint16_t index, uint16_t length,
                     const std::vector<uint8_t>& out = {});
  void fail(const std::string& why);
  SimTime period_ns() const;
  void schedule_at(SimTime time_ns);
  SimTime next_boundary(SimTime period) const;

  ChipContext& chip_;
  BoardIo& world_;
  UsbDevicePort& device_;
  HostOptions options_;
  Tick tick_;
  Phase phase_ = Phase::kDetached;
  SimTime phase_until_ns_ = 0;
  SimTime epoch_ns_ = 0;  ///< frame 0 starts here (the end of the last bus reset)
  uint8_t current_address_ = 0;
  int step_ = 0;  ///< the enumeration request in progress
  uint8_t max_packet0_ = 64;
  uint16_t language_ = 0x0409;
  ControlTransfer control_;
  bool control_active_ = false;
  uint16_t line_state_ = 0x0003;  ///< PSTN 1.2 table 18: D0 DTR, D1 RTS
  bool line_state_pending_ = false;
  std::deque<uint8_t> out_;       ///< bytes from the world waiting for the device
  std::vector<uint8_t> in_held_;  ///< bytes from the device the world has not taken yet
  HostRecord record_;
  std::string failure_;
  std::function<void(const std::string&)> on_failure_;
};

}  // namespace stepdance::sim::image::usb
