// The HAL conformance suite on the manual backend (src/stepdance/platform/manual), driven by its
// test controls (hal_manual.hpp).
#include <cmath>

#include "hal_contract.hpp"
#include "hal_manual.hpp"

namespace hal_conformance {
namespace {

namespace hal_manual = ::stepdance::hal_manual;

struct ManualAdapter {
  // The manual backend's skip list: what it does not model, by design.
  static const char* skip_reason(Clause clause) {
    switch (clause) {
      case Clause::kCyclesRate: return "manual: cycles_now() is a cost model (set_cycles_per_read), not a clock";
      case Clause::kAdcPins: return "manual: adc_begin() accepts every pin up to kMaxPin (tests set any pin's value)";
      case Clause::kCriticalNesting:
        return "manual: one thread and no interrupts; irq_save()/irq_restore() keep no state";
      default: return nullptr;
    }
  }

  static void reset() {
    hal_manual::reset();
    for (auto& words : staged) words = {0, 0};
    for (auto& words : out) words = {0, 0};
  }
  static void settle() {}
  static void advance_us(uint32_t us) { hal_manual::advance_us(us); }

  // The backend keeps the last frame handed to each port; the wire is the adapter's: a frame
  // handed over during tick k's ISR is what the port launches at tick k + 1.
  static void tick() {
    uint32_t written[4];
    for (uint8_t port = 0; port < 4; ++port) {
      // In the safe state frames are idle: nothing handed over before it goes out.
      out[port] = hal_manual::in_safe_state() ? FrameWords{0, 0} : staged[port];
      written[port] = hal_manual::frames_written(port);
    }
    hal_manual::run_frames(1);
    for (uint8_t port = 0; port < 4; ++port) {
      const bool handed = hal_manual::frames_written(port) != written[port];
      staged[port] = handed ? hal_manual::last_frame(port) : FrameWords{0, 0};
    }
  }
  static FrameWords launched(uint8_t port) { return out[port]; }

  static void inject_pulse(uint8_t port, const stepdance::protocol::CapturedPulse& pulse) {
    hal_manual::inject_pulse(port, pulse);
  }
  static void set_quadrature(uint8_t index, int32_t count) { hal_manual::set_quadrature(index, count); }
  static void set_adc_fraction(uint8_t pin, double fraction) {
    hal_manual::set_adc(pin, static_cast<uint16_t>(std::lround(fraction * kAdcFullScale)));
  }
  static void drive_pin(uint8_t pin, bool high) { hal_manual::set_pin(pin, high); }
  static void feed_console(const std::string& bytes) { hal_manual::feed_console(bytes); }
  static std::string take_console_output() { return hal_manual::take_console_output(); }
  static bool drivers_disabled() { return hal_manual::in_safe_state(); }

  static FrameWords staged[4];
  static FrameWords out[4];
};
FrameWords ManualAdapter::staged[4];
FrameWords ManualAdapter::out[4];

}  // namespace

INSTANTIATE_TYPED_TEST_SUITE_P(Manual, HalContract, ManualAdapter);

}  // namespace hal_conformance
