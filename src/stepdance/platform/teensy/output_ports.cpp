// Output ports A–D: FlexIO3 shifters n (STEP) and n+4 (DIR), timer n, pads in ALT9 (RM §11.7).
#if defined(__IMXRT1062__)

#include "stepdance/platform/teensy/output_ports.hpp"

#include "stepdance/boards/board.hpp"
#include "stepdance/hal/hal.hpp"
#include "stepdance/platform/teensy/flexio3.hpp"
#include "stepdance/platform/teensy/pins.hpp"

namespace stepdance::platform::teensy {
namespace {

/// One output port: Teensy pins and the FlexIO3 pins their pads carry in ALT9.
struct OutputWiring {
  uint8_t step_pin;
  uint8_t dir_pin;
  uint8_t step_flexio;
  uint8_t dir_flexio;
};

// The pins are the board table's (written once, in boards/board.hpp); the FlexIO3 pins follow
// from their pads: 23 = AD_B1_09 → 9, 22 = AD_B1_08 → 8, 21 = AD_B1_11 → 11, 20 = AD_B1_10 → 10,
// 37 = B1_03 → 19, 36 = B1_02 → 18, 35 = B1_12 → 28, 34 = B1_13 → 29.
constexpr OutputWiring wiring_of(const OutputPortPins& pins) {
  return {pins.step, pins.dir, flexio3_pin(pins.step), flexio3_pin(pins.dir)};
}
constexpr OutputWiring kWiring[4] = {
    wiring_of(kDriverModuleV1.output_ports[0]), wiring_of(kDriverModuleV1.output_ports[1]),
    wiring_of(kDriverModuleV1.output_ports[2]), wiring_of(kDriverModuleV1.output_ports[3])};
#if defined(ARDUINO_TEENSY40)
constexpr uint8_t kPortCount = 2;  // pins 34..37 of a Teensy 4.0 are SD pads without FlexIO3
#else
constexpr uint8_t kPortCount = 4;
#endif
// Every registered board that sits on this Teensy wires its port n as port n here.
constexpr bool boards_match_wiring() {
  for (const BoardDefinition* board : kBoards) {
    if (!board_takes(*board, kThisTeensy)) continue;
    if (board->output_port_count > kPortCount) return false;
    for (uint8_t port = 0; port < board->output_port_count; ++port) {
      const OutputPortPins& pins = board->output_ports[port];
      if (pins.step != kWiring[port].step_pin || pins.dir != kWiring[port].dir_pin) return false;
    }
  }
  return true;
}
static_assert(boards_match_wiring(), "a board's output port n is not wired as port n of this backend");
constexpr bool ports_have_flexio3_pads() {
  for (uint8_t port = 0; port < kPortCount; ++port) {
    if (kWiring[port].step_flexio == 0xFF || kWiring[port].dir_flexio == 0xFF) return false;
  }
  return true;
}
static_assert(ports_have_flexio3_pads(), "every output port pin needs a pad with a FlexIO3 function");

// Between transmissions a pin shows bit 0 of a word (the shifter's last load), so the lines idle
// low only because the frame layout never uses bit 0: STEP starts at 2 µs, DIR 1 µs before it.
static_assert(protocol::kFirstPulseStartUs - protocol::kDirMarginUs >= 1, "bit 0 of every frame word must be 0");

volatile uint8_t claimed = 0;
volatile uint8_t staged = 0;
protocol::FrameWords staged_words[4];

constexpr uint8_t port_bit(uint8_t port) { return static_cast<uint8_t>(1u << port); }

void attach_pin(uint8_t pin) {
  const PinInfo& info = *pin_info(pin);
  pad_configure(info, kPadOutput);
  pad_select(info, regs::iomuxc::kAltFlexio3);
}

void attach(const OutputWiring& wiring) {
  attach_pin(wiring.step_pin);
  attach_pin(wiring.dir_pin);
}

void park_pin(uint8_t pin) {
  const PinInfo& info = *pin_info(pin);
  pin_drive(info, false);
  pin_make_gpio(info, true);
}

}  // namespace

void output_ports_disarm() { output_ports_zero(claimed); }

uint8_t output_ports_commit_staged() {
  const uint8_t ports = staged & claimed;
  for (uint8_t port = 0; port < kPortCount; ++port) {
    if (ports & port_bit(port)) flexio::write_port(port, staged_words[port].step_bits, staged_words[port].dir_bits);
  }
  staged = 0;
  return ports;
}

void output_ports_drop_staged() { staged = 0; }

void output_ports_zero(uint8_t mask) {
  for (uint8_t port = 0; port < kPortCount; ++port) {
    if (mask & port_bit(port)) flexio::write_port(port, 0, 0);
  }
}

void output_ports_attach_pins() {
  for (uint8_t port = 0; port < kPortCount; ++port) {
    if (claimed & port_bit(port)) attach(kWiring[port]);
  }
}

void output_ports_park_pins() {
  for (uint8_t port = 0; port < kPortCount; ++port) {
    if (!(claimed & port_bit(port))) continue;
    park_pin(kWiring[port].step_pin);
    park_pin(kWiring[port].dir_pin);
  }
}

}  // namespace stepdance::platform::teensy

namespace stepdance::hal {

namespace teensy = platform::teensy;

Status port_out_begin(uint8_t port) {
  if (port >= teensy::kPortCount) return Status::kNoSuchPin;
  if (teensy::claimed & teensy::port_bit(port)) return Status::kBusy;
  const teensy::OutputWiring& wiring = teensy::kWiring[port];
  teensy::flexio::power_up();
  teensy::flexio::configure_port(port, wiring.step_flexio, wiring.dir_flexio);
  teensy::attach(wiring);
  CriticalSection guard;
  teensy::claimed = static_cast<uint8_t>(teensy::claimed | teensy::port_bit(port));
  return Status::kOk;
}

void port_out_frame(uint8_t port, const protocol::FrameWords& words) {
  if (port >= teensy::kPortCount) return;
  teensy::staged_words[port] = words;
  teensy::staged = static_cast<uint8_t>(teensy::staged | teensy::port_bit(port));
}

}  // namespace stepdance::hal

#endif  // __IMXRT1062__
