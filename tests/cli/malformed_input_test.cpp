// Malformed input refused at the door: scenario numbers out of range (tiny, huge, at and beyond
// the 64-bit limits, nan and inf), the same numbers on the command line, outputs that cannot be
// written, truncated and over-long captures, and usage errors. Each case checks the exit status
// and the message; the test runner's timeout catches a hang. The expected ranges are the ones
// docs/scenario-format.md states.
#include <algorithm>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace stepdance::sim::test {
namespace {

const std::string kFixtures = source_path("tests/sim/assembly/fixtures/malformed");

/// Runs `stepdance <arguments>` in a scratch folder named after the case.
CommandResult run(const std::string& arguments, const std::string& name) {
  return stepdance(arguments, test_output_dir("malformed_" + name));
}

/// Runs `stepdance sim` on a fixture and expects exit 2 with every `file:line: message` given.
void expect_refused(const std::string& fixture, const std::vector<std::pair<int, std::string>>& errors) {
  const std::string path = kFixtures + "/" + fixture;
  const CommandResult result = run("sim --quiet --cache " + kSketchCache + " " + path, fixture);
  EXPECT_EQ(result.exit_code, 2) << fixture << "\n" << result.err;
  for (const auto& [line, message] : errors) {
    const std::string expected = path + ":" + std::to_string(line) + ": " + message;
    EXPECT_NE(result.err.find(expected), std::string::npos) << "expected: " << expected << "\ngot:\n" << result.err;
  }
  EXPECT_EQ(result.out, "");  // nothing ran
}

// ---- scenario numbers -----------------------------------------------------------------------

TEST(MalformedScenarioTest, CsvIntervalsTooSmallOrTooLarge) {
  expect_refused("csv-interval-tiny.toml", {{10, "'csv_interval_ms' must be in [0.04, 86,400,000] ms, got 1e-09"}});
  expect_refused("csv-interval-huge.toml", {{9, "'csv_interval_ms' must be in [0.04, 86,400,000] ms, got 1e+300"}});
}

TEST(MalformedScenarioTest, LoopPeriodsOutOfRange) {
  expect_refused("loop-period-huge.toml",
                 {{7, "'loop_period_us' must be in [1, 1,000,000] µs, got 9,223,372,036,854,775,807"}});
  expect_refused("loop-period-zero.toml", {{6, "'loop_period_us' must be in [1, 1,000,000] µs, got 0"}});
}

TEST(MalformedScenarioTest, CableNumbersAtTheSixtyFourBitLimits) {
  expect_refused("cable-extremes.toml",
                 {{15, "'delay_ns' must be in [0, 1,000,000,000] ns, got 9,223,372,036,854,775,807"},
                  {16, "'stretch_ns' must be in [-1,000,000,000, 1,000,000,000] ns, got -9,223,372,036,854,775,808"},
                  {17, "'glitch_every_us' must be in [0, 86,400,000,000] µs, got 9,223,372,036,854,775,807"},
                  {18, "'glitch_width_ns' must be in [1, 1,000,000] ns, got 9,223,372,036,854,775,807"}});
}

TEST(MalformedScenarioTest, EncoderCountsAtTheSixtyFourBitLimits) {
  const std::string range = "[-1,000,000,000,000, 1,000,000,000,000] counts";
  expect_refused("encoder-extremes.toml",
                 {{13, "'start_count' must be in " + range + ", got -9,223,372,036,854,775,808"},
                  {18, "'counts' must be in " + range + ", got 9,223,372,036,854,775,807"}});
}

TEST(MalformedScenarioTest, DurationsThatAreNotARun) {
  expect_refused("duration-nan.toml", {{1, "'duration_s' must be a finite number"}});
  expect_refused("duration-inf.toml", {{1, "'duration_s' must be a finite number"}});
  expect_refused("duration-1e300.toml", {{1, "'duration_s' must be in [1e-09, 86,400] s, got 1e+300"}});
  expect_refused("duration--1.toml", {{1, "'duration_s' must be in [1e-09, 86,400] s, got -1"}});
  expect_refused("duration-0.toml", {{1, "'duration_s' must be in [1e-09, 86,400] s, got 0"}});
}

TEST(MalformedScenarioTest, TimelineTimesBeyondAnyRun) {
  expect_refused("timeline-huge.toml", {{21, "'time_s' must be in [0, 86,400] s, got 1e+300"},
                                        {28, "'over_s' must be in [0, 86,400] s, got 1e+300"},
                                        {33, "'hold_ms' must be a finite number"}});
}

// Found by hand (issue 27): travel_mm = [1e30, 1e30] ran the whole run and then failed drawing
// the PNG, without a summary. Travel is bounded when the file is read, and a plotter's PNG,
// whose page is its travel area, is sized before anything runs.
TEST(MalformedScenarioTest, WholeRunLimitsAreCheckedBeforeTheRun) {
  expect_refused("travel-huge.toml",
                 {{16, "'travel_mm' must be two numbers in (0, 1,000,000] mm, e.g. [300, 218]"},
                  {17, "'start_mm' must be two numbers in [-1,000,000, 1,000,000] mm, e.g. [120.5, 80]"}});
  const std::string path = kFixtures + "/canvas-huge.toml";
  const CommandResult result = run("sim --quiet --cache " + kSketchCache + " " + path, "canvas");
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_EQ(result.err, path +
                            ":15: at png_px_per_mm = 4, the plotter's page (travel_mm and a 10 mm margin) is too "
                            "large for a PNG: the PNG would be 4,000,080 x 8,080 px; at most 32,767 px a side and "
                            "64,000,000 px (lower png_px_per_mm or travel_mm, or set png = \"\")\n");
  EXPECT_FALSE(std::filesystem::exists(kFixtures + "/never-written"));
}

// ---- the same numbers on the command line ------------------------------------------------------

TEST(MalformedCommandLineTest, DurationFollowsTheFilesRule) {
  const std::string scenario = source_path("examples/StepASketch");
  for (const char* value : {"nan", "inf", "1e300", "-1", "0", "86401"}) {
    const CommandResult result = run("sim --duration " + std::string(value) + " " + scenario, "duration");
    EXPECT_EQ(result.exit_code, 2) << value;
    EXPECT_EQ(result.err, "--duration: must be in [1e-09, 86,400] s, got " + std::string(value) + "\n") << value;
  }
  const CommandResult words = run("sim --duration soon " + scenario, "duration_words");
  EXPECT_EQ(words.exit_code, 2);
  EXPECT_EQ(words.err, "--duration: 'soon' is not a decimal number (allowed: [1e-09, 86,400] s)\n");
}

TEST(MalformedCommandLineTest, CsvIntervalAndSpeedFollowTheirRules) {
  const std::string scenario = source_path("examples/StepASketch");
  const CommandResult tiny = run("sim --csv-interval-ms 1e-6 " + scenario, "csv_interval");
  EXPECT_EQ(tiny.exit_code, 2);
  EXPECT_EQ(tiny.err, "--csv-interval-ms: must be in [0.04, 86,400,000] ms, got 1e-6\n");
  const CommandResult speed = run("sim --live --speed nan " + scenario, "speed");
  EXPECT_EQ(speed.exit_code, 2);
  EXPECT_EQ(speed.err, "--speed: must be in (0, 1,000,000] x real time, got nan (or 'max')\n");
}

// Found by hand (issue 27): strtod read "0x10" as 16 s and " 2" as 2 but refused "1 ", and
// 1e-300 s passed the (0, 86,400] check and ran for 0 ns. One decimal grammar now reads every
// number option, and a run lasts at least a nanosecond.
TEST(MalformedCommandLineTest, NumbersAreDecimalWithNothingAroundThem) {
  const std::string scenario = source_path("examples/StepASketch");
  const std::pair<std::string, std::string> cases[] = {
      {"sim --duration 0x10 ", "--duration: '0x10' is not a decimal number (allowed: [1e-09, 86,400] s)\n"},
      {"sim --duration ' 2' ", "--duration: ' 2' is not a decimal number (allowed: [1e-09, 86,400] s)\n"},
      {"sim --duration '1 ' ", "--duration: '1 ' is not a decimal number (allowed: [1e-09, 86,400] s)\n"},
      {"sim --duration 1e-300 ", "--duration: must be in [1e-09, 86,400] s, got 1e-300\n"},
      {"sim --csv-interval-ms 0x10 ",
       "--csv-interval-ms: '0x10' is not a decimal number (allowed: [0.04, 86,400,000] ms)\n"},
      {"sim --live --speed 0x2 ",
       "--speed: '0x2' is not a decimal number (allowed: (0, 1,000,000] x real time) (or 'max')\n"},
      {"serve --speed nan ", "--speed: must be in [0.001, 1,000] x real time, got nan\n"},
      {"serve --speed 0x2 ", "--speed: '0x2' is not a decimal number (allowed: [0.001, 1,000] x real time)\n"},
      {"serve --port 0x1f41 ", "--port: '0x1f41' is not a whole decimal number (allowed: [0, 65,535])\n"},
      {"serve --port 70000 ", "--port: must be in [0, 65,535], got 70000\n"},
      {"serve --baud ' 9600' ", "--baud: ' 9600' is not a whole decimal number (allowed: [1, 10,000,000] baud)\n"}};
  for (const auto& [arguments, message] : cases) {
    const CommandResult result = run(arguments + scenario, "decimal");
    EXPECT_EQ(result.exit_code, 2) << arguments;
    EXPECT_EQ(result.err, message) << arguments;
    EXPECT_EQ(result.out, "") << arguments;
  }
  const std::string capture = kFixtures + "/long-pulses.vcd";
  for (const char* value : {"0x28", "' 40'", "'40 '", "40.0"}) {
    const CommandResult result = run("decode --frame-us " + std::string(value) + " " + capture, "decimal_frame");
    EXPECT_EQ(result.exit_code, 2) << value;
    EXPECT_NE(result.err.find("--frame-us must be 10, 20, 25 or 40"), std::string::npos) << result.err;
  }
}

// Found by hand (issue 27): --speed and --serial-link did nothing without --live, silently.
TEST(MalformedCommandLineTest, LiveOptionsNeedLive) {
  const std::string scenario = source_path("examples/StepASketch");
  const CommandResult speed = run("sim --speed 2 " + scenario, "live_only");
  EXPECT_EQ(speed.exit_code, 2);
  EXPECT_EQ(speed.err, "--speed: needs --live (it paces a live run)\n");
  const CommandResult link = run("sim --serial-link driver=/tmp/never-made " + scenario, "live_only");
  EXPECT_EQ(link.exit_code, 2);
  EXPECT_EQ(link.err, "--serial-link: needs --live (it names a live run's terminal)\n");
  EXPECT_EQ(link.out, "");
}

// Found by hand (issue 38): `[output] vcd` without `vcd_ports` wrote an empty VCD.
TEST(MalformedScenarioTest, AVcdWithoutPortsIsRefusedAtLoad) {
  expect_refused("vcd-without-ports.toml",
                 {{9, "'vcd' (\"wire.vcd\") records the ports 'vcd_ports' lists, and it lists none"}});
}

// Found by hand (issue 38): `--duration 86400 --vcd` started without a word (about 2.6 GB).
// One port for 2,000 s at 25,000 frames × 3 edges × 19 bytes a second: 2.85 GB, above 1 GB.
TEST(MalformedScenarioTest, AVcdThatCouldPassItsCapIsRefusedWithTheEstimate) {
  const std::string scratch = test_output_dir("malformed_vcd_cap");
  const std::string path = kFixtures + "/vcd-too-large.toml";
  const CommandResult result =
      run("sim --quiet --cache " + kSketchCache + " --out " + scratch + "/out " + path, "vcd_cap");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(
      result.err.find(scratch + "/out/wire.vcd: the VCD could reach 2.85 GB (1 port(s) × at most 1.425 MB per "
                                "simulated second × 2000 s), above the cap of 1.00 GB: raise it with --vcd-max-gb 3"),
      std::string::npos)
      << result.err;
  EXPECT_FALSE(std::filesystem::exists(scratch + "/out/wire.vcd"));
  EXPECT_EQ(result.out, "");
  // --duration shortens the run under the cap; --no-vcd leaves the VCD out: both run.
  EXPECT_EQ(run("sim --quiet --no-vcd --duration 0.1 --cache " + kSketchCache + " --out " + scratch + "/out2 " + path,
                "vcd_cap")
                .exit_code,
            0);
  EXPECT_EQ(
      run("sim --quiet --vcd-max-gb 3 --duration 0.1 --cache " + kSketchCache + " --out " + scratch + "/out3 " + path,
          "vcd_cap")
          .exit_code,
      0);
}

// Found by hand (issue 38): `decode --step X --dir X` decoded one wire as both.
TEST(MalformedCommandLineTest, DecodeRefusesTheSameWireTwice) {
  const std::string capture = kFixtures + "/long-pulses.vcd";
  for (const char* names :
       {"--step upstream.OUT_A_STEP --dir upstream.OUT_A_STEP", "--step OUT_A_DIR --dir OUT_A_DIR"}) {
    const CommandResult result = run("decode " + std::string(names) + " " + capture, "same_wire");
    EXPECT_EQ(result.exit_code, 2) << names;
    EXPECT_NE(result.err.find("--step and --dir name the same wire"), std::string::npos) << result.err;
    EXPECT_EQ(result.out, "") << names;
  }
}

// Found by hand (issue 38): a --serial-link naming no board exited 1; docs/simulator.md says bad input is 2.
TEST(MalformedCommandLineTest, ASerialLinkToNoBoardIsBadInput) {
  const std::string scratch = test_output_dir("malformed_serial_link_board");
  const CommandResult link =
      run("sim --live --duration 1 --serial-link nosuch=" + scratch + "/link " + source_path("examples/StepASketch"),
          "serial_link_board");
  EXPECT_EQ(link.exit_code, 2);
  EXPECT_EQ(link.err, "--serial-link: no board named 'nosuch'\n");
  EXPECT_EQ(link.out, "");
}

// Found by hand (issue 27): `--out ""` wrote into the example's own folder (an empty option was
// taken as no option), and --serial-link deleted the file it was given to make a symlink.
TEST(MalformedCommandLineTest, EmptyPathsAndFilesInTheWayOfALinkAreRefused) {
  const std::string scenario = source_path("examples/StepASketch");
  for (const char* option : {"--out", "--vcd", "--csv", "--cache"}) {
    const CommandResult result = run("sim " + std::string(option) + " '' " + scenario, "empty_path");
    EXPECT_EQ(result.exit_code, 2) << option;
    EXPECT_NE(result.err.find(std::string(option) + ": must not be empty"), std::string::npos) << result.err;
    EXPECT_EQ(result.out, "") << option;
  }
  const std::string scratch = test_output_dir("malformed_serial_link");
  std::filesystem::create_directories(scratch);
  const std::string notes = scratch + "/notes.txt";
  std::ofstream(notes) << "my notes\n";
  const CommandResult link = run("sim --live --serial-link driver=" + notes + " " + scenario, "serial_link");
  EXPECT_EQ(link.exit_code, 2);
  EXPECT_EQ(link.err,
            "--serial-link: '" + notes + "' exists and is not a symlink; it would be deleted (name a new path)\n");
  EXPECT_EQ(read_file(notes), "my notes\n");
}

TEST(MalformedCommandLineTest, AnUnwritableOutputIsRefusedBeforeTheRun) {
  const std::string scratch = test_output_dir("malformed_unwritable");
  std::filesystem::create_directories(scratch);
  const std::string file = scratch + "/a-file";
  std::ofstream(file) << "not a folder\n";
  const std::string scenario = source_path("examples/StepASketch");
  // A sketch cache nobody has filled: had the run started, the sketch would have been built there.
  const std::string cache = scratch + "/cache";
  const CommandResult out = run("sim --quiet --cache " + cache + " --out " + file + "/out " + scenario, "unwritable");
  EXPECT_EQ(out.exit_code, 2);
  EXPECT_EQ(out.err.rfind("cannot create the output folder " + file + "/out: ", 0), 0u) << out.err;
  const CommandResult vcd = run(
      "sim --quiet --cache " + cache + " --out " + scratch + "/out --vcd " + file + "/x.vcd " + scenario, "unwritable");
  EXPECT_EQ(vcd.exit_code, 2);
  EXPECT_EQ(vcd.err.rfind("cannot create the output folder " + file + ": ", 0), 0u) << vcd.err;
  EXPECT_FALSE(std::filesystem::exists(cache));
}

// ---- captures ---------------------------------------------------------------------------------

nlohmann::json decode_json(const std::string& arguments, int expected_exit, const std::string& name) {
  const CommandResult result = run("decode --json " + arguments, name);
  EXPECT_EQ(result.exit_code, expected_exit) << result.err;
  return nlohmann::json::parse(result.out);
}

TEST(MalformedCaptureTest, ATruncatedCaptureIsDecodedAndReported) {
  const std::string path = kFixtures + "/truncated.vcd";
  const CommandResult text = run("decode " + path, "truncated");
  EXPECT_EQ(text.exit_code, 4);
  EXPECT_EQ(text.err, "warning: " + path +
                          ":22: the capture is truncated (it ends in the middle of line 22); "
                          "decoded up to there\n");
  const nlohmann::json report = decode_json(path, 4, "truncated_json");
  const nlohmann::json& port = report["ports"]["upstream.OUT_A"];
  EXPECT_EQ(port["accepted"], 3);  // the three 2 µs X pulses before the cut
  EXPECT_EQ(port["pulses"]["X"]["forward"], 3);
  EXPECT_NE(report["truncated"].get<std::string>().find("truncated"), std::string::npos);

  const std::string dump = kFixtures + "/truncated-in-dumpvars.vcd";
  const CommandResult in_dump = run("decode " + dump, "truncated_dump");
  EXPECT_EQ(in_dump.exit_code, 4);
  EXPECT_NE(in_dump.err.find("a dump block has no $end"), std::string::npos) << in_dump.err;
}

TEST(MalformedCaptureTest, LongPulsesAreTooLongForStepdanceAndStepsForStepDir) {
  // 8 µs, 437 µs, 439 µs, 1 ms and 1 s: all wider than E's 7 µs.
  const std::string path = kFixtures + "/long-pulses.vcd";
  const nlohmann::json stepdance = decode_json(path, 0, "long_stepdance")["ports"]["upstream.OUT_A"];
  EXPECT_EQ(stepdance["accepted"], 0);
  EXPECT_EQ(stepdance["rejected"]["too_long"], 5);
  EXPECT_EQ(stepdance["rejected"]["too_short"], 0);
  const nlohmann::json step_dir =
      decode_json("--mode step_dir --axis Y " + path, 0, "long_step_dir")["ports"]["upstream.OUT_A"];
  EXPECT_EQ(step_dir["accepted"], 5);
  EXPECT_EQ(step_dir["pulses"]["Y"]["forward"], 5);
  EXPECT_EQ(step_dir["rejected"]["too_long"], 0);
}

TEST(MalformedCaptureTest, AFramePeriodTheBoardsCannotRunIsRefused) {
  const std::string path = kFixtures + "/long-pulses.vcd";
  for (const char* value : {"15", "0", "80"}) {
    const CommandResult result = run("decode --frame-us " + std::string(value) + " " + path, "frame_us");
    EXPECT_EQ(result.exit_code, 2) << value;
    EXPECT_EQ(result.err, "--frame-us must be 10, 20, 25 or 40 (the sending board's frame period), got " +
                              std::string(value) + "\n")
        << value;
  }
  const nlohmann::json fast = decode_json("--frame-us 10 " + path, 0, "frame_us_10")["ports"]["upstream.OUT_A"];
  EXPECT_EQ(fast["frames"]["period_us"], 10);
}

TEST(MalformedCaptureTest, AnOversizedCaptureDecodesInTimeLinearInItsWires) {
  // 50,000 STEP/DIR pairs (100,000 wires): pairing them two by two took minutes.
  const std::string scratch = test_output_dir("malformed_oversized");
  std::filesystem::create_directories(scratch);
  const std::string path = scratch + "/wide.vcd";
  {
    std::ofstream vcd(path);
    vcd << "$timescale 1ns $end\n$scope module wide $end\n";
    for (int pair = 0; pair < 50000; ++pair) {
      vcd << "$var wire 1 s" << pair << " P" << pair << "_STEP $end\n$var wire 1 d" << pair << " P" << pair
          << "_DIR $end\n";
    }
    vcd << "$upscope $end\n$enddefinitions $end\n#0\n#1000\n1s49999\n#3000\n0s49999\n#4000\n";
  }
  const CommandResult result = run("decode --json " + path, "oversized");
  ASSERT_EQ(result.exit_code, 0) << result.err.substr(0, 500);
  const nlohmann::json report = nlohmann::json::parse(result.out);
  EXPECT_EQ(report["ports"].size(), 50000u);
  EXPECT_EQ(report["ports"]["wide.P49999"]["pulses"]["X"]["reverse"], 1);
}

// ---- usage --------------------------------------------------------------------------------------

TEST(CommandLineOutputsTest, VcdAndCsvCanBeAskedForOnTheCommandLine) {
  const std::string scratch = test_output_dir("malformed_vcd_csv");
  const CommandResult result =
      run("sim --quiet --cache " + kSketchCache + " --out " + scratch + "/out --duration 0.5 --vcd " + scratch +
              "/run.vcd --csv " + scratch + "/run.csv --csv-interval-ms 100 " + source_path("examples/StepASketch"),
          "vcd_csv");
  EXPECT_EQ(result.exit_code, 3);  // half a second is too short for the example's expectations
  // A header and a row every 100 ms from 0 to 500 ms.
  const std::string csv = read_file(scratch + "/run.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 7);
  // The scenario names no vcd_ports, so the output ports are recorded: at least the three the
  // sketch drives (OUT_D, which it never begins, is not in the file: see the branch report).
  const nlohmann::json report = decode_json(scratch + "/run.vcd", 0, "vcd_csv_decode");
  for (const char* port : {"driver.OUT_A", "driver.OUT_B", "driver.OUT_C"}) {
    EXPECT_TRUE(report["ports"].contains(port)) << port;
  }
}

TEST(MalformedUsageTest, AnUnknownCommandNamesTheValidOnes) {
  const CommandResult result = run("frobnicate", "unknown_command");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err.rfind("stepdance: unknown command 'frobnicate'; the commands are: ", 0), 0u) << result.err;
  EXPECT_NE(result.err.find("sim"), std::string::npos);
  EXPECT_NE(result.err.find("decode"), std::string::npos);
  const CommandResult none = run("", "no_command");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_EQ(none.err.rfind("stepdance: a command is needed: ", 0), 0u) << none.err;
}

TEST(MalformedUsageTest, VersionPrintsTheProjectVersion) {
  const CommandResult result = run("--version", "version");
  EXPECT_EQ(result.exit_code, 0);
  EXPECT_EQ(result.out, "stepdance 0.1.0\n");  // library.properties: version=0.1.0
}

TEST(MalformedUsageTest, AFolderWithoutAScenarioSaysWhichScenarioRunsIt) {
  const std::string folder = source_path("examples/ChainedKnobsBasic");
  const CommandResult result = run("sim " + folder, "no_scenario");
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, folder + ": this folder has no scenario.toml; its sketch runs in " +
                            source_path("examples/ChainedPlotterDriver/scenario.toml") + " (stepdance sim " +
                            source_path("examples/ChainedPlotterDriver") + ")\n");
}

}  // namespace
}  // namespace stepdance::sim::test
