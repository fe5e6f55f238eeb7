// A scripted device stack for the USB model's tests: it makes the register writes a device
// driver makes (in the order the RM's device initialisation and Teensyduino 1.59's usb.c use),
// keeps its queue heads and transfer descriptors in the fake RAM laid out as the RM gives them,
// and answers the host's requests for one CDC-ACM function.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "fake_chip.hpp"
#include "image/usb/usb_controller.hpp"
#include "image/usb/usb_phy.hpp"
#include "image/usb/usb_registers.hpp"

namespace stepdance::sim::image::usb::testing {

// Descriptors written by hand from USB 2.0 §9.6 and CDC 1.2 / PSTN 1.2 §5: a Teensy-like
// serial (16C0:0483), endpoints 0x82 (notification), 0x03 (bulk OUT), 0x84 (bulk IN).
inline const std::vector<uint8_t> kDeviceDescriptor = {18,   1,    0x00, 0x02, 0xEF, 0x02, 0x01, 64, 0xC0,
                                                       0x16, 0x83, 0x04, 0x00, 0x01, 1,    2,    3,  1};
inline const std::vector<uint8_t> kConfiguration = {
    9, 2,    75,   0,    2,    1,    0, 0xC0, 50,  // configuration: 75 bytes, 2 interfaces, value 1
    8, 11,   0,    2,    2,    2,    1, 0,         // interface association: interfaces 0..1, CDC ACM
    9, 4,    0,    0,    1,    2,    2, 1,    0,   // interface 0: communications, ACM, AT commands
    5, 0x24, 0x00, 0x10, 0x01,                     // CDC header, bcdCDC 1.10
    5, 0x24, 0x01, 0x00, 1,                        // call management: data interface 1
    4, 0x24, 0x02, 0x06,                           // ACM: line coding + break
    5, 0x24, 0x06, 0,    1,                        // union: master 0, slave 1
    7, 5,    0x82, 3,    16,   0,    5,            // endpoint 0x82 interrupt, 16 bytes
    9, 4,    1,    0,    2,    0x0A, 0, 0,    0,   // interface 1: data
    7, 5,    0x03, 2,    0x00, 0x02, 0,            // endpoint 0x03 bulk OUT, 512 bytes
    7, 5,    0x84, 2,    0x00, 0x02, 0,            // endpoint 0x84 bulk IN, 512 bytes
};
inline const std::vector<uint8_t> kLanguages = {4, 3, 0x09, 0x04};
inline const std::vector<uint8_t> kManufacturer = {12, 3, 'M', 0, 'a', 0, 'k', 0, 'e', 0, 'r', 0};
inline const std::vector<uint8_t> kProduct = {14, 3, 'S', 0, 'e', 0, 'r', 0, 'i', 0, 'a', 0, 'l', 0};
inline const std::vector<uint8_t> kSerial = {6, 3, '4', 0, '2', 0};

class FakeDeviceStack {
 public:
  // Fake RAM layout.
  static constexpr uint32_t kQueueHeads = FakeChip::kRamBase;  // 2 KB aligned
  static constexpr uint32_t kDtdData = kQueueHeads + 0x1000, kDtdAck = kDtdData + 0x20;
  static constexpr uint32_t kDtdRx = kDtdData + 0x40, kDtdTx = kDtdData + 0x60, kDtdTx2 = kDtdData + 0x80;
  static constexpr uint32_t kEp0Buffer = kQueueHeads + 0x2000, kLineBuffer = kQueueHeads + 0x2800;
  static constexpr uint32_t kRxBuffer = kQueueHeads + 0x3000, kTxBuffer = kQueueHeads + 0x5000;

  FakeDeviceStack(FakeChip& chip, UsbController& usb, UsbPhy& phy) : chip_(chip), usb_(usb), phy_(phy) {}

  uint32_t reg(uint32_t offset) {
    uint32_t value = 0;
    EXPECT_EQ(usb_.read(offset, 4, value), Access::kOk) << "read of USB1+0x" << std::hex << offset;
    return value;
  }
  void set(uint32_t offset, uint32_t value) {
    EXPECT_EQ(usb_.write(offset, 4, value), Access::kOk) << "write of USB1+0x" << std::hex << offset;
  }
  uint32_t head(unsigned queue) const { return kQueueHeads + 64 * queue; }

