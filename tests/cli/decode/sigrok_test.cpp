// Interoperability with sigrok-cli (skipped when it is not installed): it reads our VCD, and we read its.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "decode/capture_decoder.hpp"
#include "decode/step_dir_pairs.hpp"
#include "decode/vcd_reader.hpp"
#include "output/vcd_writer.hpp"
#include "sim/output/test_files.hpp"
#include "stepdance/protocol/frame_encoder.hpp"

namespace stepdance::sim {
namespace {

bool have_sigrok() { return std::system("command -v sigrok-cli >/dev/null 2>&1") == 0; }

// Runs a shell command; returns its exit status and stores stdout (and stderr) in `output`.
int run(const std::string& command, std::string& output) {
  output.clear();
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return -1;
  char buffer[4096];
  size_t got = 0;
  while ((got = fread(buffer, 1, sizeof buffer, pipe)) > 0) output.append(buffer, got);
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

void append_word(VcdWriter& vcd, VcdWriter::WireId wire, uint32_t word, SimTime start) {
  bool level = false;
  for (int bit = 0; bit <= 32; ++bit) {
    const bool now = bit < 32 && ((word >> bit) & 1u);
    if (now != level) vcd.record(wire, start + bit * kMicrosecond, now);
    level = now;
  }
}

// Ten frames on one port: X and Y every frame, forward on even frames, with E on frame 3.
void write_frames(const std::string& path) {
  VcdWriter vcd(path);
  const auto step = vcd.add_wire("driver", "OUT_A_STEP");
  const auto dir = vcd.add_wire("driver", "OUT_A_DIR");
  for (int frame = 0; frame < 10; ++frame) {
    protocol::FrameRequest request;
    request.active_mask = frame == 3 ? 0x23 : 0x03;
    request.forward_mask = frame % 2 == 0 ? 0x3F : 0x00;
    const protocol::EncodedFrame encoded = protocol::encode_frame(request);
    const SimTime start = 40 * kMicrosecond * frame;
    append_word(vcd, step, encoded.words.step_bits, start);
    append_word(vcd, dir, encoded.words.dir_bits, start);
    vcd.flush_before(start + 40 * kMicrosecond);
  }
  vcd.close(400 * kMicrosecond);
}

DecodeResult decode_file(const std::string& path) {
  const VcdReadResult read = read_vcd_file(path);
  EXPECT_TRUE(read.ok) << read.error;
  const std::vector<StepDirPair> pairs = find_step_dir_pairs(read.capture);
  EXPECT_EQ(pairs.size(), 1u);
  if (pairs.empty()) return DecodeResult{};
  const VcdWire& step = read.capture.wires[pairs[0].step];
  const VcdWire& dir = read.capture.wires[pairs[0].dir];
  return decode_step_dir(step.edges, dir.edges, DecodeOptions{}, InitialLevels{step.initial, dir.initial});
}

TEST(Sigrok, ShowsOurVcd) {
  if (!have_sigrok()) GTEST_SKIP() << "sigrok-cli is not installed";
  const std::string path = test::temp_path("frames.vcd");
  write_frames(path);
  std::string output;
  ASSERT_EQ(run("sigrok-cli -I vcd -i '" + path + "' --show", output), 0) << output;
  EXPECT_NE(output.find("- OUT_A_STEP: logic"), std::string::npos) << output;
  EXPECT_NE(output.find("- OUT_A_DIR: logic"), std::string::npos) << output;
  EXPECT_NE(output.find("Logic sample count: 400000"), std::string::npos) << output;
}

TEST(Sigrok, ReExportOfOurVcdDecodesToTheSameCounts) {
  if (!have_sigrok()) GTEST_SKIP() << "sigrok-cli is not installed";
  const std::string ours = test::temp_path("ours.vcd");
  const std::string theirs = test::temp_path("theirs.vcd");
  write_frames(ours);
  std::string output;
  ASSERT_EQ(run("sigrok-cli -I vcd -i '" + ours + "' -O vcd -o '" + theirs + "'", output), 0) << output;
  const DecodeResult original = decode_file(ours);
  const DecodeResult exported = decode_file(theirs);
  EXPECT_EQ(original.counts[SIGNAL_X], (DirectionCounts{5, 5}));
  EXPECT_EQ(original.counts[SIGNAL_Y], (DirectionCounts{5, 5}));
  EXPECT_EQ(original.counts[SIGNAL_E], (DirectionCounts{0, 1}));
  EXPECT_EQ(original.frames.count, 10u);
  for (uint8_t signal = 0; signal < kNumSignals; ++signal) EXPECT_EQ(exported.counts[signal], original.counts[signal]);
  EXPECT_EQ(exported.frames.count, original.frames.count);
  EXPECT_EQ(exported.counts.too_short + exported.counts.too_long, 0u);
}

TEST(Sigrok, ReadsADemoDeviceCapture) {
  if (!have_sigrok()) GTEST_SKIP() << "sigrok-cli is not installed";
  const std::string path = test::temp_path("demo.vcd");
  std::string output;
  // 24 MHz makes sigrok write a 100 ps timescale.
  ASSERT_EQ(run("sigrok-cli -d demo --config samplerate=24m --samples 2000 -C D0,D1 -O vcd -o '" + path + "'", output),
            0)
      << output;
  const VcdReadResult read = read_vcd_file(path);
  ASSERT_TRUE(read.ok) << read.error;
  EXPECT_EQ(read.capture.timescale_fs, 100'000);
  ASSERT_EQ(read.capture.wires.size(), 2u);
  EXPECT_EQ(read.capture.wires[0].name, "D0");
  EXPECT_EQ(read.capture.wires[1].name, "D1");
  EXPECT_FALSE(read.capture.wires[0].edges.empty());
  EXPECT_TRUE(find_wire(read.capture, "D1").ok);
}

}  // namespace
}  // namespace stepdance::sim
