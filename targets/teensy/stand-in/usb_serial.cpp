// The stand-in core's USB serial: bring-up of USB1 in device mode, the USB1 interrupt, and
// usb_serial_class (Arduino.h) on a receive ring and a transmit ring. Written from the i.MX RT1060
// reference manual (RM): chapter 14 (CCM: PLL_USB1, CCGR6), chapter 42 (USB device controller)
// and chapter 43 (USBPHY).
//
// Receive: one 512-byte dTD on endpoint 3 OUT; each packet is copied into the receive ring and
// the dTD re-primed while the ring has room for another packet (otherwise the host is NAKed
// until read() makes room). Transmit: write() copies into the transmit ring and, when no
// transfer is in flight, sends the ring's next contiguous bytes from endpoint 4 IN; each
// completion sends the next. write() never blocks: it takes what fits.
#include <Arduino.h>
#include <usb_serial.h>

#include "stepdance/platform/teensy/regs_nvic.hpp"
#include "usb_serial_device.h"

namespace stand_in_usb {

alignas(4096) QueueHead queue_heads[kQueueHeads];

namespace {

namespace nvic = stepdance::platform::teensy::regs::nvic;

// ---- Clocks and PHY (RM 14.8 CCM_ANALOG, 14.7 CCM, ch. 43 USBPHY) ----
constexpr uint32_t kPllUsb1 = 0x400D8010u;  // CCM_ANALOG_PLL_USB1 (+4 SET, +8 CLR)
constexpr uint32_t kPllLock = 1u << 31, kPllBypass = 1u << 16, kPllEnable = 1u << 13;
constexpr uint32_t kPllPower = 1u << 12, kPllUsbClocks = 1u << 6;
constexpr uint32_t kCcgr6 = 0x400FC080u;    // CCM_CCGR6: CG0 = usboh3
constexpr uint32_t kUsbPhy1 = 0x400D9000u;  // USBPHY1_PWD at +0, USBPHY1_CTRL at +0x30 (+4 SET, +8 CLR)
constexpr uint32_t kPhySoftReset = 1u << 31, kPhyClockGate = 1u << 30;
constexpr uint32_t kUsbPriority = 128;  // as Teensyduino: below the frame and tick ISRs

volatile uint32_t& mmio(uint32_t address) { return *reinterpret_cast<volatile uint32_t*>(address); }

constexpr uint32_t kRingBytes = 2048;  // a power of two
constexpr uint32_t kMaxPacket = 512;
alignas(32) uint8_t rx_packet[kMaxPacket];
uint8_t rx_ring[kRingBytes];
alignas(32) uint8_t tx_ring[kRingBytes];
volatile uint32_t rx_head = 0, rx_tail = 0;  // free-running byte counts
volatile uint32_t tx_head = 0, tx_tail = 0;
volatile uint32_t tx_in_flight = 0;
volatile bool rx_primed = false;
volatile bool configured = false;
volatile uint16_t line_state = 0;
bool started = false;
TransferDescriptor rx_td;
TransferDescriptor tx_td;

uint32_t rx_packet_size() { return high_speed() ? 512u : 64u; }

void disable_usb_irq() { nvic::icer(kIrqUsb1) = nvic::irq_bit(kIrqUsb1); }
void enable_usb_irq() { nvic::iser(kIrqUsb1) = nvic::irq_bit(kIrqUsb1); }

/// Primes the receive dTD if the ring can hold a whole packet. Context: USB IRQ or IRQ off.
void arm_receive() {
  if (rx_primed || !configured || kRingBytes - (rx_head - rx_tail) < rx_packet_size()) return;
  rx_primed = true;
  prime(queue(kRxEndpoint, false), rx_td, rx_packet, rx_packet_size(), true);
}

/// Sends the ring's next contiguous bytes if nothing is in flight. Context: USB IRQ or IRQ off.
void start_transmit() {
  const uint32_t pending = tx_head - tx_tail;
  if (tx_in_flight != 0 || pending == 0 || !configured) return;
  const uint32_t offset = tx_tail % kRingBytes;
  const uint32_t length = pending < kRingBytes - offset ? pending : kRingBytes - offset;
  tx_in_flight = length;
  prime(queue(kTxEndpoint, true), tx_td, tx_ring + offset, length, true);
}

void receive_complete() {
  rx_primed = false;
  const uint32_t left = (rx_td.token >> 16) & 0x7FFFu;
  const uint32_t length = rx_packet_size() - left;
  for (uint32_t i = 0; i < length; ++i) rx_ring[(rx_head + i) % kRingBytes] = rx_packet[i];
  rx_head = rx_head + length;
  arm_receive();
}

void transmit_complete() {
  tx_tail = tx_tail + tx_in_flight;
  tx_in_flight = 0;
  start_transmit();
}

/// Reads setup packets as the RM's setup tripwire protocol asks, and answers them.
void handle_setups() {
  for (uint32_t pending = usb(kEndptSetupStat); pending != 0; pending = usb(kEndptSetupStat)) {
    usb(kEndptSetupStat) = pending;
    uint32_t words[2];
    do {
      usb(kUsbCmd) = usb(kUsbCmd) | kCmdSetupTripwire;
      words[0] = queue_heads[0].setup[0];
      words[1] = queue_heads[0].setup[1];
    } while (!(usb(kUsbCmd) & kCmdSetupTripwire));
    usb(kUsbCmd) = usb(kUsbCmd) & ~kCmdSetupTripwire;
    usb(kEndptFlush) = queue_bit(0) | queue_bit(1);  // a new setup cancels the old transfer
    while (usb(kEndptFlush) & (queue_bit(0) | queue_bit(1))) {
    }
    uint8_t request[8];
    memcpy(request, words, sizeof request);
    control_setup(request);
  }
}

void bus_reset() {
  usb(kEndptSetupStat) = usb(kEndptSetupStat);
  usb(kEndptComplete) = usb(kEndptComplete);
  while (usb(kEndptPrime) != 0) {
  }
  usb(kEndptFlush) = 0xFFFFFFFFu;
  reset_serial();
}

void usb_isr() {
  const uint32_t status = usb(kUsbSts);
  usb(kUsbSts) = status;
  if (status & kStsUri) bus_reset();
  if (status & kStsUi) {
    handle_setups();
    const uint32_t complete = usb(kEndptComplete);
    usb(kEndptComplete) = complete;
    control_complete(complete);
    if (complete & queue_bit(queue(kRxEndpoint, false))) receive_complete();
    if (complete & queue_bit(queue(kTxEndpoint, true))) transmit_complete();
  }
}

void start_clocks() {
  const uint32_t pll = mmio(kPllUsb1);
  const uint32_t on = kPllEnable | kPllPower | kPllUsbClocks;
  if ((pll & on) != on) mmio(kPllUsb1 + 4) = on;
  for (uint32_t spins = 0; !(mmio(kPllUsb1) & kPllLock) && spins < 1000000u; ++spins) {
  }
  if (mmio(kPllUsb1) & kPllBypass) mmio(kPllUsb1 + 8) = kPllBypass;
  mmio(kCcgr6) = mmio(kCcgr6) | 3u;  // CG0 on in run and wait modes
}

void start_controller() {
  mmio(kUsbPhy1 + 0x34) = kPhySoftReset;  // CTRL_SET: reset the PHY,
  usb(kUsbCmd) = kCmdReset;               // and the controller
  while (usb(kUsbCmd) & kCmdReset) {
  }
  mmio(kUsbPhy1 + 0x38) = kPhySoftReset | kPhyClockGate;  // CTRL_CLR: out of reset, clocks on
  mmio(kUsbPhy1 + 0x00) = 0;                              // PWD: everything powered
  usb(kUsbMode) = 2u | (1u << 3);                         // device mode, setup lockout off (the tripwire is used)
  memset(queue_heads, 0, sizeof queue_heads);
  for (QueueHead& head : queue_heads) head.next = 1;
  queue_heads[queue(0, false)].config = (kControlPacket << 16) | kConfigIos;
  queue_heads[queue(0, true)].config = kControlPacket << 16;
  usb(kEndptListAddr) = reinterpret_cast<uint32_t>(queue_heads);
  usb(kUsbIntr) = kStsUi | kStsUei | kStsUri;
}

}  // namespace

void prime(unsigned q, TransferDescriptor& td, const volatile void* buffer, uint32_t length, bool interrupt) {
  const uint32_t address = reinterpret_cast<uint32_t>(buffer);
  td.next = 1;
  td.token = (length << 16) | (interrupt ? kTokenIoc : 0u) | kTokenActive;
  td.page[0] = address;
  for (uint32_t i = 1; i < 5; ++i) td.page[i] = (address & ~0xFFFu) + 0x1000u * i;
  queue_heads[q].next = reinterpret_cast<uint32_t>(&td);
  queue_heads[q].token = 0;
  __asm__ volatile("dsb" ::: "memory");
  usb(kEndptPrime) = queue_bit(q);
  while (usb(kEndptPrime) & queue_bit(q)) {
  }
}

void configure_serial() {
  // Unused halves get the bulk type, as the RM asks of endpoints used in one direction only.
  usb(kEndptCtrl0 + 4 * kNotifyEndpoint) = 0x00CC0008u;  // TX interrupt, enabled, toggle reset
  usb(kEndptCtrl0 + 4 * kRxEndpoint) = 0x000800C8u;      // RX bulk, enabled, toggle reset
  usb(kEndptCtrl0 + 4 * kTxEndpoint) = 0x00C80008u;      // TX bulk, enabled, toggle reset
  const uint32_t bulk = rx_packet_size();
  queue_heads[queue(kNotifyEndpoint, true)].config = (kNotifyPacket << 16) | kConfigNoZlt;
  queue_heads[queue(kRxEndpoint, false)].config = (bulk << 16) | kConfigNoZlt;
  queue_heads[queue(kTxEndpoint, true)].config = bulk << 16;  // full final packets get a ZLP
  configured = true;
  rx_primed = false;
  tx_in_flight = 0;
  arm_receive();
  start_transmit();
}

void reset_serial() {
  configured = false;
  line_state = 0;
  rx_primed = false;
  tx_in_flight = 0;  // an interrupted transfer's bytes stay in the ring and go again
}

void set_line_state(uint16_t state) { line_state = state; }

}  // namespace stand_in_usb