  /// Device initialisation: PHY out of gating and powered, device mode, queue heads for
  /// endpoint 0 (64 bytes, interrupt on setup), interrupts, run.
  void init(bool power_phy = true) {
    if (power_phy) {
      EXPECT_EQ(phy_.write(0x38, 4, UsbPhy::kCtrlSoftReset | UsbPhy::kCtrlClockGate), Access::kOk);  // CTRL_CLR
      EXPECT_EQ(phy_.write(0x00, 4, 0), Access::kOk);                                                // PWD = 0
    }
    set(kUsbMode, 2 | (1u << 3));  // device mode, setup lockout off
    chip_.set_word(head(0), (64u << 16) | (1u << 15));
    chip_.set_word(head(1), 64u << 16);
    set(kEndptListAddr, kQueueHeads);
    set(kUsbIntr, kStsUi | kStsUei | kStsUri | kStsSli);
    set(kUsbCmd, kCmdRunStop);
  }

  /// Runs the scheduler to `end_ns`, taking the USB interrupt after each event that raised it.
  void run_until(SimTime end_ns) {
    while (chip_.scheduler().step(end_ns)) {
      for (int guard = 0; chip_.irq113 && guard < 100; ++guard) isr();
    }
    chip_.scheduler().run_until(end_ns);
  }

  /// Builds a dTD: `length` bytes at `buffer`, active, IOC as asked, terminating.
  void make_dtd(uint32_t dtd, uint32_t buffer, uint32_t length, bool ioc) {
    chip_.set_word(dtd + 0, 1);
    chip_.set_word(dtd + 4, (length << 16) | (ioc ? kTokenIoc : 0u) | kTokenActive);
    for (uint32_t page = 0; page < 5; ++page) chip_.set_word(dtd + 8 + 4 * page, buffer + 0x1000 * page);
  }
  /// Links `dtd` into a queue head's overlay and primes it (the "list empty" case of the RM).
  void prime(unsigned queue, uint32_t dtd) {
    chip_.set_word(head(queue) + 8, dtd);
    chip_.set_word(head(queue) + 12, 0);
    set(kEndptPrime, queue_bit(queue));
  }
  /// SET_CONFIGURATION's work: endpoints 2 (interrupt IN), 3 (bulk OUT), 4 (bulk IN).
  void configure_endpoints() {
    set(kEndptCtrl0 + 8, 0x00CC0000u);   // TX interrupt, enabled
    set(kEndptCtrl0 + 12, 0x000000C8u);  // RX bulk, enabled
    set(kEndptCtrl0 + 16, 0x00C80000u);  // TX bulk, enabled
    chip_.set_word(head(2 * 3), (512u << 16) | kCapZltDisabled);
    chip_.set_word(head(2 * 4 + 1), 512u << 16);
    chip_.set_word(head(2 * 3) + 8, 1);
    chip_.set_word(head(2 * 4 + 1) + 8, 1);
  }

  void isr();

  int bus_resets = 0;
  bool high_speed = false;
  bool configured = false;
  bool answer_device_descriptor = true;
  bool full_speed_configuration = false;  ///< answer with 64-byte bulk endpoints
  uint16_t line_state = 0xFFFF;
  std::vector<uint8_t> line_coding;
  std::vector<std::vector<uint8_t>> setups;
  uint32_t completions = 0;
  std::vector<uint32_t> address_writes;

 private:
  void handle_setup(const uint8_t s[8]);
  void transmit(const std::vector<uint8_t>& data, uint16_t asked);
  void acknowledge_in();
  void descriptor(uint16_t value, uint16_t length);

