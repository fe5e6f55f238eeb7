// VcdReader: round trip with the writer, sigrok/PulseView-style files, timescales, odd but legal input.
#include <gtest/gtest.h>

#include <sstream>

#include "decode/vcd_reader.hpp"
#include "output/vcd_writer.hpp"
#include "sim/output/edge_pairs.hpp"
#include "sim/output/test_files.hpp"

namespace stepdance::sim {
namespace {

using test::EdgePairs;
using test::pairs;

VcdCapture parse(const std::string& text, const std::string& name = "test.vcd") {
  std::istringstream in(text);
  VcdReadResult result = read_vcd(in, name);
  EXPECT_TRUE(result.ok) << result.error;
  return result.capture;
}

TEST(VcdReader, RoundTripsTheWritersOutput) {
  const std::string path = test::temp_path("round.vcd");
  const EdgeList step = {{2000, true}, {4000, false}, {42000, true}, {47000, false}, {50000, true}, {50000, false}};
  const EdgeList dir = {{1000, true}, {5000, false}, {123456789012, true}};
  {
    VcdWriter vcd(path);
    const auto step_wire = vcd.add_wire("driver", "OUT_A_STEP");
    const auto dir_wire = vcd.add_wire("driver", "OUT_A_DIR");
    const auto enable = vcd.add_wire("", "ENABLE", true);
    vcd.record_all(step_wire, step);
    vcd.record_all(dir_wire, dir);
    vcd.record(enable, 3000, false);
    vcd.close(200000000000);
  }
  const VcdReadResult result = read_vcd_file(path);
  ASSERT_TRUE(result.ok) << result.error;
  const VcdCapture& capture = result.capture;
  EXPECT_EQ(capture.timescale_fs, 1000000);
  EXPECT_EQ(capture.start_time, 0);
  EXPECT_EQ(capture.end_time, 200000000000);
  ASSERT_EQ(capture.wires.size(), 3u);
  EXPECT_EQ(capture.wires[0].full_name(), "driver.OUT_A_STEP");
  EXPECT_EQ(capture.wires[0].id, "!");
  EXPECT_FALSE(capture.wires[0].initial);
  EXPECT_EQ(pairs(capture.wires[0].edges), pairs(step));
  EXPECT_EQ(capture.wires[1].full_name(), "driver.OUT_A_DIR");
  EXPECT_EQ(pairs(capture.wires[1].edges), pairs(dir));
  EXPECT_EQ(capture.wires[2].full_name(), "ENABLE");
  EXPECT_TRUE(capture.wires[2].initial);
  EXPECT_EQ(pairs(capture.wires[2].edges), (EdgePairs{{3000, false}}));
}

// Shaped like a PulseView export: $date/$version/$comment, 1 us timescale, values on the
// timestamp line, an x start, then a $dumpvars block on its own.
constexpr char kSigrokStyle[] =
    "$date Thu Nov 21 12:00:00 2024 $end\n"
    "$version libsigrok 0.5.2 $end\n"
    "$comment\n"
    "  Acquisition with 2/8 channels at 1 MHz\n"
    "$end\n"
    "$timescale 1 us $end\n"
    "$scope module libsigrok $end\n"
    "$var wire 1 ! D0 $end\n"
    "$var wire 1 \" D1 $end\n"
    "$upscope $end\n"
    "$enddefinitions $end\n"
    "#0 x! x\"\n"
    "$dumpvars 0! 1\" $end\n"
    "#2 1!\n"
    "#5 0!\n"
    "#6 0\"\n"
    "#40 1! 1\"\n"
    "#43 0! x\"\n"
    "#50\n";

TEST(VcdReader, ReadsASigrokStyleExport) {
  const VcdCapture capture = parse(kSigrokStyle);
  EXPECT_EQ(capture.timescale_fs, 1000000000);
  EXPECT_EQ(capture.end_time, 50000);
  ASSERT_EQ(capture.wires.size(), 2u);
  EXPECT_EQ(capture.wires[0].full_name(), "libsigrok.D0");
  EXPECT_FALSE(capture.wires[0].initial);
  EXPECT_EQ(pairs(capture.wires[0].edges), (EdgePairs{{2000, true}, {5000, false}, {40000, true}, {43000, false}}));
  EXPECT_TRUE(capture.wires[1].initial);
  EXPECT_EQ(pairs(capture.wires[1].edges), (EdgePairs{{6000, false}, {40000, true}, {43000, false}}));
}

TEST(VcdReader, ConvertsEveryTimescaleToNanoseconds) {
  const auto end_time = [](const std::string& timescale, const std::string& time) {
    return parse("$timescale " + timescale + " $end $enddefinitions $end #" + time + "\n").end_time;
  };
  EXPECT_EQ(end_time("1 ns", "7"), 7);
  EXPECT_EQ(end_time("10ns", "7"), 70);
  EXPECT_EQ(end_time("100 ns", "7"), 700);
  EXPECT_EQ(end_time("1us", "7"), 7000);
  EXPECT_EQ(end_time("10 us", "7"), 70000);
  EXPECT_EQ(end_time("1 ms", "7"), 7000000);
  EXPECT_EQ(end_time("1 s", "7"), 7000000000);
  EXPECT_EQ(end_time("100 ps", "14"), 1);  // 1.4 ns
  EXPECT_EQ(end_time("100 ps", "15"), 2);  // 1.5 ns rounds up
  EXPECT_EQ(end_time("1 fs", "2500000"), 3);
  EXPECT_EQ(end_time("1 ns", "9223372036854775807"), 9223372036854775807);
}

TEST(VcdReader, NestedScopesAliasesBitIndicesAndVectors) {
  const VcdCapture capture = parse(
      "$scope module top $end\n"
      "$scope module driver $end\n"
      "$var wire 1 aa STEP $end\n"
      "$var reg 1 aa STEP_COPY $end\n"
      "$var wire 4 bb bus $end\n"
      "$var wire 1 cc data [3] $end\n"
      "$var real 64 dd speed $end\n"
      "$upscope $end\n"
      "$var wire 1 ee TOP $end\n"
      "$upscope $end\n"
      "$enddefinitions $end\n"
      "#0\n$dumpvars\n0aa\nb0000 bb\n0cc\nr0.5 dd\nzee\n$end\n"
      "#10\n1aa\nb1010 bb\nB1 cc\nr1e3 dd\nZee\n"
      "#20\n0aa\nb0 cc\n"
      "#20\n1ee\n");
  ASSERT_EQ(capture.wires.size(), 6u);
  EXPECT_EQ(capture.wires[0].full_name(), "top.driver.STEP");
  EXPECT_EQ(capture.wires[1].full_name(), "top.driver.STEP_COPY");
  EXPECT_EQ(pairs(capture.wires[0].edges), (EdgePairs{{10, true}, {20, false}}));
  EXPECT_EQ(pairs(capture.wires[1].edges), pairs(capture.wires[0].edges));
  EXPECT_EQ(capture.wires[2].width, 4);
  EXPECT_TRUE(capture.wires[2].edges.empty());
  EXPECT_EQ(capture.wires[3].full_name(), "top.driver.data[3]");
  EXPECT_EQ(pairs(capture.wires[3].edges), (EdgePairs{{10, true}, {20, false}}));
  EXPECT_TRUE(capture.wires[4].edges.empty());
  EXPECT_EQ(capture.wires[5].full_name(), "top.TOP");
  EXPECT_EQ(pairs(capture.wires[5].edges), (EdgePairs{{20, true}}));
}

TEST(VcdReader, ValuesBeforeTheFirstTimestampAreInitialLevels) {
  const VcdCapture capture = parse(
      "$var wire 1 ! A $end\n$enddefinitions $end\n"
      "$dumpvars 1! $end\n#100\n0!\n#200\n1!\n");
  EXPECT_EQ(capture.start_time, 100);
  ASSERT_EQ(capture.wires.size(), 1u);
  EXPECT_FALSE(capture.wires[0].initial);  // the level at the first timestamp wins
  EXPECT_EQ(pairs(capture.wires[0].edges), (EdgePairs{{200, true}}));
}

TEST(VcdReader, DumpoffBlocksReadAsLowAndRepeatedValuesAreNotEdges) {
  const VcdCapture capture = parse(
      "$var wire 1 ! A $end\n$enddefinitions $end\n"
      "#0\n1!\n#5\n1!\n#10\n$dumpoff\nx!\n$end\n#20\n$dumpon\n1!\n$end\n#30\n$dumpall 1! $end\n");
  EXPECT_TRUE(capture.wires[0].initial);
  EXPECT_EQ(pairs(capture.wires[0].edges), (EdgePairs{{10, false}, {20, true}}));
}

TEST(VcdReader, AcceptsCrLfCommentsAndUnknownDeclarations) {
  const VcdCapture capture = parse(
      "$comment a comment\r\nover lines $end\r\n"
      "$attrbegin misc 07 STEP 1 $end\r\n"
      "$timescale\r\n\t10 ns\r\n$end\r\n"
      "$var wire 1 # STEP $end\r\n"
      "$enddefinitions $end\r\n"
      "#0\r\n0#\r\n$comment in the values $end\r\n#3\r\n1#\r\n");
  EXPECT_EQ(pairs(capture.wires[0].edges), (EdgePairs{{30, true}}));
}

TEST(VcdReader, SkipsSigrokCliMetaLinesBeforeTheHeader) {
  const VcdCapture capture = parse(
      "META samplerate: 1000000000\n$timescale 1 ns $end\n$var wire 1 ! D0 $end\n"
      "$enddefinitions $end\n#0 0!\n#5 1!\n");
  EXPECT_EQ(pairs(capture.wires[0].edges), (EdgePairs{{5, true}}));
}

TEST(VcdReader, EmptyValueSectionIsFine) {
  const VcdCapture capture = parse("$var wire 1 ! A $end $enddefinitions $end");
  ASSERT_EQ(capture.wires.size(), 1u);
  EXPECT_TRUE(capture.wires[0].edges.empty());
  EXPECT_EQ(capture.end_time, 0);
}

}  // namespace
}  // namespace stepdance::sim
