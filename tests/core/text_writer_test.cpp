// TextWriter's number printers: fixed() (G-code, EBB) and significant() (RPC), expected values
// worked out by hand from each one's documented rule.
#include "stepdance/core/text_writer.hpp"

#include <gtest/gtest.h>

#include <math.h>

#include <stdlib.h>

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
  EXPECT_EQ(fixed(-0.0004, 3), "0.000");  // no "-0.000"
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
  EXPECT_EQ(significant(0.001, 9), "0.001");       // plain down to 0.001 …
  EXPECT_EQ(significant(0.000999, 9), "9.99e-4");  // … an exponent below
  EXPECT_EQ(significant(9.9999999995, 9), "10");
  EXPECT_EQ(significant(1000000000.5, 9), "1000000001");  // whole digits kept from 10^9 up
  EXPECT_EQ(significant(-12345678901234.5, 9), "-12345678901235");
  EXPECT_EQ(significant(3.14159, 3), "3.14");
  EXPECT_EQ(significant(0.012345, 3), "0.0123");
  EXPECT_EQ(significant(2.5e20, 3), "2.5e20");
  EXPECT_EQ(significant(4.9406564584124654e-324, 9), "4.94065646e-324");  // 2^-1074, subnormal
}

// A mantissa that rounds up to 10 moves the number to the next power of ten: the text is that
// power ("1e21", never "10e20"), and at the two form boundaries it takes the form the power
// calls for (10^-3 plain, 10^15 with an exponent). Expected texts: the value rounded by hand.
TEST(TextWriterSignificant, MantissaRoundedUpToTenCarriesIntoTheExponent) {
  EXPECT_EQ(significant(9.9999999996e20, 9), "1e21");
  EXPECT_EQ(significant(9.99999951e20, 7), "1e21");
  EXPECT_EQ(significant(-9.99999951e-5, 7), "-1e-4");
  EXPECT_EQ(significant(9.6e-5, 1), "1e-4");
  EXPECT_EQ(significant(9.96e-300, 2), "1e-299");
  EXPECT_EQ(significant(9.99999995e-9, 9), "9.99999995e-9");  // nine digits: nothing to carry
}

TEST(TextWriterSignificant, RoundingAcrossAFormBoundaryTakesTheNewForm) {
  EXPECT_EQ(significant(0.00099999999, 6), "0.001");  // 9.9999999e-4 → 1.00000e-3: plain
  EXPECT_EQ(significant(-0.0009996, 3), "-0.001");
  EXPECT_EQ(significant(0.00099949, 3), "9.99e-4");        // rounds down: stays below 10^-3
  EXPECT_EQ(significant(999999999999999.875, 9), "1e15");  // 10^15 − 1/8 → 10^15: exponent
  EXPECT_EQ(significant(-999999999999999.5, 9), "-1e15");
  EXPECT_EQ(significant(999999999999999.0, 9), "999999999999999");  // whole: every digit
}

// Independent check over every digit count and the values just below each power of ten from
// 10^-320 to 10^300 (where the carries happen) and just above it: glibc's strtod reads the text
// back, which must lie within half a unit of the last significant digit of the value; an exponent
// form must have one leading digit 1..9; the form must be the one the printed value calls for.
void expect_well_formed(double value, uint8_t digits) {
  const std::string text = significant(value, digits);
  const double back = strtod(text.c_str(), nullptr);
  int power = static_cast<int>(floor(log10(fabs(value))));
  while (pow(10.0, power + 1) <= fabs(value)) ++power;  // log10 can be one off next to a power
  while (pow(10.0, power) > fabs(value)) --power;
  const double unit = pow(10.0, power - digits + 1);
  EXPECT_LE(fabs(back - value), unit * 0.5000001 + fabs(value) * 1e-15) << value << " → " << text;
  const size_t e = text.find('e');
  const bool exponent_form = e != std::string::npos;
  const double printed = fabs(back);
  EXPECT_EQ(exponent_form, printed < 1e-3 || printed >= 1e15) << value << " → " << text;
  if (!exponent_form) return;
  const size_t first = text[0] == '-' ? 1 : 0;
  EXPECT_TRUE(text[first] >= '1' && text[first] <= '9' && (e == first + 1 || text[first + 1] == '.'))
      << value << " → " << text;
  const size_t shown_digits = e - first - (e == first + 1 ? 0 : 1);
  EXPECT_LE(shown_digits, digits) << value << " → " << text;
}

TEST(TextWriterSignificant, EveryDigitCountAroundEveryPowerOfTenReadsBackRight) {
  for (uint8_t digits = 1; digits <= 9; ++digits) {
    for (int power = -320; power <= 300; ++power) {
      const double ten = power < -300 ? 1e-300 * pow(10.0, power + 300) : pow(10.0, power);
      for (const double factor : {0.9999999999, 0.99999, 0.996, 0.95, 1.0000001, 1.5}) {
        const double value = ten * factor;
        if (value == floor(value) && value < 1e15) continue;  // whole numbers: printed in full
        expect_well_formed(value, digits);
        expect_well_formed(-value, digits);
      }
    }
  }
}

TEST(TextWriterSignificant, NotANumberAndInfinityAsFixedPrintsThem) {
  EXPECT_EQ(significant(NAN, 9), "nan");
  EXPECT_EQ(significant(INFINITY, 9), "inf");
  EXPECT_EQ(significant(-INFINITY, 9), "-inf");
}

}  // namespace
}  // namespace stepdance
