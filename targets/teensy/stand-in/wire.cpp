// Wire (LPI2C1, QWIIC0 on pins 18 SDA / 19 SCL) and Wire1 (LPI2C3, QWIIC1 on pins 17 SDA / 16 SCL)
// of the CI firmware image: blocking bus-master transfers. RM LPI2C chapter (master registers MCR,
// MSR, MCFGR0..3, MCCR0, MFCR, MFSR, MTDR, MRDR and the command table of MTDR), RM §11.7 (pad mux
// ALT3 = LPI2C1 on GPIO_AD_B1_00/01, ALT1 = LPI2C3 on GPIO_AD_B1_07/06, and their input selects),
// RM §14.7 (CSCDR2 LPI2C clock root, CCGR2 gates).
//
// The functional clock is the 24 MHz oscillator (LPI2C_CLK_SEL = 1, divider 1). A transfer writes
// its commands into the 4-word transmit FIFO as room frees up (START + address, data or a receive
// count, then STOP) and polls MSR for the end or an error. endTransmission's codes are Wire's:
// 0 done, 1 more than kBufferBytes written, 2 address not acknowledged, 3 data not acknowledged,
// 4 other error (arbitration lost, FIFO error, no transmission begun), 5 timeout (a device held
// SCL low past MCFGR3.PINLOW, or the transfer took over 50 ms). An address NACK is told from a
// data NACK by how many commands the controller had taken from its FIFO when NDF rose: only the
// START + address one means the address went unanswered.
#include <Arduino.h>
#include <Wire.h>
#include <stdint.h>

#include "stand_in_registers.h"
#include "stepdance/platform/teensy/pins.hpp"
#include "stepdance/platform/teensy/regs_ccm.hpp"

TwoWire Wire(0);
TwoWire Wire1(1);

