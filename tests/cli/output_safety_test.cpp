// Hands off the user's files (issue 27): an output never replaces an input of the run, never
// collides with another output, never lands outside the output folder. Each case found by hand
// destroyed a file before the fix; now each is refused with the option or line that asked for
// it, exit 2, before anything runs (no output folder is even made). The cases run on a copy of
// tests/sim/assembly/fixtures/OutputSafety, so a regression overwrites only the copy.
#include <filesystem>
#include <fstream>

#include "cli_runner.hpp"

namespace stepdance::sim::test {
namespace {

namespace fs = std::filesystem;

const std::string kFixture = source_path("tests/sim/assembly/fixtures/OutputSafety");

/// A fresh copy of the fixture in a scratch folder named after the case; its scenario gets
/// `extra` appended (TOML text).
std::string copy_fixture(const std::string& name, const std::string& extra = "") {
  const std::string copy = test_output_dir("output_safety_" + name) + "/copy";
  fs::remove_all(copy);
  fs::create_directories(copy);
  fs::copy(kFixture, copy, fs::copy_options::recursive);
  if (!extra.empty()) std::ofstream(copy + "/scenario.toml", std::ios::app) << extra;
  return copy;
}

CommandResult run_sim(const std::string& arguments, const std::string& copy) {
  return stepdance("sim --quiet --cache " + kSketchCache + " " + arguments, fs::path(copy).parent_path().string());
}

/// Expects exit 2 with exactly `message` (one line) and nothing written in the copy's output folder.
void expect_refused(const CommandResult& result, const std::string& copy, const std::string& message) {
  EXPECT_EQ(result.exit_code, 2) << result.err;
  EXPECT_EQ(result.err, message + "\n");
  EXPECT_EQ(result.out, "");
  EXPECT_FALSE(fs::exists(copy + "/out")) << "the run started";
}

TEST(OutputSafetyTest, ACommandLineOutputNeverReplacesTheScenarioOrTheSketch) {
  const std::string copy = copy_fixture("csv_scenario");
  const std::string scenario_text = read_file(copy + "/scenario.toml");
  expect_refused(run_sim("--csv " + copy + "/scenario.toml " + copy, copy), copy,
                 "--csv: would overwrite the scenario " + copy + "/scenario.toml (an output never replaces an input)");
  EXPECT_EQ(read_file(copy + "/scenario.toml"), scenario_text);
  expect_refused(run_sim("--vcd " + copy + "/Sketch/Sketch.ino " + copy, copy), copy,
                 "--vcd: would overwrite a file of the sketch of board 'driver' " + copy +
                     "/Sketch/Sketch.ino (an output never replaces an input)");
  EXPECT_NE(read_file(copy + "/Sketch/Sketch.ino").find("void setup()"), std::string::npos);
}

TEST(OutputSafetyTest, AFileTheTimelineSendsIsAnInputToo) {
  const std::string copy =
      copy_fixture("serial_file", "\n[[at]]\ntime_s = 0\nserial = \"driver\"\nfile = \"lines.txt\"\n");
  std::ofstream(copy + "/lines.txt") << "hello\n";
  expect_refused(
      run_sim("--csv " + copy + "/lines.txt " + copy, copy), copy,
      "--csv: would overwrite the serial file of line 15 " + copy + "/lines.txt (an output never replaces an input)");
  EXPECT_EQ(read_file(copy + "/lines.txt"), "hello\n");
}

TEST(OutputSafetyTest, OutputNamesThatCollideAreRefusedWithTheirLines) {
  const std::string copy = copy_fixture("same_names",
                                        "svg = \"same.txt\"\npng = \"same.txt\"\nsummary = \"same.txt\"\n"
                                        "[machine]\ntype = \"cartesian\"\nboard = \"driver\"\nx = \"A\"\n");
  const std::string file = copy + "/scenario.toml";
  const std::string same = copy + "/out/same.txt";
  const CommandResult result = run_sim(copy, copy);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, file + ":15: 'png' would write " + same + ", which 'svg' (" + file + ":14) also writes\n" +
                            file + ":16: 'summary' would write " + same + ", which 'svg' (" + file +
                            ":14) also writes\n" + file + ":16: 'summary' would write " + same + ", which 'png' (" +
                            file + ":15) also writes\n");
  EXPECT_FALSE(fs::exists(copy + "/out"));
}

TEST(OutputSafetyTest, NamesThatOnlyCollideInOneOutFolderAreRefused) {
  // Without --out they are out/a/x.txt and out/b/x.txt; --out keeps only the file names.
  const std::string copy =
      copy_fixture("flattened", "vcd = \"a/x.txt\"\ncsv = \"b/x.txt\"\nvcd_ports = [\"driver:OUT_A\"]\n");
  const std::string elsewhere = fs::path(copy).parent_path().string() + "/elsewhere";
  const CommandResult result = run_sim("--out " + elsewhere + " " + copy, copy);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err, copy + "/scenario.toml:15: 'csv' would write " + elsewhere + "/x.txt, which 'vcd' (" + copy +
                            "/scenario.toml:14) also writes\n");
  EXPECT_FALSE(fs::exists(elsewhere));
}

