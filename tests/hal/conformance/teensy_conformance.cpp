// The HAL conformance suite on the Teensy backend (src/stepdance/platform/teensy), compiled for the
// host on the register model (tests/platform/teensy/register_model.hpp): the harness plays the
// hardware the clauses need, from the i.MX RT1060 reference manual (RM), and the Teensyduino
// services the backend calls (USB serial, EEPROM emulation) as the stand-in declares them.
#include <Arduino.h>
#include <avr/eeprom.h>

#include <cstring>
#include <deque>

#include "hal_contract.hpp"
#include "register_model.hpp"
#include "stepdance/boards/board.hpp"

namespace hal_conformance {
namespace {

// ---- The frame clock (RM §50 FlexIO3; NVIC, ARMv7-M ARM §B3.4) --------------------------------
constexpr uint32_t kFlexio3 = 0x42020000u;        // FLEXIO3 base
constexpr uint32_t kTimstat = kFlexio3 + 0x018u;  // FLEXIO_TIMSTAT
constexpr uint32_t shiftbuf(unsigned n) { return kFlexio3 + 0x200u + 4u * n; }
constexpr uint32_t timctl(unsigned n) { return kFlexio3 + 0x400u + 4u * n; }
constexpr unsigned kFrameClockTimer = 4;             // the backend's frame clock: timer 4
constexpr uint32_t kTimodMask = 3u;                  // TIMCTL TIMOD: 0 = disabled
constexpr uint32_t kMarkerFlag = 1u << 5;            // timer 5: the tick marker
constexpr uint32_t kIspr4 = 0xE000E210u;             // NVIC_ISPR4: IRQs 128..159
constexpr uint32_t kIcpr4 = 0xE000E290u;             // NVIC_ICPR4
constexpr unsigned kFrameIrq = 155, kTickIrq = 156;  // reserved line, FLEXIO3
constexpr uint32_t kCyclesPerUs = teensy_model::kCoreHz / 1000000u;

// ---- GPT2 (RM §52.7): CR at the base; its software reset (SWR, bit 15) clears itself when done --
constexpr uint32_t kGpt2Cr = 0x401F0000u;
constexpr uint32_t kGptSoftwareReset = 1u << 15;

// ---- Fast GPIO6..9 (RM §12.5): DR +0, GDIR +4, PSR +8, DR_SET +0x84, DR_CLEAR +0x88 ---------
constexpr uint32_t gpio_base(unsigned fast) { return 0x42000000u + 0x4000u * fast; }

FrameWords launches[4];
uint32_t outside_levels[4];  // per fast port: the levels the world drives on input pads

// A rising edge of the frame clock: each port's shifters load their buffers (what goes out),
// and the tick marker raises its flag.
void edge() {
  for (unsigned port = 0; port < 4; ++port) {
    launches[port] = {teensy_model::peek(shiftbuf(port)), teensy_model::peek(shiftbuf(port + 4))};
  }
  teensy_model::poke(kTimstat, teensy_model::peek(kTimstat) | kMarkerFlag);
}

// The NVIC: the tick ISR if its flag is up, then the frame ISR if it is pending.
void run_pending() {
  if (teensy_model::peek(kTimstat) & kMarkerFlag) teensy_model::run_isr(kTickIrq);
  const uint32_t frame_bit = 1u << (kFrameIrq % 32);
  if (teensy_model::peek(kIspr4) & frame_bit) {
    teensy_model::poke(kIspr4, teensy_model::peek(kIspr4) & ~frame_bit);
    teensy_model::run_isr(kFrameIrq);
  }
}

void install_hardware() {
  teensy_model::reset();
  for (FrameWords& words : launches) words = {0, 0};
  teensy_model::write_one_to_clear(kTimstat);
  teensy_model::on_write(kIspr4, [](uint32_t stored, uint32_t written) { return stored | written; });
  teensy_model::on_write(kIcpr4, [](uint32_t, uint32_t written) {
    teensy_model::poke(kIspr4, teensy_model::peek(kIspr4) & ~written);
    return 0u;
  });
  // Enabling the frame clock makes its output rise at once: the first tick.
  teensy_model::on_write(timctl(kFrameClockTimer), [](uint32_t, uint32_t written) {
    if (written & kTimodMask) {
      edge();
      teensy_model::run_isr(kTickIrq);
    }
    return written;
  });
  teensy_model::on_write(kGpt2Cr, [](uint32_t, uint32_t written) { return written & ~kGptSoftwareReset; });
  // The pads: PSR shows DR on output pins (GDIR = 1) and the world's level on inputs.
  for (unsigned fast = 0; fast < 4; ++fast) {
    outside_levels[fast] = 0;
    const uint32_t base = gpio_base(fast);
    teensy_model::on_write(base + 0x84u, [base](uint32_t, uint32_t written) {
      teensy_model::poke(base, teensy_model::peek(base) | written);
      return 0u;
    });
    teensy_model::on_write(base + 0x88u, [base](uint32_t, uint32_t written) {
      teensy_model::poke(base, teensy_model::peek(base) & ~written);
      return 0u;
    });
    teensy_model::on_read(base + 0x08u, [base, fast](uint32_t) {
      const uint32_t output = teensy_model::peek(base + 0x04u);
      return (teensy_model::peek(base) & output) | (outside_levels[fast] & ~output);
    });
  }
}

// Teensy 4.1 pin → fast GPIO port and bit (the board's schematic / pad list): the pins the suite
// drives from outside.
struct PadBit {
  uint8_t pin;
  unsigned fast;  // 0..3 = GPIO6..9
  unsigned bit;
};
constexpr PadBit kOutsidePins[] = {{2, 3, 4}};  // pin 2 = EMC_04 = GPIO4_IO04 → GPIO9 bit 4

// ---- Teensyduino services (the stand-in's declarations) on host memory ------------------------
std::deque<uint8_t> usb_in;
std::string usb_out;
uint8_t eeprom[E2END + 1];

struct TeensyAdapter {
  // The Teensy backend's skip list: clauses whose hardware the suite's model does not play yet.
  static const char* skip_reason(Clause clause) {
    switch (clause) {
      case Clause::kFramePeriod: return "teensy model: the FlexIO3 clock does not run; the harness plays its edges";
      case Clause::kKhzTimer: return "teensy model: GPT2 compare events are not played by the harness";
      case Clause::kCaptureDelivery:
        return "teensy model: FlexPWM capture registers and their ISR are not played by the harness";
      case Clause::kQuadrature: return "teensy model: the ENC/XBAR decoders are not in the model build";
      case Clause::kAdcRange: return "teensy model: ADC conversions are not played by the harness";
      case Clause::kStorageRoundTrip: return "teensy model: SdFat has no host model";
      default: return nullptr;
    }
  }

