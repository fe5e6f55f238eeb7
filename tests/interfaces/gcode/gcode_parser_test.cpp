// Syntax checks of the G-code line parser against Grbl 1.1's documented error numbers.
#include "stepdance/interfaces/gcode/gcode_parser.hpp"

#include <gtest/gtest.h>

#include <string.h>

namespace stepdance::gcode {
namespace {

GrblError parse(const char* text, GcodeBlock& block, ParserOptions options = {}) {
  return parse_line(text, strlen(text), block, options);
}

GrblError parse(const char* text) {
  GcodeBlock block;
  return parse(text, block);
}

TEST(GcodeParser, ReadsWordsCaseInsensitivelyWithCommentsAndBlanks) {
  GcodeBlock block;
  ASSERT_EQ(parse("g1 x1.5 (move) Y -2 ; rest ignored Z9\r", block), GrblError::kOk);
  EXPECT_TRUE(block.has_g(GGroup::kMotion));
  EXPECT_EQ(block.g_code(GGroup::kMotion), 10);
  EXPECT_DOUBLE_EQ(block.word('X'), 1.5);
  EXPECT_DOUBLE_EQ(block.word('Y'), -2.0);
  EXPECT_FALSE(block.has_word('Z'));
}

TEST(GcodeParser, KeepsDecimalCommandsApart) {
  GcodeBlock block;
  ASSERT_EQ(parse("G92.1", block), GrblError::kOk);
  EXPECT_EQ(block.g_code(GGroup::kNonModal), 921);
  ASSERT_EQ(parse("G28.1", block), GrblError::kOk);
  EXPECT_EQ(block.g_code(GGroup::kNonModal), 281);
}

TEST(GcodeParser, EmptyCommentOnlyAndPercentLinesAreAccepted) {
  GcodeBlock block;
  EXPECT_EQ(parse("", block), GrblError::kOk);
  EXPECT_EQ(block.words_present, 0u);
  EXPECT_EQ(parse("   (just a comment)  ", block), GrblError::kOk);
  EXPECT_EQ(parse("%", block), GrblError::kOk);
  EXPECT_EQ(parse("\r", block), GrblError::kOk);
}

TEST(GcodeParser, SyntaxErrorsUseGrblNumbers) {
  EXPECT_EQ(parse("1 X2"), GrblError::kExpectedCommandLetter);
  EXPECT_EQ(parse("G1 X"), GrblError::kBadNumberFormat);
  EXPECT_EQ(parse("G1 X1.2.3"), GrblError::kExpectedCommandLetter);  // second '.' starts no word
  EXPECT_EQ(parse("G1 X-"), GrblError::kBadNumberFormat);
  EXPECT_EQ(parse("F-100"), GrblError::kNegativeValue);
  EXPECT_EQ(parse("N10000001 G1"), GrblError::kInvalidLineNumber);
  EXPECT_EQ(parse("N10000000 G1"), GrblError::kOk);  // Grbl's MAX_LINE_NUMBER is allowed
  EXPECT_EQ(parse("T256"), GrblError::kToolNumberTooLarge);
  EXPECT_EQ(parse("G1 G0 X1"), GrblError::kModalGroupViolation);
  EXPECT_EQ(parse("G90 G91"), GrblError::kModalGroupViolation);
  EXPECT_EQ(parse("M3 M5"), GrblError::kModalGroupViolation);
  EXPECT_EQ(parse("G4 G53 P1"), GrblError::kModalGroupViolation);
  EXPECT_EQ(parse("X1 X2"), GrblError::kRepeatedWord);
  EXPECT_EQ(parse("G1 A5"), GrblError::kUnsupportedCommand);
  EXPECT_EQ(parse("G5"), GrblError::kUnsupportedCommand);
  EXPECT_EQ(parse("G38.2 Z-5"), GrblError::kUnsupportedCommand);
  EXPECT_EQ(parse("G1.5 X1"), GrblError::kCommandNeedsInteger);
  EXPECT_EQ(parse("G59.1"), GrblError::kUnsupportedCoordinateSystem);
  EXPECT_EQ(parse("M6"), GrblError::kUnsupportedCommand);
}

TEST(GcodeParser, PrinterHousekeepingIsAcceptedOnlyWhenEnabled) {
  GcodeBlock block;
  ASSERT_EQ(parse("M104 S215 ; hotend", block), GrblError::kOk);
  EXPECT_TRUE(block.printer_housekeeping);
  EXPECT_EQ(block.words_present, 0u);
  ASSERT_EQ(parse("M862.3 P \"MK3S\"", block), GrblError::kOk);
  EXPECT_TRUE(block.printer_housekeeping);
  ASSERT_EQ(parse("M83", block), GrblError::kOk);
  EXPECT_EQ(block.m_code(MGroup::kExtruder), 830);
  ParserOptions strict;
  strict.accept_printer_codes = false;
  EXPECT_EQ(parse("M104 S215", block, strict), GrblError::kUnsupportedCommand);
  EXPECT_EQ(parse("M83", block, strict), GrblError::kUnsupportedCommand);
}

// A housekeeping M code takes the words after it as its own parameters (M106 S255, M117's text);
// the words before it are the line's and run. A G or M command after it would be taken for a
// parameter and lost, so the line is refused (error:20) instead.
TEST(GcodeParser, WordsBeforeAHousekeepingCodeStayInTheBlock) {
  GcodeBlock block;
  ASSERT_EQ(parse("G1 X10 M106", block), GrblError::kOk);
  EXPECT_TRUE(block.printer_housekeeping);
  EXPECT_EQ(block.g_code(GGroup::kMotion), 10);
  ASSERT_TRUE(block.has_word('X'));
  EXPECT_DOUBLE_EQ(block.word('X'), 10.0);
  ASSERT_EQ(parse("G1 X10 F600 M106 S255", block), GrblError::kOk);
  EXPECT_FALSE(block.has_word('S'));  // the fan's speed, not the spindle's
  EXPECT_DOUBLE_EQ(block.word('F'), 600.0);
  ASSERT_EQ(parse("M117 G1 done", block), GrblError::kOk);  // a message: its text is free
  EXPECT_EQ(block.g_groups_present, 0);
  EXPECT_EQ(parse("M104 S200 G1 X10"), GrblError::kUnsupportedCommand);
  EXPECT_EQ(parse("M106 S255 M3"), GrblError::kUnsupportedCommand);
}

TEST(GcodeParser, HugeNumbersAreRefusedNotOverflowed) {
  char text[400] = "G1 X";
  for (size_t i = strlen(text); i < sizeof(text) - 1; ++i) text[i] = '9';
  text[sizeof(text) - 1] = '\0';
  EXPECT_EQ(parse(text), GrblError::kBadNumberFormat);
}

}  // namespace
}  // namespace stepdance::gcode