namespace {

namespace lpi2c = stand_in::lpi2c;
namespace iomuxc = stepdance::platform::teensy::regs::iomuxc;
namespace ccm = stepdance::platform::teensy::regs::ccm;
using stepdance::platform::teensy::pin_pad;

struct Controller {
  uint32_t base;
  ccm::ClockGate gate;
  uint8_t scl_pin, sda_pin;         // Teensy pins
  uint8_t alt;                      // pad mux mode of the LPI2C function
  uint16_t scl_select, sda_select;  // input select registers (offset from the IOMUXC base)
  uint8_t select_value;             // the daisy value that picks these pads
};
constexpr Controller kControllers[2] = {
    {lpi2c::kLpi2c1Base, {2, 3}, 19, 18, 3, stand_in::daisy::kLpi2c1Scl, stand_in::daisy::kLpi2c1Sda, 1},
    {lpi2c::kLpi2c3Base, {2, 5}, 16, 17, 1, stand_in::daisy::kLpi2c3Scl, stand_in::daisy::kLpi2c3Sda, 2},
};

constexpr uint32_t kFunctionalClockHz = 24000000;
constexpr uint32_t kTransferTimeoutUs = 50000;
constexpr uint32_t kPinLowTimeoutUs = 15000;
// Open drain, 22 kΩ pull-up, drive R0/4, medium speed, hysteresis (RM §11.7 SW_PAD_CTL_PAD).
constexpr uint32_t kPadI2c = iomuxc::kPadOpenDrain | iomuxc::kPadKeeperEnable | iomuxc::kPadPullSelect |
                             iomuxc::pad_pull(iomuxc::kPull22kUp) | iomuxc::pad_drive(4) | iomuxc::pad_speed(1) |
                             iomuxc::kPadHysteresis;

stand_in::Reg32 reg(const Controller& c, uint32_t offset) { return stand_in::reg32(c.base + offset); }

uint32_t tx_fifo_count(const Controller& c) { return reg(c, lpi2c::kMfsr) & 7u; }

void reset_fifos(const Controller& c) { reg(c, lpi2c::kMcr) |= lpi2c::kMcrResetTxFifo | lpi2c::kMcrResetRxFifo; }

// Waits until the bus is free (or already ours), then clears the flags of earlier transfers.
bool claim_bus(const Controller& c) {
  const uint32_t start_us = micros();
  // Free: BBF clear. Ours already (a repeated START follows a write without STOP): MBF set.
  while ((reg(c, lpi2c::kMsr) & (lpi2c::kMsrBusBusy | lpi2c::kMsrMasterBusy)) == lpi2c::kMsrBusBusy) {
    if (micros() - start_us > kTransferTimeoutUs) return false;
  }
  reg(c, lpi2c::kMsr) = lpi2c::kMsrClearable;
  return true;
}

// Wire's code for an error flag in MSR, or 0xFF for none. `taken` is how many commands have left the
// transmit FIFO.
uint8_t error_code(const Controller& c, uint32_t status, uint32_t taken) {
  if (status & lpi2c::kMsrNack) {
    reset_fifos(c);
    reg(c, lpi2c::kMtdr) = lpi2c::kCmdStop;
    return taken <= 1 ? 2 : 3;
  }
  if (status & lpi2c::kMsrPinLowTimeout) {
    reset_fifos(c);
    return 5;
  }
  if (status & (lpi2c::kMsrArbitrationLost | lpi2c::kMsrFifoError)) {
    reset_fifos(c);
    return 4;
  }
  return 0xFF;
}

/// The commands of one transfer, fed into the FIFO as it empties.
struct CommandQueue {
  uint16_t words[TwoWire::kBufferBytes + 3];
  uint32_t count = 0;
  uint32_t pushed = 0;
  void add(uint32_t word) { words[count++] = static_cast<uint16_t>(word); }
  void feed(const Controller& c) {
    while (pushed < count && tx_fifo_count(c) < lpi2c::kFifoWords) reg(c, lpi2c::kMtdr) = words[pushed++];
  }
  uint32_t taken(const Controller& c) const { return pushed - tx_fifo_count(c); }
};

// Runs the queued commands; `receive` gets the bytes read (up to `expected`). Returns Wire's code.
uint8_t run(const Controller& c, CommandQueue& queue, bool stop, uint8_t* receive, uint8_t expected,
            uint8_t& received) {
  const uint32_t start_us = micros();
  for (;;) {
    queue.feed(c);
    for (uint32_t data = reg(c, lpi2c::kMrdr); !(data & lpi2c::kMrdrEmpty); data = reg(c, lpi2c::kMrdr)) {
      if (received < expected) receive[received++] = static_cast<uint8_t>(data);
    }
    const uint32_t status = reg(c, lpi2c::kMsr);
    const uint8_t error = error_code(c, status, queue.taken(c));
    if (error != 0xFF) return error;
    const bool sent = queue.pushed == queue.count && tx_fifo_count(c) == 0;
    if (sent && received >= expected && (!stop || (status & lpi2c::kMsrStopDetected))) return 0;
    if (micros() - start_us > kTransferTimeoutUs) {
      reset_fifos(c);
      return 5;
    }
    yield();
  }
}

void configure_pad(uint8_t pin, uint8_t alt) {
  const uint16_t mux = pin_pad(pin).mux;
  iomuxc::pad_ctl(mux) = kPadI2c;
  iomuxc::pad_mux(mux) = alt | iomuxc::kMuxSion;
}

}  // namespace

void TwoWire::begin() {
  const Controller& c = kControllers[controller_];
  // LPI2C clock root: the 24 MHz oscillator, undivided.
  stand_in::reg32(stand_in::ccm::kCscdr2) =
      (stand_in::reg32(stand_in::ccm::kCscdr2) & ~stand_in::ccm::kCscdr2Lpi2cPodfMask) | stand_in::ccm::kCscdr2Lpi2cOsc;
  ccm::gate_on(c.gate);
  reg(c, lpi2c::kMcr) = lpi2c::kMcrReset;
  reg(c, lpi2c::kMcr) = 0;
  setClock(100000);
  configure_pad(c.scl_pin, c.alt);
  configure_pad(c.sda_pin, c.alt);
  iomuxc::select_input(c.scl_select) = c.select_value;
  iomuxc::select_input(c.sda_select) = c.select_value;
}

