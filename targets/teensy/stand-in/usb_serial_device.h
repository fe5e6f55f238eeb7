/* Internals of the stand-in USB serial shared by its source files (usb_serial*.cpp). */
#pragma once

#include <stddef.h>
#include <stdint.h>

namespace stand_in_usb {

// ---- USB1 registers (RM ch. 42, USB_n* register map) ---------------------------------------
constexpr uint32_t kUsb1Base = 0x402E0000u;
inline volatile uint32_t& usb(uint32_t offset) { return *reinterpret_cast<volatile uint32_t*>(kUsb1Base + offset); }
constexpr uint32_t kUsbCmd = 0x140, kUsbSts = 0x144, kUsbIntr = 0x148, kDeviceAddr = 0x154;
constexpr uint32_t kEndptListAddr = 0x158, kPortSc1 = 0x184, kUsbMode = 0x1A8, kEndptSetupStat = 0x1AC;
constexpr uint32_t kEndptPrime = 0x1B0, kEndptFlush = 0x1B4, kEndptComplete = 0x1BC, kEndptCtrl0 = 0x1C0;
constexpr uint32_t kCmdRunStop = 1u << 0, kCmdReset = 1u << 1, kCmdSetupTripwire = 1u << 13;
constexpr uint32_t kStsUi = 1u << 0, kStsUei = 1u << 1, kStsUri = 1u << 6;
constexpr uint32_t kPortHighSpeed = 1u << 9;       // PORTSC1.HSP
constexpr uint32_t kDeviceAddrAdvance = 1u << 24;  // DEVICEADDR.USBADRA
constexpr uint32_t kIrqUsb1 = 113;                 // RM ch. 4: USB OTG1

// ---- Endpoints of the CDC-ACM function --------------------------------------------------------
constexpr unsigned kNotifyEndpoint = 2;  // interrupt IN 0x82
constexpr unsigned kRxEndpoint = 3;      // bulk OUT 0x03
constexpr unsigned kTxEndpoint = 4;      // bulk IN 0x84
constexpr unsigned kQueueHeads = 2 * (kTxEndpoint + 1);
constexpr unsigned kNotifyPacket = 16;
constexpr unsigned kControlPacket = 64;
/// dQH index and ENDPTPRIME/ENDPTCOMPLETE bit of an endpoint direction.
constexpr unsigned queue(unsigned endpoint, bool in) { return 2 * endpoint + (in ? 1 : 0); }
constexpr uint32_t queue_bit(unsigned q) { return 1u << (q / 2 + ((q & 1) ? 16 : 0)); }

/// Device endpoint queue head (RM ch. 42, "Endpoint Queue Head"): 48 bytes the controller
/// uses, padded to the 64 bytes between heads. The controller writes it: volatile.
struct QueueHead {
  volatile uint32_t config;   // MULT 31:30, ZLT 29, max packet 26:16, IOS 15
  volatile uint32_t current;  // the dTD in progress
  volatile uint32_t next;     // overlay: next dTD, T bit 0
  volatile uint32_t token;    // overlay: total bytes 30:16, IOC 15, status 7:0
  volatile uint32_t page[5];
  volatile uint32_t reserved;
  volatile uint32_t setup[2];  // the last setup packet
  uint32_t unused[4];
};
static_assert(sizeof(QueueHead) == 64, "dQHs are 64 bytes apart");

/// Device transfer descriptor (RM ch. 42, "Endpoint Transfer Descriptor"), 32-byte aligned.
struct alignas(32) TransferDescriptor {
  volatile uint32_t next;
  volatile uint32_t token;
  volatile uint32_t page[5];
  uint32_t unused;
};
constexpr uint32_t kTokenActive = 1u << 7, kTokenIoc = 1u << 15;
constexpr uint32_t kConfigIos = 1u << 15, kConfigNoZlt = 1u << 29;

extern QueueHead queue_heads[kQueueHeads];

/// Points `q`'s dQH at `td` describing `length` bytes at `buffer` and primes it. Context: the
/// USB interrupt, or thread with the USB interrupt disabled.
void prime(unsigned q, TransferDescriptor& td, const volatile void* buffer, uint32_t length, bool interrupt);
/// True when the last bus reset ended at high speed.
inline bool high_speed() { return (usb(kPortSc1) & kPortHighSpeed) != 0; }

// ---- Control endpoint (usb_serial_control.cpp) ---------------------------------------------
/// Handles a setup packet (USB 2.0 §9.4, PSTN 1.2 §6.3). Context: USB interrupt.
void control_setup(const uint8_t request[8]);
/// Handles endpoint 0 completions (ENDPTCOMPLETE bits 0 and 16). Context: USB interrupt.
void control_complete(uint32_t complete);

// ---- Descriptors (usb_serial_descriptors.cpp) ----------------------------------------------
/// The descriptor GET_DESCRIPTOR(`value`, `index`) asks for, or null; its length in `length`.
/// Configurations come in the current bus speed's variant.
const uint8_t* descriptor(uint16_t value, uint16_t index, uint16_t& length);

// ---- The serial's data side (usb_serial.cpp) -----------------------------------------------
/// SET_CONFIGURATION: enables the endpoints and starts receiving. Context: USB interrupt.
void configure_serial();
/// Bus reset: forgets the configuration. Context: USB interrupt.
void reset_serial();
/// CDC control line state (PSTN 1.2 table 18: bit 0 DTR, bit 1 RTS).
void set_line_state(uint16_t state);

}  // namespace stand_in_usb