TEST(OutputSafetyTest, NothingIsWrittenInsideABoardsSdCardFolder) {
  const std::string copy = copy_fixture("inside_sd", "summary = \"driver.sd/eeprom.bin\"\n");
  const CommandResult result = run_sim(copy, copy);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err,
            copy + "/scenario.toml:14: 'summary' would write " + copy + "/out/driver.sd/eeprom.bin inside " + copy +
                "/out/driver.sd, which the SD card folder of board 'driver' (" + copy + "/scenario.toml:5) writes\n");
}

TEST(OutputSafetyTest, NamesThatWouldLeaveTheOutputFolderAreRefusedWhenTheScenarioIsRead) {
  const std::string copy =
      copy_fixture("escape",
                   "summary = \"../summary.json\"\n"
                   "[[board]]\nname = \"../../x\"\nsketch = \"Sketch/Sketch.ino\"\n"
                   "[[device]]\nname = \"../knob\"\ntype = \"encoder\"\nboard = \"driver\"\nconnector = \"ENC1\"\n"
                   "[[host]]\nboard = \"driver\"\ntranscript = \"/tmp/host.txt\"\n[[host.step]]\nsend = \"?\"\n");
  const std::string file = copy + "/scenario.toml";
  const CommandResult result = run_sim(copy, copy);
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_EQ(result.err,
            file + ":14: 'summary' (\"../summary.json\") must stay inside the output folder (no '..')\n" + file +
                ":16: board name \"../../x\" names its SD card folder (<name>.sd in the output folder), so it "
                "must not contain '/'\n" +
                file +
                ":19: device name \"../knob\" names the device's files in the output folder, so it must not "
                "contain '/'\n" +
                file +
                ":25: 'transcript' (\"/tmp/host.txt\") must be a name inside the output folder, not an "
                "absolute path\n");
  EXPECT_FALSE(fs::exists(fs::path(copy).parent_path() / "x.sd"));
}

// The replay page (--html, [output] html) is checked and replaced as the other outputs are.
TEST(OutputSafetyTest, TheReplayPageIsAnOutputLikeTheOthers) {
  const std::string copy = copy_fixture("html");
  const std::string scenario_text = read_file(copy + "/scenario.toml");
  expect_refused(run_sim("--html " + copy + "/scenario.toml " + copy, copy), copy,
                 "--html: would overwrite the scenario " + copy + "/scenario.toml (an output never replaces an input)");
  EXPECT_EQ(read_file(copy + "/scenario.toml"), scenario_text);
  const std::string named = copy_fixture("html_names", "csv = \"r.html\"\nhtml = \"r.html\"\n");
  const std::string file = named + "/scenario.toml";
  expect_refused(run_sim(named, named), named,
                 file + ":15: 'html' would write " + named + "/out/r.html, which 'csv' (" + file + ":14) also writes");
  fs::create_directories(copy + "/folder.html");
  expect_refused(run_sim("--html " + copy + "/folder.html " + copy, copy), copy,
                 "cannot write " + copy + "/folder.html: it is a folder");
  const CommandResult under_a_file = run_sim("--html " + copy + "/scenario.toml/x.html " + copy, copy);
  EXPECT_EQ(under_a_file.exit_code, 2);
  EXPECT_EQ(under_a_file.err.rfind("cannot create the output folder " + copy + "/scenario.toml: ", 0), 0u)
      << under_a_file.err;
  EXPECT_EQ(read_file(copy + "/scenario.toml"), scenario_text);
}

TEST(OutputSafetyTest, AnExistingReplayPageIsReplacedAndNothingBesideIt) {
  const std::string copy = copy_fixture("html_replaced");
  fs::create_directories(copy + "/out");
  std::ofstream(copy + "/out/run.html") << "an older page";
  std::ofstream(copy + "/out/notes.txt") << "mine";
  const CommandResult result = run_sim("--html " + copy + "/out/run.html " + copy, copy);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  const std::string page = read_file(copy + "/out/run.html");
  EXPECT_EQ(page.rfind("<!doctype html>", 0), 0u);
  EXPECT_NE(page.find("id=\"stepdance-replay\""), std::string::npos);
  EXPECT_EQ(page.find("<script src"), std::string::npos);
  EXPECT_EQ(read_file(copy + "/out/notes.txt"), "mine");
}

TEST(OutputSafetyTest, TheFixtureRunsWhenNothingCollides) {
  const std::string copy = copy_fixture("fine");
  const CommandResult result = run_sim(copy, copy);
  EXPECT_EQ(result.exit_code, 0) << result.err;
  EXPECT_TRUE(fs::exists(copy + "/out/summary.json"));
}

}  // namespace
}  // namespace stepdance::sim::test
