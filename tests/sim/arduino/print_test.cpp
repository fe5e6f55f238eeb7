// Print formatting, byte for byte: integers in every base, floats, text, println and printf.
#include <gtest/gtest.h>

#include <limits.h>
#include <math.h>

#include <string>

#include "arduino_fixture.hpp"

namespace {

using stepdance::test_support::CapturePrint;

// Prints one value and returns exactly what was written, checking the returned byte count.
template <typename... Args>
std::string printed(Args... args) {
  CapturePrint out;
  const size_t count = out.print(args...);
  EXPECT_EQ(count, out.text.size());
  return out.text;
}

TEST(PrintTest, IntegersInDecimal) {
  EXPECT_EQ(printed(0), "0");
  EXPECT_EQ(printed(42), "42");
  EXPECT_EQ(printed(-42), "-42");
  EXPECT_EQ(printed(42u), "42");
  EXPECT_EQ(printed(INT_MAX), "2147483647");
  EXPECT_EQ(printed(INT_MIN), "-2147483648");
  EXPECT_EQ(printed(UINT_MAX), "4294967295");
  EXPECT_EQ(printed(-1L), "-1");
  EXPECT_EQ(printed(LLONG_MIN), "-9223372036854775808");
  EXPECT_EQ(printed(ULLONG_MAX), "18446744073709551615");
  EXPECT_EQ(printed(static_cast<int16_t>(-300)), "-300");
  EXPECT_EQ(printed(static_cast<int8_t>(-5)), "-5");     // signed char promotes to int: a number
  EXPECT_EQ(printed(static_cast<uint8_t>(200)), "200");  // uint8_t is a number, not a character
  EXPECT_EQ(printed(static_cast<uint32_t>(3000000000u)), "3000000000");
}

TEST(PrintTest, IntegersInOtherBases) {
  EXPECT_EQ(printed(255, HEX), "FF");
  EXPECT_EQ(printed(255, BIN), "11111111");
  EXPECT_EQ(printed(8, OCT), "10");
  EXPECT_EQ(printed(0, HEX), "0");
  EXPECT_EQ(printed(35, 36), "Z");
  EXPECT_EQ(printed(static_cast<uint8_t>(0xA5), HEX), "A5");
  // Negative numbers in another base: the two's complement of the argument's type.
  EXPECT_EQ(printed(-1, HEX), "FFFFFFFF");
  EXPECT_EQ(printed(-2L, HEX), "FFFFFFFFFFFFFFFE");
  // Base 1 (and anything above 36) falls back to decimal; base 0 writes the byte itself.
  EXPECT_EQ(printed(35, 1), "35");
  EXPECT_EQ(printed(35, 37), "35");
  EXPECT_EQ(printed(65, 0), "A");
  EXPECT_EQ(printed(static_cast<uint8_t>(66), 0), "B");
}

TEST(PrintTest, CharactersBooleansAndText) {
  EXPECT_EQ(printed('A'), "A");
  EXPECT_EQ(printed(true), "1");
  EXPECT_EQ(printed(false), "0");
  EXPECT_EQ(printed("motion"), "motion");
  EXPECT_EQ(printed(F("flash text")), "flash text");
  EXPECT_EQ(printed(String("a String")), "a String");
  EXPECT_EQ(printed(static_cast<const char*>(nullptr)), "");
}

TEST(PrintTest, FloatsHaveTwoDigitsByDefault) {
  EXPECT_EQ(printed(3.14159), "3.14");
  EXPECT_EQ(printed(2.5f), "2.50");
  EXPECT_EQ(printed(-1.25), "-1.25");
  EXPECT_EQ(printed(0.0), "0.00");
  EXPECT_EQ(printed(1.996), "2.00");  // rounds, carrying into the integer part
  EXPECT_EQ(printed(1e10), "10000000000.00");
}

TEST(PrintTest, FloatsWithChosenDigits) {
  EXPECT_EQ(printed(1.23456, 4), "1.2346");
  EXPECT_EQ(printed(1.23456, 1), "1.2");
  EXPECT_EQ(printed(2.4, 0), "2");  // no decimal point at all
  EXPECT_EQ(printed(-7.0, 3), "-7.000");
  EXPECT_EQ(printed(0.1f, 8), "0.10000000");  // float 0.1 is 0.100000001490116…
  EXPECT_EQ(printed(1.5, -3), "2");           // negative digits count as 0
}

TEST(PrintTest, FloatSignsAndSpecialValues) {
  EXPECT_EQ(printed(-0.0), "0.00");     // negative zero prints unsigned, as on the board
  EXPECT_EQ(printed(-0.001), "-0.00");  // a small negative value keeps its sign
  EXPECT_EQ(printed(NAN), "nan");
  EXPECT_EQ(printed(INFINITY), "inf");
  EXPECT_EQ(printed(-INFINITY), "-inf");
}

TEST(PrintTest, PrintlnEndsLinesWithCarriageReturnNewline) {
  CapturePrint out;
  EXPECT_EQ(out.println("abc"), 5u);
  EXPECT_EQ(out.println(), 2u);
  EXPECT_EQ(out.println(-12), 5u);
  EXPECT_EQ(out.println(42, HEX), 4u);
  EXPECT_EQ(out.println(1.5, 3), 7u);
  EXPECT_EQ(out.println('x'), 3u);
  EXPECT_EQ(out.text, "abc\r\n\r\n-12\r\n2A\r\n1.500\r\nx\r\n");
}

TEST(PrintTest, WriteSendsRawBytes) {
  CapturePrint out;
  EXPECT_EQ(out.write(0), 1u);  // an integer writes one byte, here NUL
  EXPECT_EQ(out.write('Z'), 1u);
  EXPECT_EQ(out.write("hi"), 2u);
  const uint8_t bytes[3] = {1, 2, 3};
  EXPECT_EQ(out.write(bytes, 3), 3u);
  EXPECT_EQ(out.write(static_cast<uint8_t>(0x141 & 0xFF)), 1u);
  EXPECT_EQ(out.text, std::string("\0Zhi\1\2\3A", 8));
}

TEST(PrintTest, PrintfFormatsShortAndLongText) {
  CapturePrint out;
  EXPECT_EQ(out.printf("x=%d y=%.1f %s", 7, 2.25, "ok"), 12);
  EXPECT_EQ(out.take(), "x=7 y=2.2 ok");  // printf rounds 2.25 to even, as the C library does
  const std::string long_text(300, 'q');
  EXPECT_EQ(out.printf("[%s]", long_text.c_str()), 302);
  EXPECT_EQ(out.take(), "[" + long_text + "]");
}

}  // namespace
