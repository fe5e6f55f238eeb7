// One of the USB controller's two general-purpose timers (GPTIMER0/1): a 24-bit down-counter at
// 1 MHz that sets USBSTS.TI0/TI1 when it runs out. Teensyduino 1.59's USB serial flushes its
// partly filled transmit buffer from GPTIMER0 (75 µs after the last write), not from SOF.
#pragma once

#include <cstdint>

#include "common/sim_time.hpp"
#include "image/chip/chip_context.hpp"
#include "kernel/scheduler/event.hpp"

namespace stepdance::sim::image::usb {

/// RM ch. 42, USB_nGPTIMERnLD and USB_nGPTIMERnCTRL. The count is derived from simulated time;
/// the expiry is an event on the chip's scheduler. Simulator thread only.
class GpTimer {
 public:
  /// `expired` is called at the expiry time (from a scheduler event) with `context`.
  GpTimer(ChipContext& chip, void (*expired)(void* context), void* context);
  ~GpTimer();
  GpTimer(const GpTimer&) = delete;
  GpTimer& operator=(const GpTimer&) = delete;

  uint32_t load() const { return load_; }
  /// GPTLD: the period in µs minus 1 (bits 23:0).
  void write_load(uint32_t value) { load_ = value & 0x00FFFFFFu; }
  /// GPTIMERnCTRL as read: RUN, MODE and the current count.
  uint32_t read_control() const;
  /// GPTIMERnCTRL written: RST reloads the count from GPTLD, RUN starts or stops it.
  void write_control(uint32_t value);
  /// Stops the timer and clears it (controller reset).
  void reset();

 private:
  struct Expiry : Event {
    explicit Expiry(GpTimer& owner);
    GpTimer& timer;
  };
  static void on_expiry(Event& event, Scheduler& scheduler);
  uint32_t count_now() const;
  void schedule_from(uint32_t count);

  ChipContext& chip_;
  void (*expired_)(void*);
  void* context_;
  Expiry expiry_;
  uint32_t load_ = 0;
  bool running_ = false;
  bool repeat_ = false;
  uint32_t stopped_count_ = 0;  ///< the count while stopped
  SimTime zero_at_ns_ = 0;      ///< while running: when the count reaches its end
};

}  // namespace stepdance::sim::image::usb
