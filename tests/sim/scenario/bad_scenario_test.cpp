// Bad scenario fixtures: each must fail with exactly the listed `file:line: message` errors.
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "scenario/load_scenario.hpp"

namespace stepdance::sim::scenario {
namespace {

const std::string kFixtures = std::string(STEPDANCE_SOURCE_DIR) + "/tests/sim/scenario/fixtures";
const std::string kBad = kFixtures + "/bad";

struct BadCase {
  /// Fixture name under fixtures/bad/ without ".toml".
  std::string name;
  /// Expected errors: (line, message), in line order.
  std::vector<std::pair<int, std::string>> errors;
};

/// Names the case in test listings instead of dumping its bytes.
void PrintTo(const BadCase& bad, std::ostream* out) { *out << bad.name; }

std::vector<BadCase> cases() {
  return {
      {"syntax_error", {{3, "Error while parsing key-value pair: cannot redefine existing integer 'duration_s'"}}},
      {"unknown_key",
       {{1, "the scenario is missing required key 'duration_s'"},
        {2, "unknown key 'durations_s' in the scenario"},
        {7, "unknown key 'loop_period' in [[board]]"}}},
      {"wrong_type", {{7, "'loop_period_us' must be an integer, not a string"}}},
      {"missing_key", {{4, "[[board]] is missing required key 'sketch'"}}},
      {"missing_sketch", {{6, "sketch not found: " + kFixtures + "/sketches/nowhere.ino"}}},
      // An image board may leave out its sketch, but its image must be there.
      {"missing_image", {{6, "firmware image not found: " + kFixtures + "/images/nowhere.elf"}}},
      {"duplicate_board", {{9, "duplicate board name 'driver' (first defined on line 5)"}}},
      {"unknown_board", {{9, "unknown board 'drvier'"}}},
      {"missing_port", {{14, "board 'basic' (basic module) has no output port B"}}},
      {"basic_sockets", {{9, "a basic module has no driver sockets"}}},
      {"negative_time", {{15, "'time_s' must be in [0, 86,400] s, got -1"}}},
      {"time_after_end",
       {{15, "'time_s' = 12 is after the end of the run (duration_s = 10)"},
        {23, "the turn ends at 10.5 s, after the end of the run (duration_s = 10)"}}},
      {"bad_connector",
       {{12,
         "unknown connector 'ENC3' (connectors are ENC1, ENC2, A1..A4, D1, D2, LIMIT_A..LIMIT_D, QWIIC0 and QWIIC1)"}}},
      {"connector_for_type",
       {{13, "a button cannot use connector ENC1 (use D1, D2 or A1..A4)"},
        {15, "a limit_switch needs a [machine] to watch"},
        {19, "board 'basic' (basic module) has no connector LIMIT_A"}}},
      {"missing_serial_file", {{11, "serial file not found: " + kBad + "/missing.gcode"}}},
      {"wrong_device", {{16, "'turn' needs an encoder, but 'pen' is a button"}, {21, "unknown device 'buton'"}}},
      {"machine_socket",
       {{12, "'pen_servo' needs a servo in socket C of board 'driver', but it is empty"},
        {15, "'motor_b' must be a socket letter A..D, got \"E\""}}},
      {"socket_values",
       {{7, "'frame_phase_us' must be in [0, 39] µs, got 40"},
        {10, "'microsteps' must be 1, 2, 4, 8, 16, 32 or 64, got 3"},
        {11, "'build' must be \"90deg\" or \"180deg\", got \"270deg\""},
        {12, "unknown socket 'E' (sockets are A, B, C and D)"}}},
      {"action_shape",
       {{17, "an [[at]] entry takes one action, but has both 'turn' and 'press'"},
        {22, "'hold_ms' does not go with 'press'"},
        {24, "an [[at]] entry needs one action: turn, press, release, click, set or serial"}}},
      {"cables_and_vcd",
       {{14, "input port driver:A already has a cable (line 8)"},
        {18, "'vcd_ports' must look like \"board:OUT_A\" or \"board:IN_A\", got \"driver:A\""}}},
      {"board_as_table", {{4, "'board' must be written as [[board]] tables"}}},
      {"expectations",
       {{12, "an [[expect]] checks one thing, but has both 'motor' and 'strokes'"},
        {15, "'pen_mm' needs a [machine]"},
        {18, "socket B of board 'driver' holds no stepper"}}},
  };
}

class BadScenario : public ::testing::TestWithParam<BadCase> {};

TEST_P(BadScenario, ReportsExactlyTheseErrors) {
  const BadCase& bad = GetParam();
  const std::string file = kBad + "/" + bad.name + ".toml";
  const LoadResult result = load_scenario(file);
  ASSERT_FALSE(result.ok());
  std::vector<std::string> expected;
  for (const auto& [line, message] : bad.errors) expected.push_back(file + ":" + std::to_string(line) + ": " + message);
  std::vector<std::string> actual;
  for (const Diagnostic& error : result.errors) actual.push_back(error.to_string());
  EXPECT_EQ(actual, expected);
}

INSTANTIATE_TEST_SUITE_P(Fixtures, BadScenario, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<BadCase>& param) { return param.param.name; });

TEST(BadScenarioFile, AMissingFileHasNoLine) {
  const LoadResult result = load_scenario(kBad + "/nothing.toml");
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_EQ(result.errors[0].to_string(),
            kBad + "/nothing.toml: cannot read the scenario file (missing or not a file)");
}

TEST(BadScenarioFile, AFolderWithoutScenarioToml) {
  const LoadResult result = load_scenario(kBad);
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_EQ(result.errors[0].to_string(),
            kBad + ": this folder has no scenario.toml");  // and no sibling scenario runs a sketch in it
}

}  // namespace
}  // namespace stepdance::sim::scenario

