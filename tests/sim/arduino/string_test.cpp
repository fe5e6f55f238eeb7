// Arduino's String: building text from numbers, searching, slicing, editing and converting.
#include <gtest/gtest.h>

#include <string>

#include "arduino_fixture.hpp"

namespace {

TEST(StringTest, ConcatenatesTextAndNumbers) {
  String text = "Hello";
  text += ' ';
  text += 42;
  text += ", ";
  text += 1.5;
  EXPECT_EQ(text, "Hello 42, 1.50");
  EXPECT_EQ(text.length(), 14u);
  EXPECT_EQ(String("x") + 5 + 'y' + -2L, "x5y-2");
  EXPECT_EQ("a" + String("b"), "ab");
  EXPECT_EQ(String("n=") + String(7u), "n=7");
}

TEST(StringTest, NumberConstructorsFormatLikePrint) {
  EXPECT_EQ(String(255, HEX), "FF");
  EXPECT_EQ(String(5, BIN), "101");
  EXPECT_EQ(String(-1, HEX), "FFFFFFFF");
  EXPECT_EQ(String(-17), "-17");
  EXPECT_EQ(String(3.14159, 3), "3.142");
  EXPECT_EQ(String(2.5f), "2.50");
  EXPECT_EQ(String('c'), "c");
  EXPECT_EQ(String(static_cast<unsigned char>(200)), "200");
  EXPECT_EQ(String(F("flash")), "flash");
  EXPECT_EQ(String(static_cast<const char*>(nullptr)), "");
}

TEST(StringTest, SearchesAndSlices) {
  const String text = "G1 X10 Y20 X30";
  EXPECT_EQ(text.indexOf('X'), 3);
  EXPECT_EQ(text.indexOf('X', 4), 11);
  EXPECT_EQ(text.indexOf("Y2"), 7);
  EXPECT_EQ(text.indexOf('Q'), -1);
  EXPECT_EQ(text.indexOf("X", 100), -1);
  EXPECT_EQ(text.lastIndexOf('X'), 11);
  EXPECT_EQ(text.lastIndexOf('X', 10), 3);
  EXPECT_EQ(text.lastIndexOf("X"), 11);
  EXPECT_EQ(text.substring(3, 6), "X10");
  EXPECT_EQ(text.substring(6, 3), "X10");  // bounds swapped, as the Arduino core does
  EXPECT_EQ(text.substring(11), "X30");
  EXPECT_EQ(text.substring(50), "");
  EXPECT_TRUE(text.startsWith("G1"));
  EXPECT_TRUE(text.startsWith("X10", 3));
  EXPECT_FALSE(text.startsWith("X10", 30));
  EXPECT_TRUE(text.endsWith("X30"));
  EXPECT_FALSE(text.endsWith("a much longer suffix than the text"));
}

TEST(StringTest, CharactersInAndOutOfRange) {
  String text = "abc";
  EXPECT_EQ(text.charAt(1), 'b');
  EXPECT_EQ(text[2], 'c');
  EXPECT_EQ(text.charAt(9), '\0');
  text[0] = 'A';
  text[9] = 'Z';  // past the end: lost, nothing crashes
  text.setCharAt(1, 'B');
  text.setCharAt(7, 'Q');
  EXPECT_EQ(text, "ABc");
  char buffer[3];
  text.toCharArray(buffer, sizeof buffer);
  EXPECT_STREQ(buffer, "AB");  // size − 1 characters and a NUL
}

TEST(StringTest, EditsInPlace) {
  String text = "  a-b-c \r\n";
  text.trim();
  EXPECT_EQ(text, "a-b-c");
  text.replace('-', '+');
  EXPECT_EQ(text, "a+b+c");
  text.replace("+", "--");
  EXPECT_EQ(text, "a--b--c");
  text.remove(1, 2);
  EXPECT_EQ(text, "ab--c");
  text.remove(2);
  EXPECT_EQ(text, "ab");
  text.toUpperCase();
  EXPECT_EQ(text, "AB");
  text.toLowerCase();
  EXPECT_EQ(text, "ab");
  String blank = " \t ";
  blank.trim();
  EXPECT_TRUE(blank.isEmpty());
}

TEST(StringTest, ComparesAndConverts) {
  EXPECT_TRUE(String("abc").equals("abc"));
  EXPECT_TRUE(String("ABC").equalsIgnoreCase(String("abc")));
  EXPECT_FALSE(String("ABC").equalsIgnoreCase(String("abcd")));
  EXPECT_EQ(String("a").compareTo(String("b")), -1);
  EXPECT_EQ(String("b").compareTo(String("a")), 1);
  EXPECT_TRUE(String("a") < String("b"));
  EXPECT_TRUE(String("a") != "b");
  EXPECT_EQ(String("  -42mm").toInt(), -42);
  EXPECT_EQ(String("none").toInt(), 0);
  EXPECT_FLOAT_EQ(String("2.75").toFloat(), 2.75f);
  EXPECT_DOUBLE_EQ(String("-0.125").toDouble(), -0.125);
}

}  // namespace
