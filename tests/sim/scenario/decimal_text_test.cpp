// The command line's one number grammar: decimal text and nothing around it.
#include "scenario/decimal_text.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "scenario/value_range.hpp"

namespace stepdance::sim::scenario {
namespace {

TEST(DecimalTextTest, PlainDecimalsRead) {
  EXPECT_EQ(parse_decimal("2"), 2.0);
  EXPECT_EQ(parse_decimal("-2.5"), -2.5);
  EXPECT_EQ(parse_decimal("+.5"), 0.5);
  EXPECT_EQ(parse_decimal("3."), 3.0);
  EXPECT_EQ(parse_decimal("1e-3"), 0.001);
  EXPECT_EQ(parse_decimal("25E+1"), 250.0);
  EXPECT_EQ(parse_decimal("007"), 7.0);
}

TEST(DecimalTextTest, WhatStrtodTakesButAUserDidNotMeanIsRefused) {
  // strtod reads "0x10" as 16 and "0x2" as 2, skips leading blanks and stops at trailing ones.
  for (const char* text : {"0x10", "0x2", " 2",  "1 ",    "\t3",   "2\n", "",    "+",   "-",        ".",     "e3",
                           "1e",   "1e+", "1,5", "1_000", "1.2.3", "2s",  "0b1", "--2", "infinite", "nan(1)"}) {
    EXPECT_FALSE(parse_decimal(text).has_value()) << "'" << text << "'";
  }
}

TEST(DecimalTextTest, NonFiniteWordsAreReadSoTheRangeCanRefuseThem) {
  EXPECT_TRUE(std::isnan(*parse_decimal("nan")));
  EXPECT_TRUE(std::isnan(*parse_decimal("NaN")));
  EXPECT_EQ(*parse_decimal("-inf"), -INFINITY);
  EXPECT_EQ(*parse_decimal("Infinity"), INFINITY);
  EXPECT_EQ(*parse_decimal("1e999"), INFINITY);  // beyond a double
  EXPECT_EQ(*parse_decimal("1e-999"), 0.0);      // below its smallest
}

TEST(DecimalTextTest, IntegersAreDigitsOnly) {
  EXPECT_EQ(parse_decimal_integer("8001"), 8001);
  EXPECT_EQ(parse_decimal_integer("-12"), -12);
  EXPECT_EQ(parse_decimal_integer("9223372036854775807"), INT64_MAX);
  for (const char* text : {"9223372036854775808", "0x10", " 1", "1 ", "1.0", "1e3", "", "+", "nan"}) {
    EXPECT_FALSE(parse_decimal_integer(text).has_value()) << "'" << text << "'";
  }
}

TEST(NumberOptionTest, MessagesNameTheOptionAndTheRange) {
  std::string error;
  EXPECT_FALSE(parse_number_option("--speed", "nan", ranges::kServeSpeed, error));
  EXPECT_EQ(error, "--speed: must be in [0.001, 1,000] x real time, got nan");
  EXPECT_FALSE(parse_number_option("--duration", "0x10", ranges::kDurationS, error));
  EXPECT_EQ(error, "--duration: '0x10' is not a decimal number (allowed: [1e-09, 86,400] s)");
  EXPECT_FALSE(parse_number_option("--duration", "1e-300", ranges::kDurationS, error));
  EXPECT_EQ(error, "--duration: must be in [1e-09, 86,400] s, got 1e-300");
  EXPECT_EQ(parse_number_option("--duration", "1e-9", ranges::kDurationS, error), 1e-9);
  EXPECT_FALSE(parse_integer_option("--port", "65536", ranges::kTcpPort, error));
  EXPECT_EQ(error, "--port: must be in [0, 65,535], got 65536");
  EXPECT_FALSE(parse_integer_option("--port", "0x1f41", ranges::kTcpPort, error));
  EXPECT_EQ(error, "--port: '0x1f41' is not a whole decimal number (allowed: [0, 65,535])");
}

}  // namespace
}  // namespace stepdance::sim::scenario