using namespace stand_in_usb;

extern "C" void stand_in_usb_serial_start(void) {
  if (started) return;
  started = true;
  start_clocks();
  start_controller();
  attachInterruptVector(static_cast<IRQ_NUMBER_t>(kIrqUsb1), &usb_isr);
  stepdance::platform::teensy::regs::nvic::ipr(kIrqUsb1) = static_cast<uint8_t>(kUsbPriority);
  enable_usb_irq();
  usb(kUsbCmd) = kCmdRunStop;  // attach
}

// ---- usb_serial_class (Arduino.h). Only `Serial` is this port; SerialUSB1 (Dual Serial) has no
// second CDC function here and reads nothing, writes nowhere. Context: thread. ----

void usb_serial_class::begin(long) { stand_in_usb_serial_start(); }

int usb_serial_class::available() {
  if (this != &Serial) return 0;
  stand_in_usb_serial_start();
  return static_cast<int>(rx_head - rx_tail);
}

int usb_serial_class::peek() {
  if (available() == 0) return -1;
  return rx_ring[rx_tail % kRingBytes];
}

int usb_serial_class::read() {
  if (available() == 0) return -1;
  const uint8_t byte = rx_ring[rx_tail % kRingBytes];
  disable_usb_irq();
  rx_tail = rx_tail + 1;
  arm_receive();
  enable_usb_irq();
  return byte;
}

int usb_serial_class::availableForWrite() {
  if (this != &Serial) return 0;
  stand_in_usb_serial_start();
  if (!configured) return 0;
  return static_cast<int>(kRingBytes - (tx_head - tx_tail));
}

size_t usb_serial_class::write(const uint8_t* data, size_t length) {
  if (this != &Serial) return length;
  const size_t room = static_cast<size_t>(availableForWrite());
  const size_t count = length < room ? length : room;
  for (size_t i = 0; i < count; ++i) tx_ring[(tx_head + i) % kRingBytes] = data[i];
  disable_usb_irq();
  tx_head = tx_head + static_cast<uint32_t>(count);
  start_transmit();
  enable_usb_irq();
  return count;
}

size_t usb_serial_class::write(uint8_t byte) { return write(&byte, 1); }

usb_serial_class::operator bool() const {
  return this == &Serial && configured && (line_state & 1u) != 0;  // DTR on
}
