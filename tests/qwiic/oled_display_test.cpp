// OledDisplay: the byte stream of init and of known screens, written out here by hand from the
// SSD1306 datasheet's command table; one transfer per loop pass; a missing display.
#include "stepdance/qwiic/oled_display.hpp"

#include <gtest/gtest.h>

#include "qwiic/qwiic_fixture.hpp"

namespace stepdance {
namespace {

using Bytes = std::vector<uint8_t>;

class OledDisplayTest : public test_support::QwiicFixture {};

// The datasheet's names for these bytes, as the expectation lists them.
const Bytes kExpectedInit = {
    0x00,        // control byte: Co = 0, D/C# = 0, commands follow
    0xAE,        // display off
    0xD5, 0x80,  // clock: divide ratio 1, oscillator setting 8 (the reset value)
    0xA8, 0x1F,  // multiplex ratio 32 (value = rows − 1)
    0xD3, 0x00,  // no display offset
    0x40,        // display start line 0
    0x8D, 0x14,  // charge pump on
    0x20, 0x00,  // horizontal addressing mode
    0xA1,        // segment remap: column address 127 is SEG0
    0xC8,        // COM output scan direction remapped
    0xDA, 0x02,  // COM pins: sequential, no left/right remap (the 128×32 panel)
    0x81, 0x8F,  // contrast
    0xD9, 0xF1,  // pre-charge: phase 1 one clock, phase 2 fifteen
    0xDB, 0x40,  // VCOMH deselect level
    0x2E,        // deactivate scroll
    0xA4,        // output follows RAM
    0xA6,        // normal (not inverted)
    0xAF,        // display on
};

// Column window [first, last] on one page: 21h and 22h with their two bytes each.
Bytes window(uint8_t first, uint8_t last, uint8_t page) { return {0x00, 0x21, first, last, 0x22, page, page}; }

// A data transfer: control byte 40h and 32 bytes, zero except `set` (index, value) pairs.
Bytes data(std::initializer_list<std::pair<int, uint8_t>> set) {
  Bytes bytes(33, 0);
  bytes[0] = 0x40;
  for (const auto& [index, value] : set) bytes[1 + index] = value;
  return bytes;
}

TEST_F(OledDisplayTest, InitSequenceIsTheDatasheetsPowerOnOrder) {
  OledDisplay display;
  ASSERT_EQ(display.begin(QWIIC_1), Status::kOk);
  loop_passes(2);  // the display queues it, the bus starts it
  ASSERT_GE(hal_manual::i2c_log().size(), 1u);
  EXPECT_EQ(hal_manual::i2c_log()[0].address, 0x3C);
  EXPECT_EQ(hal_manual::i2c_log()[0].bus, 1);
  EXPECT_EQ(written(0), kExpectedInit);
  EXPECT_EQ(hal_manual::i2c_clock(1), 400000u);
}

TEST_F(OledDisplayTest, FirstUpdateBlanksEveryChunkPageByPage) {
  OledDisplay display;
  ASSERT_EQ(display.begin(QWIIC_1), Status::kOk);
  loop_passes(40);
  ASSERT_EQ(hal_manual::i2c_log().size(), 33u);
  EXPECT_TRUE(display.up_to_date());
  size_t index = 1;
  for (uint8_t page = 0; page < 4; ++page) {
    for (uint8_t first = 0; first < 128; first += 32) {
      EXPECT_EQ(written(index++), window(first, static_cast<uint8_t>(first + 31), page));
      EXPECT_EQ(written(index++), data({}));
    }
  }
}

TEST_F(OledDisplayTest, KnownScreenSendsOnlyTheChangedChunks) {
  OledDisplay display;
  ASSERT_EQ(display.begin(QWIIC_1), Status::kOk);
  loop_passes(40);
  const size_t before = hal_manual::i2c_log().size();
  // Pixel (5, 10): page 1 (rows 8..15), bit 2, column 5 → chunk 0 of page 1, data byte 5 = 04h.
  display.set_pixel(5, 10, true);
  // Pixel (127, 31): page 3, bit 7, column 127 → last chunk of page 3, byte 31 = 80h.
  display.set_pixel(127, 31, true);
  loop_passes(10);
  ASSERT_EQ(hal_manual::i2c_log().size(), before + 4);
  EXPECT_EQ(written(before), window(0, 31, 1));
  EXPECT_EQ(written(before + 1), data({{5, 0x04}}));
  EXPECT_EQ(written(before + 2), window(96, 127, 3));
  EXPECT_EQ(written(before + 3), data({{31, 0x80}}));
}

TEST_F(OledDisplayTest, TextCellsAreSixColumnsAndAnUnchangedLineSendsNothing) {
  OledDisplay display;
  ASSERT_EQ(display.begin(QWIIC_1), Status::kOk);
  loop_passes(40);
  display.print_line(2, "-");
  // '-' is a bar on row 3 of the glyph (bit 3) across the glyph's five columns, then a blank
  // spacing column; on text row 2 = page 2.
  EXPECT_EQ(display.framebuffer()[2 * 128 + 0], 0x08);
  EXPECT_EQ(display.framebuffer()[2 * 128 + 4], 0x08);
  EXPECT_EQ(display.framebuffer()[2 * 128 + 5], 0x00);
  loop_passes(10);
  const size_t after_first = hal_manual::i2c_log().size();
  display.print_line(2, "-");
  loop_passes(10);
  EXPECT_EQ(hal_manual::i2c_log().size(), after_first);
}

TEST_F(OledDisplayTest, NoLoopPassStartsMoreThanOneBoundedTransfer) {
  OledDisplay display;
  ASSERT_EQ(display.begin(QWIIC_1), Status::kOk);
  for (int pass = 0; pass < 60; ++pass) {
    if (pass == 35) display.print_line(0, "ABCDEFGHIJKLMNOPQRSTU");
    const size_t before = hal_manual::i2c_log().size();
    loop_passes(1);
    const size_t started = hal_manual::i2c_log().size() - before;
    ASSERT_LE(started, 1u) << "pass " << pass;
    if (started == 1) {
      const auto& transfer = hal_manual::i2c_log().back();
      // 400 kHz: (START + STOP + 9 bits × (address + bytes)) × 2.5 µs ≤ 1 ms → ≤ 43 bytes written.
      const double wire_us = (2 + 9.0 * (1 + transfer.written.size())) * 2.5;
      EXPECT_LE(wire_us, 1000.0);
    }
  }
}

TEST_F(OledDisplayTest, MissingDisplayIsReportedOnceAndRetriedEverySecond) {
  hal_manual::i2c_set_responder(
      [](const hal_manual::I2cRecord&, uint8_t*, uint16_t) { return hal::I2cResult::kAddressNack; });
  OledDisplay display;
  ASSERT_EQ(display.begin(QWIIC_1), Status::kOk);
  loop_passes(100);  // 20 ms
  EXPECT_EQ(display.state(), OledDisplay::State::kFailed);
  EXPECT_EQ(display.last_result(), hal::I2cResult::kAddressNack);
  EXPECT_EQ(hal_manual::i2c_log().size(), 1u);
  EXPECT_EQ(hal_manual::take_console_output(),
            "OledDisplay: QWIIC1 address 60: address nack, retrying every second\r\n");
  loop_passes(5000);  // 1 s more
  EXPECT_EQ(hal_manual::i2c_log().size(), 2u);
  EXPECT_EQ(hal_manual::take_console_output(), "");  // the same news is not repeated
  // The display appears: init, then the whole screen.
  hal_manual::i2c_set_responder(nullptr);
  loop_passes(5000);
  EXPECT_EQ(display.state(), OledDisplay::State::kReady);
  EXPECT_TRUE(display.up_to_date());
}

TEST_F(OledDisplayTest, BusErrorMidUpdateResendsEverything) {
  int transfers = 0;
  hal_manual::i2c_set_responder([&transfers](const hal_manual::I2cRecord&, uint8_t*, uint16_t) {
    return ++transfers == 6 ? hal::I2cResult::kBusError : hal::I2cResult::kOk;
  });
  OledDisplay display;
  ASSERT_EQ(display.begin(QWIIC_1), Status::kOk);
  loop_passes(40);
  EXPECT_EQ(display.last_result(), hal::I2cResult::kBusError);
  EXPECT_EQ(display.state(), OledDisplay::State::kFailed);
  loop_passes(5100);
  EXPECT_TRUE(display.up_to_date());
  EXPECT_EQ(written(6), kExpectedInit);
}

}  // namespace
}  // namespace stepdance