  FakeChip& chip_;
  UsbController& usb_;
  UsbPhy& phy_;
  bool line_coding_pending_ = false;
};

inline void FakeDeviceStack::isr() {
  const uint32_t status = reg(kUsbSts);
  set(kUsbSts, status);
  if (status & kStsUi) {
    for (uint32_t setup = reg(kEndptSetupStat); setup != 0; setup = reg(kEndptSetupStat)) {
      set(kEndptSetupStat, setup);
      uint8_t s[8];
      do {
        set(kUsbCmd, reg(kUsbCmd) | kCmdSetupTripwire);
        chip_.read_memory(head(0) + 0x28, s, 8);
      } while (!(reg(kUsbCmd) & kCmdSetupTripwire));
      set(kUsbCmd, reg(kUsbCmd) & ~kCmdSetupTripwire);
      set(kEndptFlush, 0x00010001u);
      handle_setup(s);
    }
    const uint32_t complete = reg(kEndptComplete);
    set(kEndptComplete, complete);
    completions |= complete;
    if ((complete & (1u << 16)) && line_coding_pending_) {
      line_coding.assign(chip_.ram.begin() + (kLineBuffer - FakeChip::kRamBase),
                         chip_.ram.begin() + (kLineBuffer - FakeChip::kRamBase) + 7);
      line_coding_pending_ = false;
    }
  }
  if (status & kStsUri) {
    ++bus_resets;
    set(kEndptSetupStat, reg(kEndptSetupStat));
    set(kEndptComplete, reg(kEndptComplete));
    set(kEndptFlush, 0xFFFFFFFFu);
  }
  if (status & kStsPci) high_speed = (reg(kPortSc1) & kPortHsp) != 0;
}

inline void FakeDeviceStack::transmit(const std::vector<uint8_t>& data, uint16_t asked) {
  const uint32_t length = data.size() < asked ? static_cast<uint32_t>(data.size()) : asked;
  for (uint32_t i = 0; i < length; ++i) chip_.ram[kEp0Buffer - FakeChip::kRamBase + i] = data[i];
  make_dtd(kDtdData, kEp0Buffer, length, false);
  prime(1, kDtdData);
  make_dtd(kDtdAck, 0, 0, false);    // status stage: the host's zero-length OUT
  set(kEndptComplete, 0x00010001u);  // forget earlier endpoint-0 completions, as Teensyduino does
  prime(0, kDtdAck);
}

inline void FakeDeviceStack::acknowledge_in() {
  make_dtd(kDtdAck, 0, 0, false);  // status stage: a zero-length IN
  set(kEndptComplete, 0x00010001u);
  prime(1, kDtdAck);
}

inline void FakeDeviceStack::descriptor(uint16_t value, uint16_t length) {
  switch (value) {
    case 0x0100:
      if (answer_device_descriptor) transmit(kDeviceDescriptor, length);
      return;
    case 0x0200: {
      std::vector<uint8_t> configuration = kConfiguration;
      if (full_speed_configuration) {  // wMaxPacketSize of 0x03 (bytes 65-66) and 0x84 (72-73): 64
        configuration[65] = configuration[72] = 64;
        configuration[66] = configuration[73] = 0;
      }
      return transmit(configuration, length);
    }
    case 0x0300: return transmit(kLanguages, length);
    case 0x0301: return transmit(kManufacturer, length);
    case 0x0302: return transmit(kProduct, length);
    case 0x0303: return transmit(kSerial, length);
    default: set(kEndptCtrl0, 0x00010001u);  // stall
  }
}

inline void FakeDeviceStack::handle_setup(const uint8_t s[8]) {
  setups.emplace_back(s, s + 8);
  const uint16_t request = static_cast<uint16_t>(s[0] | (s[1] << 8));
  const uint16_t value = static_cast<uint16_t>(s[2] | (s[3] << 8));
  const uint16_t length = static_cast<uint16_t>(s[6] | (s[7] << 8));
  switch (request) {
    case 0x0680: return descriptor(value, length);
    case 0x0500:
      acknowledge_in();
      address_writes.push_back((uint32_t{value} << 25) | kDeviceAddrAdvance);
      return set(kDeviceAddr, address_writes.back());
    case 0x0900:
      configure_endpoints();
      configured = true;
      return acknowledge_in();
    case 0x2021:
      make_dtd(kDtdData, kLineBuffer, 7, false);
      prime(0, kDtdData);
      make_dtd(kDtdAck, 0, 0, true);
      set(kEndptComplete, 0x00010001u);
      prime(1, kDtdAck);
      line_coding_pending_ = true;
      return;
    case 0x2221: line_state = value; return acknowledge_in();
    default: set(kEndptCtrl0, 0x00010001u);
  }
}

}  // namespace stepdance::sim::image::usb::testing
