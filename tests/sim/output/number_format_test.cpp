// Number formatting: fixed decimals without "-0", trimmed decimals, integer-exact times.
#include <gtest/gtest.h>

#include <limits>

#include "output/number_format.hpp"

namespace stepdance::sim {
namespace {

TEST(NumberFormat, Fixed) {
  EXPECT_EQ(format_fixed(1.23456, 3), "1.235");
  EXPECT_EQ(format_fixed(-0.0001, 3), "0.000");
  EXPECT_EQ(format_fixed(-0.4, 0), "0");
  EXPECT_EQ(format_fixed(-2.5e-3, 2), "0.00");
  EXPECT_EQ(format_fixed(-1.5, 1), "-1.5");
  EXPECT_EQ(format_fixed(std::numeric_limits<double>::quiet_NaN(), 2), "nan");
  EXPECT_EQ(format_fixed(-std::numeric_limits<double>::infinity(), 2), "-inf");
  EXPECT_EQ(format_fixed(1e300, 17).size(), 319u);
}

TEST(NumberFormat, Trimmed) {
  EXPECT_EQ(format_trimmed(1.5, 3), "1.5");
  EXPECT_EQ(format_trimmed(2.0, 3), "2");
  EXPECT_EQ(format_trimmed(-0.0004, 3), "0");
  EXPECT_EQ(format_trimmed(120, 3), "120");
  EXPECT_EQ(format_trimmed(0.1 + 0.2, 3), "0.3");
}

TEST(NumberFormat, TimeIsIntegerExact) {
  EXPECT_EQ(format_time(1'234'567, kMicrosecond, 3), "1234.567");
  EXPECT_EQ(format_time(1'234'567, kMicrosecond, 5), "1234.56700");
  EXPECT_EQ(format_time(1500, kMicrosecond, 0), "2");
  EXPECT_EQ(format_time(1499, kMicrosecond, 0), "1");
  EXPECT_EQ(format_time(-1500, kMicrosecond, 1), "-1.5");
  EXPECT_EQ(format_time(-1, kMicrosecond, 0), "0");
  EXPECT_EQ(format_time(5, kNanosecond, 2), "5.00");
  EXPECT_EQ(format_time(999'999'999'500, kSecond, 6), "1000.000000");
  EXPECT_EQ(format_time(std::numeric_limits<SimTime>::max(), kSecond, 9), "9223372036.854775807");
  EXPECT_EQ(format_time(std::numeric_limits<SimTime>::min(), kSecond, 9), "-9223372036.854775808");
}

}  // namespace
}  // namespace stepdance::sim
