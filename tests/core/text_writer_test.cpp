// TextWriter's number printers: fixed() (G-code, EBB) and significant() (RPC), expected values
// worked out by hand from each one's documented rule.
#include "stepdance/core/text_writer.hpp"

#include <gtest/gtest.h>

#include <math.h>

#include <string>

namespace stepdance {
namespace {

std::string fixed(double value, uint8_t decimals) {
  char storage[64];
  TextWriter out(storage, sizeof(storage));
  out.fixed(value, decimals);
  return out.c_str();
}

std::string significant(double value, uint8_t digits) {
  char storage[64];
  TextWriter out(storage, sizeof(storage));
  out.significant(value, digits);
  return out.c_str();
}

TEST(TextWriterFixed, RoundsToItsDecimalsAndKeepsTheirZeros) {
  EXPECT_EQ(fixed(1.5, 3), "1.500");
  EXPECT_EQ(fixed(-0.0625, 3), "-0.063");  // half away from zero
  EXPECT_EQ(fixed(2.0004, 3), "2.000");
  EXPECT_EQ(fixed(-0.0004, 3), "0.000");   // no "-0.000"
  EXPECT_EQ(fixed(0.05, 6), "0.050000");
  EXPECT_EQ(fixed(7, 0), "7");
  EXPECT_EQ(fixed(1e9, 1), "ovf");
  EXPECT_EQ(fixed(NAN, 2), "nan");
  EXPECT_EQ(fixed(-INFINITY, 2), "-inf");
}

TEST(TextWriterSignificant, WholeNumbersBelowTenToTheFifteenInFull) {
  EXPECT_EQ(significant(0, 9), "0");
  EXPECT_EQ(significant(-0.0, 9), "0");
  EXPECT_EQ(significant(-42, 9), "-42");
  EXPECT_EQ(significant(4294967296.0, 9), "4294967296");  // 2^32
  EXPECT_EQ(significant(9007199254740.0, 3), "9007199254740");
  EXPECT_EQ(significant(999999999999999.0, 9), "999999999999999");
  EXPECT_EQ(significant(1000000001000000.0, 9), "1e15");  // from 10^15: significant digits
  EXPECT_EQ(significant(-1.5e15, 9), "-1.5e15");
}

TEST(TextWriterSignificant, OtherNumbersRoundedWithoutTrailingZeros) {
  EXPECT_EQ(significant(123.456789012, 9), "123.456789");
  EXPECT_EQ(significant(-1234.5678, 9), "-1234.5678");
  EXPECT_EQ(significant(0.001, 9), "0.001");  // plain down to 0.001 …
  EXPECT_EQ(significant(0.000999, 9), "9.99e-4");  // … an exponent below
  EXPECT_EQ(significant(9.9999999995, 9), "10");
  EXPECT_EQ(significant(1000000000.5, 9), "1000000001");  // whole digits kept from 10^9 up
  EXPECT_EQ(significant(-12345678901234.5, 9), "-12345678901235");
  EXPECT_EQ(significant(3.14159, 3), "3.14");
  EXPECT_EQ(significant(0.012345, 3), "0.0123");
  EXPECT_EQ(significant(2.5e20, 3), "2.5e20");
  EXPECT_EQ(significant(4.9406564584124654e-324, 9), "4.94065646e-324");  // 2^-1074, subnormal
}

TEST(TextWriterSignificant, NotANumberAndInfinityAsFixedPrintsThem) {
  EXPECT_EQ(significant(NAN, 9), "nan");
  EXPECT_EQ(significant(INFINITY, 9), "inf");
  EXPECT_EQ(significant(-INFINITY, 9), "-inf");
}

}  // namespace
}  // namespace stepdance
