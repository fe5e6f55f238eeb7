// The `stepdance` command as a user runs it: exit statuses, `file:line:` errors, decode output.
#include <algorithm>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace stepdance::sim::test {
namespace {

std::string write_scenario(const std::string& directory, const std::string& text) {
  std::filesystem::create_directories(directory);
  const std::string path = directory + "/scenario.toml";
  std::ofstream(path) << text;
  return path;
}

TEST(CliTest, HelpWorksForEveryCommand) {
  const std::string scratch = test_output_dir("cli_help");
  EXPECT_EQ(stepdance("--help", scratch).exit_code, 0);
  const CommandResult sim = stepdance("sim --help", scratch);
  EXPECT_EQ(sim.exit_code, 0);
  EXPECT_NE(sim.out.find("--no-vcd"), std::string::npos);
  EXPECT_EQ(stepdance("decode --help", scratch).exit_code, 0);
  EXPECT_EQ(stepdance("frobnicate", scratch).exit_code, 2);
}

TEST(CliTest, ABadScenarioGivesFileLineAndExitTwo) {
  const std::string scratch = test_output_dir("cli_bad_scenario");
  const std::string path = write_scenario(
      scratch, "duration_s = 1\n\n[[board]]\nname = \"b\"\nsketch = \"StepASketch.ino\"\nloop_period_us = -5\n");
  const CommandResult result = stepdance("sim " + path, scratch);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find(path + ":6: "), std::string::npos) << result.err;
}

TEST(CliTest, ASketchThatDoesNotCompileNamesItsLineAndExitsTwo) {
  const std::string scratch = test_output_dir("cli_bad_sketch");
  std::filesystem::create_directories(scratch);
  std::ofstream(scratch + "/Broken.ino")
      << "#define module_driver\n#include \"stepdance.hpp\"\n\nvoid setup() { no_such_function(); }\nvoid loop() {}\n";
  const std::string path =
      write_scenario(scratch, "duration_s = 1\n[[board]]\nname = \"b\"\nsketch = \"Broken.ino\"\n");
  const CommandResult result = stepdance("sim --quiet --cache " + kSketchCache + " " + path, scratch);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.err.find("Broken.ino:4:"), std::string::npos) << result.err;
}

TEST(CliTest, AFailedExpectationExitsThree) {
  const std::string scratch = test_output_dir("cli_expectation");
  const std::string path = write_scenario(scratch, "duration_s = 0.1\n[[board]]\nname = \"driver\"\nsketch = \"" +
                                                       source_path("examples/StepASketch/StepASketch.ino") +
                                                       "\"\n[board.sockets]\nA = { device = \"stepper\" }\n"
                                                       "[output]\nsvg = \"\"\npng = \"\"\n"
                                                       "[[expect]]\nmotor = \"driver:A\"\nsteps = 5\n");
  const CommandResult result = stepdance("sim --cache " + kSketchCache + " --out " + scratch + "/out " + path, scratch);
  EXPECT_EQ(result.exit_code, 3);
  EXPECT_NE(result.out.find("FAILED  " + path + ":10: motor driver:A steps: expected 5, got 0"), std::string::npos)
      << result.out;
}

TEST(CliTest, DecodeOfTheSimulatorsVcdMatchesItsSummary) {
  const std::string scratch = test_output_dir("cli_decode");
  const CommandResult run = stepdance("sim --quiet --cache " + kSketchCache + " --out " + scratch + "/out " +
                                          source_path("examples/ChainedPlotterDriver"),
                                      scratch);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const CommandResult decoded = stepdance("decode --json " + scratch + "/out/cable.vcd", scratch);
  ASSERT_EQ(decoded.exit_code, 0) << decoded.err;
  const nlohmann::json report = nlohmann::json::parse(decoded.out);
  const nlohmann::json summary = nlohmann::json::parse(read_file(scratch + "/out/summary.json"));
  EXPECT_EQ(report["ports"]["knobs.OUT_A"]["pulses"], summary["ports"]["knobs:OUT_A"]["pulses"]);
  EXPECT_EQ(report["ports"]["plotter.IN_A"]["pulses"], summary["ports"]["plotter:IN_A"]["pulses"]);
  EXPECT_EQ(report["ports"]["plotter.IN_A"]["rejected"]["too_short"],
            summary["ports"]["plotter:IN_A"]["rejected"]["too_short"]);
}

// Found by hand (issue 38): 20 × 5,000 `x` printed without a newline, then "END", showed 5,794
// of the 100,000 bytes: the 4,096-byte pieces of the long line were folded as repeated lines.
TEST(CliTest, ConsoleTextWithoutANewlineIsShownWhole) {
  const std::string scratch = test_output_dir("cli_console_pieces");
  std::filesystem::create_directories(scratch);
  std::ofstream(scratch + "/Pieces.ino") << "#define module_driver\n#include \"stepdance.hpp\"\n"
                                            "void setup() {\n  Serial.begin(115200);\n  static char block[5001];\n"
                                            "  memset(block, 'x', 5000);\n"
                                            "  for (int i = 0; i < 20; ++i) Serial.print(block);\n"
                                            "  Serial.println(\"END\");\n  dance_start();\n}\n"
                                            "void loop() { dance_loop(); }\n";
  const std::string scenario = write_scenario(
      scratch, "duration_s = 0.2\n[[board]]\nname = \"driver\"\nsketch = \"Pieces.ino\"\nmodule = \"driver\"\n");
  const CommandResult result =
      stepdance("sim --cache " + kSketchCache + " --out " + scratch + "/out " + scenario, scratch);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  std::istringstream lines(result.out);
  size_t shown = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("[driver] ", 0) == 0) shown += static_cast<size_t>(std::count(line.begin(), line.end(), 'x'));
  }
  EXPECT_EQ(shown, 100000u);
  EXPECT_NE(result.out.find("xEND\n"), std::string::npos);
  EXPECT_EQ(result.out.find("the same line"), std::string::npos) << result.out.substr(0, 200);
}

TEST(CliTest, DecodeOfAMissingWireIsBadInput) {
  const std::string scratch = test_output_dir("cli_decode_missing");
  const CommandResult run = stepdance("sim --quiet --cache " + kSketchCache + " --out " + scratch + "/out " +
                                          source_path("examples/ChainedPlotterDriver"),
                                      scratch);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const CommandResult decoded =
      stepdance("decode --step nope --dir knobs.OUT_A_DIR " + scratch + "/out/cable.vcd", scratch);
  EXPECT_EQ(decoded.exit_code, 2);
  EXPECT_NE(decoded.err.find("nope"), std::string::npos) << decoded.err;
}

}  // namespace
}  // namespace stepdance::sim::test