  static void reset() {
    install_hardware();
    usb_in.clear();
    usb_out.clear();
    std::memset(eeprom, 0xFF, sizeof eeprom);  // erased flash
  }
  static void settle() { run_pending(); }
  static void advance_us(uint32_t us) { teensy_model::advance_cycles(uint64_t{us} * kCyclesPerUs); }

  static void tick() {
    teensy_model::advance_cycles(uint64_t{kFramePeriodUs} * kCyclesPerUs);
    if (teensy_model::peek(timctl(kFrameClockTimer)) & kTimodMask) {
      edge();
    } else {
      for (FrameWords& words : launches) words = {0, 0};  // no clock, nothing shifts
    }
    run_pending();
  }
  static FrameWords launched(uint8_t port) { return launches[port]; }

  static void inject_pulse(uint8_t, const stepdance::protocol::CapturedPulse&) {}
  static void set_quadrature(uint8_t, int32_t) {}
  static void set_adc_fraction(uint8_t, double) {}
  static void drive_pin(uint8_t pin, bool high) {
    for (const PadBit& pad : kOutsidePins) {
      if (pad.pin != pin) continue;
      if (high)
        outside_levels[pad.fast] |= 1u << pad.bit;
      else
        outside_levels[pad.fast] &= ~(1u << pad.bit);
    }
  }
  static void feed_console(const std::string& bytes) { usb_in.insert(usb_in.end(), bytes.begin(), bytes.end()); }
  static std::string take_console_output() {
    std::string out;
    out.swap(usb_out);
    return out;
  }
  // The safe state of a port: its driver's ENABLE (active low) driven high, STEP and DIR low.
  static bool drivers_disabled() {
    const stepdance::OutputPortPins& pins = stepdance::active_board().output_ports[2];
    return stepdance::hal::gpio_read(pins.enable) && !stepdance::hal::gpio_read(pins.step) &&
           !stepdance::hal::gpio_read(pins.dir);
  }
};

}  // namespace

INSTANTIATE_TYPED_TEST_SUITE_P(Teensy, HalContract, TeensyAdapter);

}  // namespace hal_conformance

// ---- The stand-in's USB serial and EEPROM emulation, kept in the harness's memory -------------
size_t Print::write(const uint8_t* data, size_t length) {
  for (size_t i = 0; i < length; ++i) write(data[i]);
  return length;
}
void usb_serial_class::begin(long) {}
int usb_serial_class::available() { return static_cast<int>(hal_conformance::usb_in.size()); }
int usb_serial_class::read() {
  if (hal_conformance::usb_in.empty()) return -1;
  const int byte = hal_conformance::usb_in.front();
  hal_conformance::usb_in.pop_front();
  return byte;
}
int usb_serial_class::peek() { return hal_conformance::usb_in.empty() ? -1 : hal_conformance::usb_in.front(); }
size_t usb_serial_class::write(uint8_t byte) {
  hal_conformance::usb_out.push_back(static_cast<char>(byte));
  return 1;
}
size_t usb_serial_class::write(const uint8_t* data, size_t length) {
  hal_conformance::usb_out.append(reinterpret_cast<const char*>(data), length);
  return length;
}
int usb_serial_class::availableForWrite() { return 64; }  // one USB packet of room at a time
usb_serial_class::operator bool() const { return true; }
usb_serial_class Serial;

extern "C" void eeprom_read_block(void* buf, const void* addr, uint32_t len) {
  std::memcpy(buf, hal_conformance::eeprom + reinterpret_cast<uintptr_t>(addr), len);
}
extern "C" void eeprom_write_block(const void* buf, void* addr, uint32_t len) {
  std::memcpy(hal_conformance::eeprom + reinterpret_cast<uintptr_t>(addr), buf, len);
}
