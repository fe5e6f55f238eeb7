// SparkFun Qwiic Twist (RGB rotary encoder, firmware 1.x): its I2C register map, from SparkFun's
// published register description. Multi-byte registers are little-endian; reads and writes run
// on through consecutive registers.
#pragma once

#include <stdint.h>

namespace stepdance::twist {

constexpr uint8_t kDefaultAddress = 0x3F;
/// The value of kId on a Qwiic Twist.
constexpr uint8_t kIdValue = 0x5C;

constexpr uint8_t kId = 0x00;                ///< 1 byte, read only
constexpr uint8_t kStatus = 0x01;            ///< 1 byte: the bits below; a write replaces bits 0 and 2
constexpr uint8_t kVersion = 0x02;           ///< 2 bytes: firmware major, minor
constexpr uint8_t kEnableInterrupts = 0x04;  ///< 1 byte: the bits below
constexpr uint8_t kCount = 0x05;             ///< int16: detents turned (24 a turn), writable
constexpr uint8_t kDifference = 0x07;        ///< int16: change since it was last cleared (write 0)
constexpr uint8_t kSinceMovementMs = 0x09;   ///< uint16: ms since the knob last moved (write 0)
constexpr uint8_t kSinceButtonMs = 0x0B;     ///< uint16: ms since the last press/release (write 0)
constexpr uint8_t kRed = 0x0D;               ///< 1 byte each: LED brightness 0..255
constexpr uint8_t kGreen = 0x0E;
constexpr uint8_t kBlue = 0x0F;
constexpr uint8_t kConnectRed = 0x10;  ///< int16 each: brightness change per detent
constexpr uint8_t kConnectGreen = 0x12;
constexpr uint8_t kConnectBlue = 0x14;
constexpr uint8_t kTurnInterruptTimeoutMs = 0x16;  ///< uint16: quiet time before a turn interrupt
constexpr uint8_t kChangeAddress = 0x18;           ///< 1 byte: new 7-bit address (stored in EEPROM)

// kStatus bits
constexpr uint8_t kStatusMoved = 1u << 0;  ///< the knob turned since the bit was cleared
constexpr uint8_t kStatusPressed =
    1u << 1;  ///< the button is held (set at the press, cleared at the release; read only)
constexpr uint8_t kStatusClicked = 1u << 2;  ///< a press and release happened since it was cleared
// kEnableInterrupts bits: the INT pin goes low on these events until kStatus is cleared
constexpr uint8_t kInterruptOnTurn = 1u << 0;
constexpr uint8_t kInterruptOnButton = 1u << 1;

}  // namespace stepdance::twist
