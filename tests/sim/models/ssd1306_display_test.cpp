// Ssd1306Display: control bytes, the addressing modes and the picture, from the datasheet's
// description of each command; and text read back off the picture.
#include "models/ssd1306_display.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "stepdance/qwiic/font_5x7.hpp"

namespace stepdance::sim {
namespace {

using Bytes = std::vector<uint8_t>;

// Display on, charge pump on, segment and COM remapped (the SparkFun board's upright image).
const Bytes kPowerOn = {0x00, 0x8D, 0x14, 0xA1, 0xC8, 0xAF};

void send(Ssd1306Display& oled, const Bytes& bytes) { ASSERT_TRUE(oled.write(0, bytes.data(), bytes.size())); }

TEST(Ssd1306Display, DarkUntilTheDisplayAndChargePumpAreOn) {
  Ssd1306Display oled;
  send(oled, {0x00, 0x20, 0x00, 0x21, 0, 127, 0x22, 0, 3});
  send(oled, {0x40, 0xFF});
  EXPECT_FALSE(oled.image().at(0, 0));
  send(oled, kPowerOn);
  EXPECT_TRUE(oled.image().at(0, 0));
  EXPECT_TRUE(oled.image().at(0, 7));
  EXPECT_FALSE(oled.image().at(0, 8));
}

TEST(Ssd1306Display, HorizontalAddressingWrapsToTheNextPageOfTheWindow) {
  Ssd1306Display oled;
  send(oled, kPowerOn);
  // Window: columns 10..11, pages 1..2; four bytes fill (10,p1) (11,p1) (10,p2) (11,p2).
  send(oled, {0x00, 0x20, 0x00, 0x21, 10, 11, 0x22, 1, 2});
  send(oled, {0x40, 0x01, 0x02, 0x04, 0x80});
  const OledImage picture = oled.image();
  EXPECT_TRUE(picture.at(10, 8));   // page 1, bit 0
  EXPECT_TRUE(picture.at(11, 9));   // page 1, bit 1
  EXPECT_TRUE(picture.at(10, 18));  // page 2, bit 2
  EXPECT_TRUE(picture.at(11, 23));  // page 2, bit 7
  int lit = 0;
  for (bool pixel : picture.lit) lit += pixel ? 1 : 0;
  EXPECT_EQ(lit, 4);
}

TEST(Ssd1306Display, PageAddressingAndContinuationControlBytes) {
  Ssd1306Display oled;
  send(oled, kPowerOn);
  // Page mode (20h 02h), page 3 (B3h), column 0x25 (05h then 12h); Co = 1 control bytes take one
  // byte each: 80h command, C0h data.
  send(oled, {0x80, 0x20, 0x80, 0x02, 0x80, 0xB3, 0x80, 0x05, 0x80, 0x12, 0xC0, 0x10});
  EXPECT_TRUE(oled.image().at(0x25, 3 * 8 + 4));
}

TEST(Ssd1306Display, WithoutRemapsTheImageIsMirrored) {
  Ssd1306Display oled;
  send(oled, {0x00, 0x8D, 0x14, 0xAF, 0x20, 0x00, 0x21, 0, 127, 0x22, 0, 3});
  send(oled, {0x40, 0x01});  // RAM column 0, row 0
  EXPECT_TRUE(oled.image().at(127, 31));
}

TEST(Ssd1306Display, InversionAndBadControlByte) {
  Ssd1306Display oled;
  send(oled, kPowerOn);
  send(oled, {0x00, 0xA7});
  EXPECT_TRUE(oled.image().at(64, 16));
  const Bytes bad = {0x01, 0xAE};  // low six bits of a control byte must be 0
  EXPECT_FALSE(oled.write(0, bad.data(), bad.size()));
}

TEST(Ssd1306Display, TextRowsReadTheFontBack) {
  Ssd1306Display oled;
  send(oled, kPowerOn);
  send(oled, {0x00, 0x20, 0x00, 0x21, 0, 127, 0x22, 2, 2});
  Bytes row = {0x40};
  for (char c : std::string("HI 7.5")) {
    const uint8_t* glyph = font5x7::glyph(c);
    row.insert(row.end(), glyph, glyph + 5);
    row.push_back(0);
  }
  send(oled, row);
  const std::vector<std::string> rows = oled.text_rows();
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0], "");
  EXPECT_EQ(rows[2], "HI 7.5");
}

TEST(Ssd1306Display, SnapshotsHoldTheScreenAsOfTheirTime) {
  Ssd1306Display oled;
  oled.set_snapshot_times({from_seconds(2.0), from_seconds(1.0)});
  send(oled, kPowerOn);
  const Bytes pixel = {0x40, 0x01};
  ASSERT_TRUE(oled.write(from_seconds(1.5), pixel.data(), pixel.size()));
  oled.finish();
  ASSERT_EQ(oled.snapshots().size(), 2u);
  EXPECT_EQ(oled.snapshots()[0].first, from_seconds(1.0));
  EXPECT_FALSE(oled.snapshots()[0].second.at(0, 0));
  EXPECT_TRUE(oled.snapshots()[1].second.at(0, 0));
}

}  // namespace
}  // namespace stepdance::sim
