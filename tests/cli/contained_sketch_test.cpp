// A misbehaving sketch never hangs the simulator, never kills it and never fakes a pass: each of
// the sketches under fixtures/Contained runs through `stepdance sim` as a user runs it, and the
// run ends at its duration or is stopped with its board, its entry point and a distinct status.
#include <chrono>
#include <ostream>

#include "cli_runner.hpp"

namespace stepdance::sim::test {
namespace {

// Statuses of cli/exit_codes.hpp, written out: the test pins the command's contract.
constexpr int kOk = 0;
constexpr int kSketchFailed = 5;
constexpr int kSketchHung = 6;

struct Case {
  const char* sketch;
  int status;
  /// Must appear in stderr (the stop's report) or stdout (console, expectations).
  const char* in_err;
  const char* in_out;
  /// False when the run never starts (the sketch ended the program while loading).
  bool runs = true;
  /// A null write UBSan reports (and ends the process for) before the fault: in a sanitizer
  /// build the sanitizer, not the simulator, diagnoses the sketch's bug, as it should.
  bool ubsan_diagnoses = false;
};

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitizerBuild = true;
#else
constexpr bool kSanitizerBuild = false;
#endif

void PrintTo(const Case& c, std::ostream* os) { *os << c.sketch; }

std::string fixture(const std::string& name) { return source_path("tests/sim/assembly/fixtures/Contained/" + name); }

/// Runs the fixture with a 1 s watchdog; `timeout` makes a regression fail instead of hanging.
CommandResult run_fixture(const std::string& name, const std::string& extra = "") {
  const std::string scratch = test_output_dir("contained_" + name);
  return stepdance("sim " + fixture(name) + " --out " + scratch + "/out --watchdog-s 1 " + extra, scratch);
}

class ContainedSketch : public ::testing::TestWithParam<Case> {};

TEST_P(ContainedSketch, EndsWithItsStatusAndReport) {
  const Case& c = GetParam();
  if (kSanitizerBuild && c.ubsan_diagnoses) GTEST_SKIP() << "UBSan reports this sketch's null write itself";
  const auto started = std::chrono::steady_clock::now();
  const CommandResult result = run_fixture(c.sketch);
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  EXPECT_EQ(result.exit_code, c.status) << result.out << result.err;
  EXPECT_NE(result.err.find(c.in_err), std::string::npos) << result.err;
  EXPECT_NE(result.out.find(c.in_out), std::string::npos) << result.out;
  // The hangs are stopped after the 1 s budget, not at some later time.
  EXPECT_LT(wall_s, 20.0);
  if (c.status != kOk && c.runs) {
    // Never a false pass: nothing is reported as checked.
    EXPECT_EQ(result.out.find("ok      "), std::string::npos) << result.out;
    EXPECT_NE(result.out.find("NOT RUN "), std::string::npos) << result.out;
  }
}

const Case kCases[] = {
    // `while (1) delay(1000);` ends with the run, at its duration, and passes.
    {"HaltInDelay", kOk, "", "simulated 2.000 s"},
    // A minute's delay in setup() does not make a 2 s run last a minute.
    {"LongDelayInSetup", kOk, "", "simulated 2.000 s"},
    // Busy loops: stopped by the watchdog, with where; the unfinished console line is shown.
    {"BusyLoop", kSketchHung, "board 'driver': loop() has not returned for 1 s of wall time", "[driver] progress: 50%"},
    {"BusySetup", kSketchHung, "board 'driver': setup() has not returned for 1 s of wall time", "NOT RUN "},
    // A wait in the C library that the watchdog's signal cuts short, after which setup()
    // returns by itself: still a hang, never a pass.
    {"SleepInSetup", kSketchHung, "board 'driver': setup() has not returned for 1 s of wall time", "NOT RUN "},
    // exit() and abort(): reported, never status 0.
    {"ExitInLoop", kSketchFailed, "board 'driver': exit(0) called in loop() at t = 0.501", "NOT RUN "},
    {"AbortInLoop", kSketchFailed, "board 'driver': abort() called in loop()", "NOT RUN "},
    // Crashes: the signal, the entry point and the sketch's own frames; the line printed just
    // before the crash is not lost.
    {"NullWrite", kSketchFailed, "SIGSEGV (invalid memory access", "[driver] about to write through a null pointer",
     true, true},
    {"EndlessRecursion", kSketchFailed, "deeper(int)", "NOT RUN "},
    {"TimerCrash", kSketchFailed, "tick()", "NOT RUN ", true, true},
    // exit() from a global constructor, before the board is attached: the process says so.
    {"ExitWhileLoading", kSketchFailed, "a sketch ended the program (exit() or abort()) while loading", "", false},
};

std::string case_name(const ::testing::TestParamInfo<Case>& info) { return info.param.sketch; }

INSTANTIATE_TEST_SUITE_P(Fixtures, ContainedSketch, ::testing::ValuesIn(kCases), case_name);

TEST(ContainedSketch, ACrashReportNamesTheLineOfTheSketch) {
  if (kSanitizerBuild) GTEST_SKIP() << "UBSan reports this sketch's null write itself";
  const CommandResult result = run_fixture("NullWrite");
  EXPECT_NE(result.err.find("in loop() at t = 0.000000 s"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("#0 loop() at " + fixture("NullWrite") + "/NullWrite.ino:11"), std::string::npos)
      << result.err;
}

TEST(ContainedSketch, ACrashInTheFirstFunctionNamesTheLineOfTheSketch) {
  if (kSanitizerBuild) GTEST_SKIP() << "UBSan reports this sketch's null write itself";
  const CommandResult result = run_fixture("NullWriteInSetup");
  EXPECT_NE(result.err.find("#0 setup() at " + fixture("NullWriteInSetup") + "/NullWriteInSetup.ino:8"),
            std::string::npos)
      << result.err;
}

TEST(ContainedSketch, TheOutputsAreWrittenWhenASketchIsStopped) {
  const std::string scratch = test_output_dir("contained_outputs");
  const CommandResult result = stepdance("sim " + fixture("ExitInLoop") + " --out " + scratch + "/out", scratch);
  EXPECT_EQ(result.exit_code, kSketchFailed);
  const std::string summary = read_file(scratch + "/out/summary.json");
  EXPECT_NE(summary.find("\"what\": \"exit(0) called\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"simulated_time_s\": 0.501"), std::string::npos) << summary;
}

// A sketch that writes without end cannot fill the host's disk or use up the simulator's files:
// its card takes 64 MiB written per run and 16 open files, refuses the rest as a full card would,
// and the run says how much. RunawayCard opens log.bin and 40 more files it never closes (15 of
// them fit, taking "0".."14": 10 × 1 + 5 × 2 = 20 bytes), then writes 100 blocks of 1 MiB:
// 63 fit beside the 20 bytes, 37 are refused.
TEST(ContainedSketch, ARunawayCardWriterIsHeldToTheCardsLimits) {
  const std::string scratch = test_output_dir("contained_RunawayCard");
  const CommandResult result = run_fixture("RunawayCard");
  EXPECT_EQ(result.exit_code, kOk) << result.out << result.err;
  EXPECT_NE(result.out.find("[driver] warning ×37: SD card: full (first: the card takes 64 MiB written per run; "
                            "38797312 bytes refused)"),
            std::string::npos)
      << result.out;
  EXPECT_NE(result.out.find("[driver] warning ×25: SD card: too many open files"), std::string::npos) << result.out;
  const std::string card = scratch + "/out/driver.sd";
  EXPECT_EQ(std::filesystem::file_size(card + "/log.bin"), 63u * 1048576u);
  size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(card)) files += entry.is_regular_file() ? 1 : 0;
  EXPECT_EQ(files, 16u);
  EXPECT_NE(read_file(scratch + "/out/summary.json").find("\"SD card: full\": 37"), std::string::npos);
}

// SIGTERM (and Ctrl-C) end a batch run stuck in a sketch within a second, writing the outputs,
// with 128 + the signal's number. A first run, ended by a short watchdog, compiles the sketch into
// the cache; the signal goes to the second once it has spent 1 s of processor time (loading takes
// far less; the busy loop() takes all it gets), so it reaches a run that is in loop() however
// loaded the machine is, not one still loading.
TEST(ContainedSketch, SigtermEndsAStuckBatchRunWithItsOutputs) {
  const std::string scratch = test_output_dir("contained_sigterm");
  std::filesystem::create_directories(scratch);
  const std::string warm_up =
      kStepdance + " sim " + fixture("BusyLoop") + " --out " + scratch + "/warm-up --watchdog-s 0.2 >/dev/null 2>&1; ";
  const std::string command = warm_up + kStepdance + " sim " + fixture("BusyLoop") + " --out " + scratch +
                              "/out --watchdog-s 60 >" + scratch + "/stdout.txt 2>" + scratch +
                              "/stderr.txt & pid=$!; ticks=$(getconf CLK_TCK); for i in $(seq 600); do "
                              "kill -0 $pid 2>/dev/null || break; [ $(cut -d\\) -f2 /proc/$pid/stat | cut -d\\  -f13) "
                              "-ge $ticks ] && break; sleep 0.05; done; "
                              "kill -TERM $pid; start=$(date +%s%N); wait $pid; "
                              "status=$?; echo $(( ($(date +%s%N) - start) / 1000000 )) >" +
                              scratch + "/ms.txt; exit $status";
  const int status = std::system(("bash -c '" + command + "'").c_str());
  EXPECT_EQ(WEXITSTATUS(status), 128 + 15);
  EXPECT_LT(std::stol(read_file(scratch + "/ms.txt")), 1000);
  EXPECT_NE(read_file(scratch + "/stderr.txt").find("terminated (SIGTERM) in loop()"), std::string::npos);
  EXPECT_NE(read_file(scratch + "/out/summary.json").find("\"what\": \"terminated (SIGTERM)\""), std::string::npos);
}

}  // namespace
}  // namespace stepdance::sim::test