// SCL period = (CLKLO + CLKHI + 2 + SCL_LATENCY) × 2^PRESCALE / 24 MHz, SCL_LATENCY =
// (2 + FILTSCL) / 2^PRESCALE (RM LPI2C, "Timing parameters", rise time taken as 0).
void TwoWire::setClock(uint32_t frequency) {
  const Controller& c = kControllers[controller_];
  if (frequency < 100000) frequency = 100000;
  const uint32_t prescale = frequency < 200000 ? 1 : 0;
  const uint32_t filter = frequency > 400000 ? 1 : 2;
  const uint32_t period = kFunctionalClockHz / (frequency << prescale);
  const uint32_t clocks = period - 2 - (2 + filter) / (1u << prescale);
  uint32_t low = (clocks * 60 + 99) / 100;  // 60 % low: I2C's minimum low time is twice its high
  if (low > 63) low = 63;
  uint32_t high = clocks - low > 63 ? 63 : clocks - low;
  const uint32_t sethold = high;
  const uint32_t datavd = low / 3;
  reg(c, lpi2c::kMcr) = 0;
  reg(c, lpi2c::kMccr0) = datavd << 24 | sethold << 16 | high << 8 | low;
  reg(c, lpi2c::kMccr1) = reg(c, lpi2c::kMccr0);
  reg(c, lpi2c::kMcfgr0) = 0;
  reg(c, lpi2c::kMcfgr1) = prescale;
  reg(c, lpi2c::kMcfgr2) = filter << 24 | filter << 16 | (4 * period);  // FILTSDA, FILTSCL, BUSIDLE
  const uint32_t pin_low = kPinLowTimeoutUs * (kFunctionalClockHz / 1000000) / (256u << prescale);
  reg(c, lpi2c::kMcfgr3) = pin_low << 8;
  reg(c, lpi2c::kMfcr) = 0;
  reg(c, lpi2c::kMcr) = lpi2c::kMcrEnable;
}

void TwoWire::beginTransmission(uint8_t address) {
  address_ = address;
  transmitting_ = true;
  too_long_ = false;
  tx_length_ = 0;
}

size_t TwoWire::write(const uint8_t* data, size_t quantity) {
  if (!transmitting_) return 0;
  size_t written = 0;
  while (written < quantity && tx_length_ < kBufferBytes) tx_[tx_length_++] = data[written++];
  if (written < quantity) too_long_ = true;
  return written;
}

uint8_t TwoWire::endTransmission(uint8_t sendStop) {
  if (!transmitting_) return 4;
  transmitting_ = false;
  if (too_long_) return 1;
  const Controller& c = kControllers[controller_];
  if (!claim_bus(c)) return 5;
  CommandQueue queue;
  queue.add(lpi2c::kCmdStart | static_cast<uint32_t>(address_ & 0x7Fu) << 1);
  for (uint8_t i = 0; i < tx_length_; ++i) queue.add(lpi2c::kCmdTransmit | tx_[i]);
  if (sendStop) queue.add(lpi2c::kCmdStop);
  uint8_t none = 0;
  return run(c, queue, sendStop != 0, nullptr, 0, none);
}

uint8_t TwoWire::requestFrom(uint8_t address, uint8_t quantity, uint8_t sendStop) {
  rx_length_ = 0;
  rx_index_ = 0;
  if (quantity == 0) return 0;
  if (quantity > kBufferBytes) quantity = kBufferBytes;
  const Controller& c = kControllers[controller_];
  if (!claim_bus(c)) return 0;
  CommandQueue queue;
  queue.add(lpi2c::kCmdStart | static_cast<uint32_t>(address & 0x7Fu) << 1 | 1u);
  queue.add(lpi2c::kCmdReceive | static_cast<uint32_t>(quantity - 1u));
  if (sendStop) queue.add(lpi2c::kCmdStop);
  uint8_t received = 0;
  const uint8_t code = run(c, queue, sendStop != 0, rx_, quantity, received);
  rx_length_ = code == 0 ? received : 0;
  return rx_length_;
}

int TwoWire::available() { return rx_length_ - rx_index_; }

int TwoWire::read() { return rx_index_ < rx_length_ ? rx_[rx_index_++] : -1; }
