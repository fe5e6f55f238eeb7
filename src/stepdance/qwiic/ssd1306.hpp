// SSD1306 OLED controller: the command bytes and I2C control bytes our driver sends, named after
// the controller datasheet's command table (Solomon Systech SSD1306, section 9 and 10).
#pragma once

#include <stdint.h>

namespace stepdance::ssd1306 {

// ---- I2C control byte (datasheet 8.1.5.2): Co = bit 7, D/C# = bit 6 ----------------------------
/// Every following byte of the transfer is a command (Co = 0, D/C# = 0).
constexpr uint8_t kControlCommands = 0x00;
/// Every following byte of the transfer is display RAM data (Co = 0, D/C# = 1).
constexpr uint8_t kControlData = 0x40;

// ---- Fundamental commands (10.1) ---------------------------------------------------------------
constexpr uint8_t kSetContrast = 0x81;    ///< + 1 byte: 0..255
constexpr uint8_t kFollowRam = 0xA4;      ///< output follows the display RAM
constexpr uint8_t kNormalDisplay = 0xA6;  ///< lit pixel = RAM bit 1 (0xA7 inverts)
constexpr uint8_t kDisplayOff = 0xAE;
constexpr uint8_t kDisplayOn = 0xAF;
// ---- Scrolling (10.2) --------------------------------------------------------------------------
constexpr uint8_t kDeactivateScroll = 0x2E;
// ---- Addressing (10.3) -------------------------------------------------------------------------
constexpr uint8_t kSetAddressingMode = 0x20;  ///< + 1 byte: 0 horizontal, 1 vertical, 2 page
constexpr uint8_t kHorizontalAddressing = 0x00;
constexpr uint8_t kSetColumnRange = 0x21;  ///< + start column, end column (0..127)
constexpr uint8_t kSetPageRange = 0x22;    ///< + start page, end page (0..7)
// ---- Hardware configuration (10.4) -------------------------------------------------------------
constexpr uint8_t kStartLineZero = 0x40;     ///< 0x40 | line (0..63)
constexpr uint8_t kSegmentRemap = 0xA1;      ///< column 127 drives SEG0
constexpr uint8_t kSetMultiplex = 0xA8;      ///< + 1 byte: rows − 1
constexpr uint8_t kComScanReversed = 0xC8;   ///< scan COM[N−1] to COM0
constexpr uint8_t kSetDisplayOffset = 0xD3;  ///< + 1 byte: vertical shift
constexpr uint8_t kSetComPins = 0xDA;        ///< + 1 byte: 0x02 sequential, no remap (32 rows)
// ---- Timing and driving (10.5) -----------------------------------------------------------------
constexpr uint8_t kSetClock = 0xD5;         ///< + 1 byte: oscillator (high nibble), divide − 1
constexpr uint8_t kSetPrecharge = 0xD9;     ///< + 1 byte: phase 2 (high nibble), phase 1 (low)
constexpr uint8_t kSetVcomDeselect = 0xDB;  ///< + 1 byte: 0x40 (about 0.89 × Vcc on most panels)
// ---- Charge pump (application note, command 8Dh) -----------------------------------------------
constexpr uint8_t kChargePump = 0x8D;  ///< + 0x14 on, 0x10 off
constexpr uint8_t kChargePumpOn = 0x14;

}  // namespace stepdance::ssd1306