namespace stepdance::sim::scenario {
namespace {

// Found by fuzz/scenario_fuzz.cpp: toml++ 3.3 asserts on a control character in a table header.
// TOML allows none but tab, LF and CR, so the scenario reader refuses them first.
TEST(BadScenarioText, AControlCharacterIsRefusedWithItsLine) {
  const LoadResult result = parse_scenario(
      "duration_s = 1\n[[\x01"
      "board]]\n",
      "x.toml");
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_EQ(result.errors[0].to_string(), "x.toml:2: control character U+0001 is not allowed in a scenario file");
  EXPECT_TRUE(parse_scenario("duration_s = 1\t# a tab is fine\r\n", "x.toml").ok());
  // Found by the same fuzzer: a CR opening a table header's name ("[[\rexpect]]"). A CR is
  // only allowed before LF, so a lone one is refused wherever it is.
  for (const char* text : {"[[\rexpect]]\n", "x = 1\r", "x = \"\r\"\n"}) {
    const LoadResult lone_cr = parse_scenario(std::string("duration_s = 1\n") + text, "x.toml");
    ASSERT_EQ(lone_cr.errors.size(), 1u) << text;
    EXPECT_EQ(lone_cr.errors[0].to_string(),
              "x.toml:2: a carriage return without a line feed (U+000D) is not allowed in a scenario file");
  }
}

// Found by the same fuzzer: toml++ 3.3 reaches an unreachable point classifying 'µ' outside a
// string. TOML allows non-ASCII text only in comments and strings, where it stays welcome.
TEST(BadScenarioText, NonAsciiOutsideStringsAndCommentsIsRefusedWithItsLine) {
  const LoadResult result = parse_scenario("duration_s = 1\nx = { a = 1, m\xc2\xb5s = 2 }\n", "x.toml");
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_EQ(result.errors[0].to_string(),
            "x.toml:2: a non-ASCII character outside a string or comment is not allowed in a scenario file");
  const LoadResult fine = parse_scenario("# 3 \xc2\xb5s \xe2\x86\x92 X\nduration_s = 1 # \xc2\xb1 0.1\n", "x.toml");
  EXPECT_TRUE(fine.ok()) << fine.error_text();
  const LoadResult quoted = parse_scenario("duration_s = 1\n\"k\\\"\xc2\xb5\" = 'x\xc2\xb5'\n", "x.toml");
  for (const Diagnostic& error : quoted.errors) {
    EXPECT_EQ(error.to_string().find("non-ASCII"), std::string::npos) << error.to_string();
  }
}

// Found by the same fuzzer: toml++ 3.3 asserts on a table header whose name starts with a
// character no key can start with. Lines of a multi-line array that open with '[' stay valid.
TEST(BadScenarioText, ATableHeaderWithoutANameIsRefusedWithItsLine) {
  for (const char* header : {"[^at]]\n", "[[ !board]]\n", "[=x]\n", "[[.02\n", "[+x]\n", "[\n"}) {
    const LoadResult result = parse_scenario(std::string("duration_s = 1\n") + header, "x.toml");
    ASSERT_EQ(result.errors.size(), 1u) << header;
    EXPECT_EQ(result.errors[0].to_string(),
              "x.toml:2: a table header must start with a name (letters, digits, '_', '-' or a quoted key)");
  }
  const LoadResult arrays = parse_scenario("duration_s = 1\nx = [\n  [+1, 2],\n  [.5, 3],\n  [ ]\n]\n", "x.toml");
  for (const Diagnostic& error : arrays.errors) {
    EXPECT_EQ(error.to_string().find("table header"), std::string::npos) << error.to_string();
  }
}

// Found by the same fuzzer: toml++ 3.3 asserts on '}' where an array expects a value (after '['
// or ',', whitespace, line breaks or comments between). Braces in strings and comments, and
// inline tables in arrays, stay valid.
TEST(BadScenarioText, ABraceWhereAnArrayValueBelongsIsRefusedWithItsLine) {
  const std::pair<const char*, int> cases[] = {
      {"x = [}]\n", 2}, {"x = [1,}]\n", 2}, {"x = [1, # c\n }]\n", 3}, {"x = [[ }]]\n", 2}, {"x = { a = [}] }\n", 2}};
  for (const auto& [text, line] : cases) {
    const LoadResult result = parse_scenario(std::string("duration_s = 1\n") + text, "x.toml");
    ASSERT_EQ(result.errors.size(), 1u) << text;
    EXPECT_EQ(result.errors[0].to_string(), "x.toml:" + std::to_string(line) + ": '}' cannot follow '[' or ','")
        << text;
  }
  const LoadResult fine = parse_scenario("duration_s = 1\nx = [{}, { a = 1 }, \"[}\", ',}'] # [}\n", "x.toml");
  for (const Diagnostic& error : fine.errors) {
    EXPECT_EQ(error.to_string().find("cannot follow"), std::string::npos) << error.to_string();
  }
}

// Found by the same fuzzer: toml++ 3.3 scans an unquoted value ahead to tell its type, and
// asserts on some it cannot type ("9904------ 0" followed by a table). An unquoted value must be
// true, false or a TOML number; scenario files have no dates.
TEST(BadScenarioText, AnUnquotedValueMustBeANumberOrABoolean) {
  const std::pair<const char*, const char*> refused[] = {
      {"x = 9904------ 0\n\n[[x", "'9904------' is not a number, true or false (a text value needs quotes)"},
      {"x = 5s\n", "'5s' is not a number, true or false (a text value needs quotes)"},
      {"x = yes\n", "'yes' is not a number, true or false (a text value needs quotes)"},
      {"x = [1, two]\n", "'two' is not a number, true or false (a text value needs quotes)"},
      {"x = 1979-05-27\n", "'1979-05-27' is not a number, true or false (a text value needs quotes)"},
      {"x = 01\n", "'01' is not a number, true or false (a text value needs quotes)"},
      {"x = 1__0\n", "'1__0' is not a number, true or false (a text value needs quotes)"},
      {"x = 0x\n", "'0x' is not a number, true or false (a text value needs quotes)"},
      {"x = 1.e5\n", "'1.e5' is not a number, true or false (a text value needs quotes)"},
      {"x = 12345678901234567890123456789012345678901234567890z\n",
       "'1234567890123456789012345678901234567890...' is not a number, true or false (a text value needs quotes)"}};
  for (const auto& [text, message] : refused) {
    const LoadResult result = parse_scenario(std::string("duration_s = 1\n") + text, "x.toml");
    ASSERT_EQ(result.errors.size(), 1u) << text;
    EXPECT_EQ(result.errors[0].to_string(), std::string("x.toml:2: ") + message) << text;
  }
  const LoadResult numbers = parse_scenario(
      "duration_s = 1\nx = [1_000, -0.5e-3, +inf, -nan, 0xDEAD_beef, 0o17, 0b101, 1E+5, 0, -0.0]\n"
      "y = { a = true, b = false,c=3 }\n",
      "x.toml");
  for (const Diagnostic& error : numbers.errors) {
    EXPECT_EQ(error.to_string().find("is not a number"), std::string::npos) << error.to_string();
  }
}

// Found by the same fuzzer: toml++ 3.3's whitespace test reaches an unreachable point for most
// non-ASCII characters (here U+048C), which it asks about outside strings (also after a quote
// it reads as a stray character, as in `1"…`) and after a backslash in a string. Strings and
// comments keep their non-ASCII text.
TEST(BadScenarioText, NonAsciiWhereTomlPlusPlusTestsForWhitespaceIsRefusedWithItsLine) {
  const std::string u048c = "\xd2\x8c";
  const std::pair<std::string, std::string> cases[] = {
      {"sketch = 1\"C" + u048c + "x\n",
       "a non-ASCII character outside a string or comment is not allowed in a scenario file"},
      {"x = \"a\" \"" + u048c + "\"\n",
       "a non-ASCII character outside a string or comment is not allowed in a scenario file"},
      {"x = 1.\"" + u048c + "\"\n",
       "a non-ASCII character outside a string or comment is not allowed in a scenario file"},
      {"x = \"\"\"a \\ " + u048c + "\"\"\"\n",
       "a non-ASCII character after a backslash in a string is not allowed in a scenario file"},
      {"x = \"a\\" + u048c + "\"\n",
       "a non-ASCII character after a backslash in a string is not allowed in a scenario file"},
      {"x = \"\"\"a\\\n\n  " + u048c + "\"\"\"\n",
       "a non-ASCII character after a backslash in a string is not allowed in a scenario file"}};
  for (const auto& [text, message] : cases) {
    const LoadResult result = parse_scenario("duration_s = 1\n" + text, "x.toml");
    ASSERT_EQ(result.errors.size(), 1u) << text;
    EXPECT_EQ(result.errors[0].to_string(), "x.toml:2: " + message) << text;
  }
  const LoadResult fine = parse_scenario("duration_s = 1\n# " + u048c + "\n[a]\nb = [\"" + u048c + "\", '" + u048c +
                                             "']\n\"k" + u048c + "\" = { \"c\" = \"\"\"x\\\n  y" + u048c + "\"\"\" }\n",
                                         "x.toml");
  for (const Diagnostic& error : fine.errors) {
    EXPECT_EQ(error.to_string().find("non-ASCII"), std::string::npos) << error.to_string();
  }
}

// Found by hand (issue 27): toml++ 3.3 recurses once per dotted part of a key, so a key of
// 40,000 parts overflowed the stack. Keys are bounded in parts and length before toml++ sees
// them, wherever a key stands: a key/value pair, a table header, an inline table.
TEST(BadScenarioText, KeysOfManyPartsOrGreatLengthAreRefusedWithTheirLine) {
  std::string parts_40000 = "a";
  for (int i = 1; i < 40000; ++i) parts_40000 += ".a";
  std::string parts_17 = "a";
  for (int i = 1; i < 17; ++i) parts_17 += ".a";
  const std::string many = "a key of more than 16 dotted parts is not allowed in a scenario file";
  const std::string long_key = "a key longer than 256 characters is not allowed in a scenario file";
  const std::pair<std::string, std::string> cases[] = {{parts_40000 + " = 1\n", many},
                                                       {"[" + parts_40000 + "]\n", many},
                                                       {"[[" + parts_17 + "]]\n", many},
                                                       {"x = { " + parts_17 + " = 1 }\n", many},
                                                       {"x = [{ y = 2, " + parts_17 + " = 1 }]\n", many},
                                                       {"\"a\" . 'b' . " + parts_17 + " = 1\n", many},
                                                       {std::string(257, 'k') + " = 1\n", long_key},
                                                       {"\"" + std::string(255, 'k') + "\" = 1\n", long_key},
                                                       {"x.\"" + std::string(300, '.') + "\" = 1\n", long_key}};
  for (const auto& [text, message] : cases) {
    const LoadResult result = parse_scenario("duration_s = 1\n" + text, "x.toml");
    ASSERT_EQ(result.errors.size(), 1u) << text.substr(0, 60);
    EXPECT_EQ(result.errors[0].to_string(), "x.toml:2: " + message) << text.substr(0, 60);
  }
  // Keys at the limits pass, and dots inside string values are no key's.
  std::string parts_16 = "a";
  for (int i = 1; i < 16; ++i) parts_16 += ".a";
  const LoadResult fine = parse_scenario("duration_s = 1\n" + parts_16 + " = 1\n" + std::string(256, 'k') + " = \"" +
                                             std::string(1000, '.') + "\"\n[" + parts_16 + "]\n",
                                         "x.toml");
  for (const Diagnostic& error : fine.errors) {
    EXPECT_EQ(error.to_string().find("a key"), std::string::npos) << error.to_string();
  }
}

}  // namespace
}  // namespace stepdance::sim::scenario
