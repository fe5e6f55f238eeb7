// VcdReader on malformed input: exact file:line errors, and random mutations that must not crash.
#include <gtest/gtest.h>

#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "decode/vcd_reader.hpp"
#include "output/vcd_writer.hpp"

namespace stepdance::sim {
namespace {

constexpr char kDeclarations[] = "$timescale 1 ns $end\n$var wire 1 ! STEP $end\n$enddefinitions $end\n";

std::string error_of(const std::string& text) {
  std::istringstream in(text);
  const VcdReadResult result = read_vcd(in, "bad.vcd");
  EXPECT_FALSE(result.ok) << "accepted:\n" << text;
  return result.error;
}

TEST(VcdReaderErrors, MissingEnddefinitions) {
  EXPECT_EQ(error_of("$timescale 1 ns $end\n$var wire 1 ! A $end\n"),
            "bad.vcd:2: unexpected end of file: missing $enddefinitions");
}

TEST(VcdReaderErrors, EmptyFile) {
  EXPECT_EQ(error_of(""), "bad.vcd:1: unexpected end of file: missing $enddefinitions");
}

TEST(VcdReaderErrors, BadTimescaleNumberAndUnit) {
  EXPECT_EQ(error_of("$timescale 3 ns $end\n"),
            "bad.vcd:1: bad $timescale '3ns' (expected 1, 10 or 100 and s, ms, us, ns, ps or fs)");
  EXPECT_EQ(error_of("\n$timescale 1 ks $end\n"),
            "bad.vcd:2: bad $timescale '1ks' (expected 1, 10 or 100 and s, ms, us, ns, ps or fs)");
}

TEST(VcdReaderErrors, VarWithMissingFieldsOrBadWidth) {
  EXPECT_EQ(error_of("$var wire 1 ! $end\n"), "bad.vcd:1: $var needs a type, a width, an identifier and a name");
  EXPECT_EQ(error_of("$var wire one ! A $end\n"), "bad.vcd:1: bad $var width 'one'");
  EXPECT_EQ(error_of("$var wire 0 ! A $end\n"), "bad.vcd:1: bad $var width '0'");
}

TEST(VcdReaderErrors, CommandMissingItsEnd) {
  EXPECT_EQ(error_of("$var wire 1 ! A\n$enddefinitions $end\n"),
            "bad.vcd:2: missing $end of $var (from line 1), found '$enddefinitions'");
  EXPECT_EQ(error_of("$comment never\nends\n"),
            "bad.vcd:2: unexpected end of file: missing $end of $comment (from line 1)");
  EXPECT_EQ(error_of("$scope module a\n"), "bad.vcd:1: unexpected end of file: missing $end of $scope (from line 1)");
}

TEST(VcdReaderErrors, ScopeStructure) {
  EXPECT_EQ(error_of("$upscope $end\n"), "bad.vcd:1: $upscope without an open $scope");
  EXPECT_EQ(error_of("$scope module $end\n"), "bad.vcd:1: $scope needs a type and a name");
}

TEST(VcdReaderErrors, TextWhereADeclarationBelongs) {
  EXPECT_EQ(error_of("hello\n"), "bad.vcd:1: expected a declaration command, found 'hello'");
  EXPECT_EQ(error_of("$end\n"), "bad.vcd:1: expected a declaration command, found '$end'");
  EXPECT_EQ(error_of(std::string("\x01\xff\x7f rest")),
            "bad.vcd:1: expected a declaration command, found '\\x01\\xff\\x7f'");
}

TEST(VcdReaderErrors, UndeclaredIdentifier) {
  EXPECT_EQ(error_of(std::string(kDeclarations) + "#0\n1?\n"), "bad.vcd:5: value change for undeclared identifier '?'");
  EXPECT_EQ(error_of(std::string(kDeclarations) + "#0\nb1 \"\n"),
            "bad.vcd:5: value change for undeclared identifier '\"'");
}

TEST(VcdReaderErrors, TimeGoingBackwards) {
  EXPECT_EQ(error_of(std::string(kDeclarations) + "#10\n1!\n#5\n"), "bad.vcd:6: time goes backwards (#5 after #10)");
}

TEST(VcdReaderErrors, BadTimestamps) {
  EXPECT_EQ(error_of(std::string(kDeclarations) + "#1x\n"), "bad.vcd:4: bad timestamp '#1x'");
  EXPECT_EQ(error_of(std::string(kDeclarations) + "#\n"), "bad.vcd:4: bad timestamp '#'");
  EXPECT_EQ(error_of(std::string(kDeclarations) + "#-3\n"), "bad.vcd:4: bad timestamp '#-3'");
  EXPECT_EQ(error_of(std::string(kDeclarations) + "#99999999999999999999\n"),
            "bad.vcd:4: bad timestamp '#99999999999999999999'");
  EXPECT_EQ(error_of("$timescale 1 s $end $enddefinitions $end\n#10000000000\n"),
            "bad.vcd:2: timestamp '#10000000000' overflows 64-bit nanoseconds");
}

TEST(VcdReaderErrors, MalformedValues) {
  EXPECT_EQ(error_of(std::string(kDeclarations) + "#0\nhello\n"), "bad.vcd:5: unexpected 'hello' in value changes");
  EXPECT_EQ(error_of(std::string(kDeclarations) + "#0\n1\n"), "bad.vcd:5: value '1' has no identifier");
  EXPECT_EQ(error_of(std::string(kDeclarations) + "#0\nb102 !\n"), "bad.vcd:5: bad binary value 'b102'");
  EXPECT_EQ(error_of(std::string(kDeclarations) + "#0\nb1\n"),
            "bad.vcd:5: unexpected end of file: value 'b1' has no identifier");
  EXPECT_EQ(error_of(std::string(kDeclarations) + "#0\n$bogus\n"), "bad.vcd:5: unexpected '$bogus' in value changes");
}

/// Reads text that should be accepted as a truncated capture; returns the warning.
std::string truncation_of(const std::string& text) {
  std::istringstream in(text);
  const VcdReadResult result = read_vcd(in, "cut.vcd");
  EXPECT_TRUE(result.ok) << result.error;
  EXPECT_TRUE(result.truncated) << text;
  return result.warning;
}

TEST(VcdReaderTruncation, AFileCutInsideADumpBlockIsTruncatedNotWrong) {
  EXPECT_EQ(truncation_of(std::string(kDeclarations) + "#0\n$dumpvars\n0!\n"),
            "cut.vcd:6: the capture is truncated (a dump block has no $end); decoded up to there");
}

TEST(VcdReaderTruncation, ALastLineWithoutNewlineLosesItsLastTokenOnly) {
  // "#2000" cut to "#20" must not become a timestamp of 20 ns; "1!" before it on the line stays.
  const std::string text = std::string(kDeclarations) + "#0\n0!\n#1000\n1! #20";
  std::istringstream in(text);
  const VcdReadResult result = read_vcd(in, "cut.vcd");
  ASSERT_TRUE(result.ok) << result.error;
  EXPECT_TRUE(result.truncated);
  EXPECT_EQ(result.warning,
            "cut.vcd:7: the capture is truncated (it ends in the middle of line 7); decoded up to there");
  ASSERT_EQ(result.capture.wires[0].edges.size(), 1u);
  EXPECT_EQ(result.capture.wires[0].edges[0].time, 1000);
  EXPECT_EQ(result.capture.end_time, 1000);
  // A value cut off its identifier ("b1" of "b1 !") is dropped, not an error.
  EXPECT_EQ(truncation_of(std::string(kDeclarations) + "#0\nb1"),
            "cut.vcd:5: the capture is truncated (it ends in the middle of line 5); decoded up to there");
}

TEST(VcdReaderTruncation, AFileEndingInANewlineIsComplete) {
  std::istringstream in(std::string(kDeclarations) + "#0\n0!\n#1000\n1!\n");
  const VcdReadResult result = read_vcd(in, "whole.vcd");
  ASSERT_TRUE(result.ok);
  EXPECT_FALSE(result.truncated);
  EXPECT_EQ(result.warning, "");
}

TEST(VcdReaderErrors, DumpBlocks) {
  EXPECT_EQ(error_of(std::string(kDeclarations) + "#0\n$end\n"), "bad.vcd:5: $end without an open command");
  EXPECT_EQ(error_of(std::string(kDeclarations) + "$dumpvars\n$dumpvars\n"),
            "bad.vcd:5: $dumpvars inside another dump block");
}

TEST(VcdReaderErrors, LongTokensAreShortenedInMessages) {
  EXPECT_EQ(error_of(std::string(60, 'q') + "\n"),
            "bad.vcd:1: expected a declaration command, found '" + std::string(40, 'q') + "...'");
}

// The reader holds one chunk and one token at a time: a token (a run of bytes without blanks)
// over 1 MiB is no VCD, and neither is a declaration of endless words.
TEST(VcdReaderErrors, EndlessTokensAndCommandsAreRefused) {
  EXPECT_EQ(error_of(std::string(kDeclarations) + "#0\n" + std::string(2 << 20, 'x')),
            "bad.vcd:5: a token longer than 1048576 bytes (this is not a VCD file)");
  EXPECT_EQ(error_of("$timescale 1 ns $end\n" + std::string(3 << 20, '\0')),
            "bad.vcd:2: a token longer than 1048576 bytes (this is not a VCD file)");
  std::string words = "$attrbegin";
  for (int i = 0; i < 17; ++i) words += " w";
  EXPECT_EQ(error_of(words + " $end\n"), "bad.vcd:1: $attrbegin (from line 1) has more than 16 words before its $end");
  // A vector value of the widest wire (1,000,000 bits) is still one token.
  std::istringstream wide("$var wire 1000000 ! bus $end\n$enddefinitions $end\n#0\nb" + std::string(1000000, '1') +
                          " !\n");
  EXPECT_TRUE(read_vcd(wide, "wide.vcd").ok);
}

TEST(VcdReaderErrors, MissingFile) {
  const VcdReadResult result = read_vcd_file("/nonexistent-dir/capture.vcd");
  EXPECT_FALSE(result.ok);
  EXPECT_EQ(result.error, "/nonexistent-dir/capture.vcd:0: cannot open");
}

// A valid file with several wires, scopes and a sigrok-style tail, to mutate.
std::string fuzz_seed() {
  std::ostringstream out;
  {
    VcdWriter vcd(out, "seed");
    const auto step = vcd.add_wire("driver", "OUT_A_STEP");
    const auto dir = vcd.add_wire("driver", "OUT_A_DIR");
    const auto other = vcd.add_wire("basic", "IN_A_STEP", true);
    for (int frame = 0; frame < 6; ++frame) {
      const SimTime start = 40000 * frame;
      vcd.record(dir, start + 1000, frame % 2 == 0);
      vcd.record(step, start + 2000, true);
      vcd.record(step, start + 4000 + frame * 100, false);
      vcd.record(dir, start + 5000, false);
      vcd.record(other, start + 7000, frame % 3 == 0);
    }
    vcd.close(300000);
  }
  return out.str() + "$comment tail $end\n#300001 b1 ! r2.5 \" x#\n$dumpall 1! $end\n";
}

// True if `error` reads "fuzz.vcd:<line>: <message>" with a non-empty message.
bool has_error_form(const std::string& error) {
  const std::string prefix = "fuzz.vcd:";
  if (error.compare(0, prefix.size(), prefix) != 0) return false;
  size_t at = prefix.size();
  const size_t digits_start = at;
  while (at < error.size() && error[at] >= '0' && error[at] <= '9') ++at;
  return at > digits_start && error.compare(at, 2, ": ") == 0 && error.size() > at + 2;
}

void check_does_not_crash(const std::string& text) {
  std::istringstream in(text);
  const VcdReadResult result = read_vcd(in, "fuzz.vcd");
  if (!result.ok) {
    EXPECT_TRUE(has_error_form(result.error)) << result.error;
    return;
  }
  for (const VcdWire& wire : result.capture.wires) {
    bool level = wire.initial;
    SimTime last = result.capture.start_time;
    for (const Edge& edge : wire.edges) {
      EXPECT_GE(edge.time, last);
      EXPECT_NE(edge.level, level);
      level = edge.level;
      last = edge.time;
    }
  }
}

TEST(VcdReaderErrors, EveryTruncationGivesAResultOrAnError) {
  const std::string seed = fuzz_seed();
  {
    std::istringstream in(seed);
    ASSERT_TRUE(read_vcd(in, "seed").ok);
  }
  for (size_t length = 0; length <= seed.size(); ++length) check_does_not_crash(seed.substr(0, length));
}

TEST(VcdReaderErrors, RandomMutationsGiveAResultOrAnError) {
  const std::string seed = fuzz_seed();
  const std::vector<std::string> dictionary = {
      "$end", "$var", "$scope", "$upscope",  "$enddefinitions", "#",
      "b",    "r",    "x",      "$dumpvars", "$comment",        "#18446744073709551615",
      "\n",   " ",    "\0"};
  std::mt19937 rng(20241121);
  for (int round = 0; round < 3000; ++round) {
    std::string text = seed;
    const int mutations = 1 + static_cast<int>(rng() % 6);
    for (int m = 0; m < mutations && !text.empty(); ++m) {
      const size_t at = rng() % text.size();
      switch (rng() % 5) {
        case 0: text[at] = static_cast<char>(rng() % 256); break;
        case 1: text.erase(at, 1 + rng() % 16); break;
        case 2: text.insert(at, dictionary[rng() % dictionary.size()]); break;
        case 3: text.insert(at, text.substr(rng() % text.size(), 1 + rng() % 32)); break;
        default: text.resize(at); break;
      }
    }
    check_does_not_crash(text);
  }
}

}  // namespace
}  // namespace stepdance::sim
