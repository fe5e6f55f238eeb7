// `stepdance decode` in bounded memory (issue 27): it read the whole capture into edge lists
// first, so a 1 GB capture took about 1 GB (2.1 GB with denser edges) and /dev/zero 16.8 GB before
// failing. Now it streams, and each case here runs with the data segment limited to 64 MiB
// (`ulimit -d 65536`; not in the AddressSanitizer build): the old reader died of std::bad_alloc
// on every one of them.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace stepdance::sim::test {
namespace {

#if defined(__SANITIZE_ADDRESS__)
/// AddressSanitizer maps terabytes of shadow memory, which no data limit admits: the sanitizer
/// build runs these cases for their results alone (scripts/test.sh runs them limited first).
constexpr const char* kDataLimit = "";
#else
constexpr const char* kDataLimit = "ulimit -d 65536 && ";
#endif

/// `stepdance <arguments>` with at most 64 MiB of data segment (heap and anonymous mappings), as
/// cli_runner.hpp runs it otherwise.
CommandResult limited(const std::string& arguments, const std::string& scratch) {
  std::filesystem::create_directories(scratch);
  const std::string out = scratch + "/stdout.txt", err = scratch + "/stderr.txt";
  const std::string command = kDataLimit + kStepdance + " " + arguments + " >" + out + " 2>" + err;
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_file(out), read_file(err)};
}

constexpr uint64_t kPulses = 8'000'000;  // about 250 MB of VCD text

/// Opens the FIFO at `path` for writing once a reader has opened it (false if none does in 60 s,
/// say because the decoder could not start).
int open_fifo_for_writing(const std::string& path) {
  for (int attempt = 0; attempt < 6000; ++attempt) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK);  // ENXIO while nobody reads
    if (fd >= 0) {
      ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
      return fd;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return -1;
}

/// Writes a capture of kPulses X pulses (2 µs wide, one a frame) into the FIFO at `path`.
void write_long_capture(const std::string& path) {
  const int fd = open_fifo_for_writing(path);
  if (fd < 0) return;
  std::string block =
      "$timescale 1ns $end\n$scope module long $end\n$var wire 1 s OUT_A_STEP $end\n$var wire 1 d OUT_A_DIR $end\n"
      "$upscope $end\n$enddefinitions $end\n#0\n0s\n1d\n";
  char record[64];
  for (uint64_t pulse = 0; pulse < kPulses; ++pulse) {
    const uint64_t start = 40000 * (pulse + 1);
    block.append(record, static_cast<size_t>(std::snprintf(record, sizeof record, "#%llu\n1s\n#%llu\n0s\n",
                                                           static_cast<unsigned long long>(start + 2000),
                                                           static_cast<unsigned long long>(start + 4000))));
    if (block.size() < (1 << 20) && pulse + 1 < kPulses) continue;
    if (::write(fd, block.data(), block.size()) != static_cast<ssize_t>(block.size())) break;  // the reader left
    block.clear();
  }
  ::close(fd);
}

TEST(DecodeMemoryTest, ALongCaptureIsDecodedWithin64MiB) {
  ::signal(SIGPIPE, SIG_IGN);  // a decoder that gives up early must not take the test with it
  const std::string scratch = test_output_dir("decode_memory_long");
  std::filesystem::create_directories(scratch);
  const std::string fifo = scratch + "/capture.vcd";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::thread writer(write_long_capture, fifo);
  const CommandResult result = limited("decode --json " + fifo, scratch);
  writer.join();
  ASSERT_EQ(result.exit_code, 0) << result.err.substr(0, 500);
  const nlohmann::json port = nlohmann::json::parse(result.out)["ports"]["long.OUT_A"];
  EXPECT_EQ(port["accepted"], kPulses);
  EXPECT_EQ(port["pulses"]["X"]["forward"], kPulses);
  EXPECT_EQ(port["frames"]["count"], kPulses);
}

TEST(DecodeMemoryTest, AnEndlessTokenIsRefusedAfterAMebibyte) {
  const CommandResult result = limited("decode /dev/zero", test_output_dir("decode_memory_zero"));
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, "/dev/zero:1: a token longer than 1048576 bytes (this is not a VCD file)\n");
}

/// A capture of `pairs` STEP/DIR pairs, each sending one X pulse.
std::string write_wide_capture(const std::string& scratch, int pairs) {
  const std::string path = scratch + "/wide.vcd";
  std::ofstream vcd(path);
  vcd << "$timescale 1ns $end\n$scope module wide $end\n";
  for (int pair = 0; pair < pairs; ++pair) {
    vcd << "$var wire 1 s" << pair << " P" << pair << "_STEP $end\n$var wire 1 d" << pair << " P" << pair
        << "_DIR $end\n";
  }
  vcd << "$upscope $end\n$enddefinitions $end\n#0\n#1000\n";
  for (int pair = 0; pair < pairs; ++pair) vcd << "1s" << pair << "\n";
  vcd << "#3000\n";
  for (int pair = 0; pair < pairs; ++pair) vcd << "0s" << pair << "\n";
  return path;
}

TEST(DecodeMemoryTest, TheWidestCaptureAllowedFitsAndAWiderOneIsRefused) {
  const std::string scratch = test_output_dir("decode_memory_wide");
  std::filesystem::create_directories(scratch);
  const CommandResult widest = limited("decode --json " + write_wide_capture(scratch, 50000), scratch);
  ASSERT_EQ(widest.exit_code, 0) << widest.err.substr(0, 500);
  EXPECT_EQ(nlohmann::json::parse(widest.out)["ports"]["wide.P49999"]["accepted"], 1);
  const std::string path = write_wide_capture(scratch, 50001);
  const CommandResult wider = limited("decode " + path, scratch);
  EXPECT_EQ(wider.exit_code, 2);
  // Line 100,003 declares the 100,001st wire: two header lines, then two lines a pair.
  EXPECT_EQ(wider.err, path + ":100003: more than 100000 wires (too wide a capture to decode)\n");
}

}  // namespace
}  // namespace stepdance::sim::test
