// VcdWriter: golden text, time-0 folding, watermark streaming, timescales, determinism, misuse.
#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>

#include "output/vcd_writer.hpp"
#include "sim/output/test_files.hpp"

namespace stepdance::sim {
namespace {

constexpr char kHeader[] =
    "$version Stepdance simulator $end\n"
    "$timescale 1 ns $end\n"
    "$scope module driver $end\n"
    "$var wire 1 ! OUT_A_STEP $end\n"
    "$var wire 1 \" OUT_A_DIR $end\n"
    "$upscope $end\n"
    "$scope module basic $end\n"
    "$var wire 1 # OUT_A_STEP $end\n"
    "$upscope $end\n"
    "$enddefinitions $end\n";

// One forward X pulse on driver OUT_A and a copy on basic OUT_A, recorded out of order.
void write_small_waveform(VcdWriter& vcd) {
  const auto step = vcd.add_wire("driver", "OUT_A_STEP");
  const auto dir = vcd.add_wire("driver", "OUT_A_DIR");
  const auto basic = vcd.add_wire("basic", "OUT_A_STEP");
  vcd.record(basic, 2000, true);
  vcd.record(step, 2000, true);
  vcd.record(dir, 1000, true);
  vcd.flush_before(3000);
  vcd.record(step, 4000, false);
  vcd.record(step, 4500, false);  // no change: dropped
  vcd.record(basic, 5500, false);
  vcd.record(dir, 5000, false);
  vcd.close(40000);
}

TEST(VcdWriter, GoldenTextForASmallWaveform) {
  std::ostringstream out;
  VcdWriter vcd(out, "golden.vcd");
  write_small_waveform(vcd);
  EXPECT_EQ(out.str(), std::string(kHeader) +
                           "#0\n$dumpvars\n0!\n0\"\n0#\n$end\n"
                           "#1000\n1\"\n"
                           "#2000\n1!\n1#\n"
                           "#4000\n0!\n"
                           "#5000\n0\"\n"
                           "#5500\n0#\n"
                           "#40000\n");
}

TEST(VcdWriter, FileOutputIsByteIdenticalFromRunToRun) {
  const std::string first = test::temp_path("first.vcd");
  const std::string second = test::temp_path("second.vcd");
  {
    VcdWriter vcd(first);
    write_small_waveform(vcd);
  }
  {
    VcdWriter vcd(second);
    write_small_waveform(vcd);
  }
  std::ostringstream expected;
  VcdWriter reference(expected, "reference");
  write_small_waveform(reference);
  EXPECT_EQ(test::read_text(first), expected.str());
  EXPECT_EQ(test::read_text(second), expected.str());
}

TEST(VcdWriter, EdgesAtTimeZeroFoldIntoTheInitialValues) {
  std::ostringstream out;
  VcdWriter vcd(out, "zero.vcd", VcdWriterOptions{1, ""});
  const auto high = vcd.add_wire("", "ENABLE", true);
  const auto line = vcd.add_wire("", "LINE");
  vcd.record(line, 0, true);
  vcd.record(high, 10, false);
  vcd.close(10);
  EXPECT_EQ(out.str(),
            "$timescale 1 ns $end\n"
            "$var wire 1 ! ENABLE $end\n"
            "$var wire 1 \" LINE $end\n"
            "$enddefinitions $end\n"
            "#0\n$dumpvars\n1!\n1\"\n$end\n"
            "#10\n0!\n");
}

TEST(VcdWriter, TopLevelWiresComeAfterTheScopes) {
  std::ostringstream out;
  VcdWriter vcd(out, "top.vcd", VcdWriterOptions{1, ""});
  vcd.add_wire("", "TRIGGER");
  vcd.add_wire("basic", "OUT_A_DIR");
  vcd.close(0);
  EXPECT_EQ(out.str(),
            "$timescale 1 ns $end\n"
            "$scope module basic $end\n"
            "$var wire 1 ! OUT_A_DIR $end\n"
            "$upscope $end\n"
            "$var wire 1 \" TRIGGER $end\n"
            "$enddefinitions $end\n"
            "#0\n$dumpvars\n0\"\n0!\n$end\n");
}

TEST(VcdWriter, SameTimeChangesOfOneWireKeepTheirOrder) {
  std::ostringstream out;
  VcdWriter vcd(out, "glitch.vcd", VcdWriterOptions{1, ""});
  const auto line = vcd.add_wire("", "STEP");
  vcd.record(line, 7, true);
  vcd.record(line, 7, false);
  vcd.close(7);
  EXPECT_EQ(out.str(),
            "$timescale 1 ns $end\n$var wire 1 ! STEP $end\n$enddefinitions $end\n"
            "#0\n$dumpvars\n0!\n$end\n#7\n1!\n0!\n");
}

TEST(VcdWriter, CoarserTimescaleRoundsTimesHalfUp) {
  std::ostringstream out;
  VcdWriter vcd(out, "coarse.vcd", VcdWriterOptions{10, ""});
  const auto line = vcd.add_wire("", "STEP");
  vcd.record(line, 14, true);   // 1.4 units → 1
  vcd.record(line, 25, false);  // 2.5 units → 3
  vcd.close(1004);              // 100.4 → 100
  EXPECT_EQ(out.str(),
            "$timescale 10 ns $end\n$var wire 1 ! STEP $end\n$enddefinitions $end\n"
            "#0\n$dumpvars\n0!\n$end\n#1\n1!\n#3\n0!\n#100\n");
}

TEST(VcdWriter, MicrosecondTimescaleIsWrittenAsUs) {
  std::ostringstream out;
  VcdWriter vcd(out, "us.vcd", VcdWriterOptions{1000, ""});
  vcd.add_wire("", "STEP");
  vcd.close(0);
  EXPECT_EQ(out.str().substr(0, 22), "$timescale 1 us $end\n$");
}

TEST(VcdWriter, WatermarkFlushesOnlyOlderEdgesAndBoundsTheBuffer) {
  std::ostringstream out;
  VcdWriter vcd(out, "stream.vcd", VcdWriterOptions{1, ""});
  const auto line = vcd.add_wire("", "STEP");
  for (int i = 1; i <= 1000; ++i) {
    vcd.record(line, i * 100, i % 2 == 1);
    if (i % 10 == 0) {
      vcd.flush_before(i * 100 - 50);
      EXPECT_LE(vcd.buffered_edges(), 1u);
    }
  }
  vcd.flush_before(450);  // a watermark that moves back is ignored
  vcd.close(100000);
  const std::string text = out.str();
  EXPECT_NE(text.find("#100\n1!\n#200\n0!\n"), std::string::npos);
  EXPECT_NE(text.find("#99900\n1!\n#100000\n0!\n"), std::string::npos);
  EXPECT_EQ(vcd.buffered_edges(), 0u);
}

TEST(VcdWriter, IdentifiersUseAllPrintableCharactersThenGrow) {
  EXPECT_EQ(VcdWriter::identifier(0), "!");
  EXPECT_EQ(VcdWriter::identifier(1), "\"");
  EXPECT_EQ(VcdWriter::identifier(93), "~");
  EXPECT_EQ(VcdWriter::identifier(94), "!\"");
  EXPECT_EQ(VcdWriter::identifier(95), "\"\"");
  EXPECT_EQ(VcdWriter::identifier(94 * 94), "!!\"");
}

TEST(VcdWriter, ManyWiresGetMultiCharacterIdentifiers) {
  std::ostringstream out;
  VcdWriter vcd(out, "many.vcd", VcdWriterOptions{1, ""});
  for (int i = 0; i < 100; ++i) vcd.add_wire("bus", "L" + std::to_string(i));
  vcd.close(0);
  EXPECT_NE(out.str().find("$var wire 1 ~ L93 $end\n$var wire 1 !\" L94 $end\n"), std::string::npos);
}

TEST(VcdWriter, MisuseThrows) {
  std::ostringstream out;
  VcdWriter vcd(out, "misuse.vcd");
  EXPECT_THROW(vcd.add_wire("driver", ""), std::invalid_argument);
  EXPECT_THROW(vcd.add_wire("driver", "OUT A"), std::invalid_argument);
  EXPECT_THROW(vcd.add_wire("dri ver", "OUT_A"), std::invalid_argument);
  const auto line = vcd.add_wire("driver", "OUT_A_STEP");
  EXPECT_THROW(vcd.record(line + 1, 5, true), std::logic_error);
  EXPECT_THROW(vcd.record(line, -1, true), std::logic_error);
  vcd.record(line, 100, true);
  vcd.flush_before(200);
  try {
    vcd.record(line, 150, false);
    FAIL() << "an edge older than the watermark was accepted";
  } catch (const std::logic_error& error) {
    EXPECT_STREQ(error.what(), "misuse.vcd: VCD edge at 150 ns is older than the watermark 200 ns");
  }
  EXPECT_THROW(vcd.add_wire("driver", "LATE"), std::logic_error);
  vcd.close(300);
  EXPECT_THROW(vcd.record(line, 400, false), std::logic_error);
  EXPECT_THROW(VcdWriter(out, "bad", VcdWriterOptions{5, ""}), std::invalid_argument);
}

TEST(VcdWriter, UnwritablePathThrowsWithThePath) {
  try {
    VcdWriter vcd("/nonexistent-dir/trace.vcd");
    FAIL() << "opened an impossible path";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "/nonexistent-dir/trace.vcd: cannot open for writing");
  }
}

}  // namespace
}  // namespace stepdance::sim
