// Grbl settings a sender writes survive a re-run of the simulation into the same output folder,
// as they survive a reset of a Teensy in its EEPROM: the store is `<output>/<board>.sd/eeprom.bin`.
#include <filesystem>

#include "simulation_fixture.hpp"

namespace stepdance::sim::test {
namespace {

std::string scenario_text(const std::string& out, const std::string& steps) {
  return "duration_s = 0.5\n" + gcode_step_a_sketch_board() +
         "[[host]]\nboard = \"driver\"\n"
         "[[host.step]]\nwait = \"^Grbl 1\\\\.1\"\ntimeout_s = 0.1\n" +
         steps + "[output]\ndirectory = \"" + out + "\"\nsvg = \"\"\npng = \"\"\nsummary = \"\"\n";
}

/// Runs the scenario into `out` without emptying it first (a re-run into the same folder).
std::unique_ptr<Simulation> run_into(const std::string& out, const std::string& steps) {
  SimulationOptions options;
  plug_test_hooks(options);
  options.output_directory = out;
  options.write_vcd = false;
  SimulationError error;
  auto simulation = Simulation::create(parse(scenario_text(out, steps), out + "-scenario.toml"), options, error);
  EXPECT_NE(simulation, nullptr) << error.message;
  if (simulation != nullptr) simulation->finish();
  return simulation;
}

bool received(const Simulation& simulation, const std::string& line) {
  for (const HostClient::Entry& entry : simulation.host_client("driver")->transcript()) {
    if (!entry.from_host && entry.text == line) return true;
  }
  return false;
}

TEST(GcodeSettingsPersist, ASettingWrittenInOneRunIsListedByTheNext) {
  const std::string out = test_output_dir("gcode_settings_persist");
  std::filesystem::remove_all(out);
  auto first = run_into(out, "[[host.step]]\nstream = \"$110=7200\\n$120=640\\n\"\n");
  ASSERT_NE(first, nullptr);
  ASSERT_TRUE(first->host_client("driver")->completed()) << first->host_client("driver")->failure();
  EXPECT_TRUE(received(*first, "ok"));
  // The board's EEPROM image: 1,080 bytes starting with the store's magic.
  const std::string image = read_file(out + "/driver.sd/eeprom.bin");
  ASSERT_EQ(image.size(), 1080u);
  EXPECT_EQ(image.substr(0, 4), "SDGS");

  auto second =
      run_into(out, "[[host.step]]\nsend = \"$$\\n\"\n[[host.step]]\nwait = \"^\\\\$132=\"\ntimeout_s = 0.1\n");
  ASSERT_NE(second, nullptr);
  ASSERT_TRUE(second->host_client("driver")->completed()) << second->host_client("driver")->failure();
  EXPECT_TRUE(received(*second, "$110=7200.000"));
  EXPECT_TRUE(received(*second, "$120=640.000"));
  EXPECT_TRUE(received(*second, "$121=2000.000"));  // never written: the sketch's default

  // An emptied folder is a fresh board: the defaults again.
  std::filesystem::remove_all(out);
  auto fresh =
      run_into(out, "[[host.step]]\nsend = \"$$\\n\"\n[[host.step]]\nwait = \"^\\\\$132=\"\ntimeout_s = 0.1\n");
  ASSERT_NE(fresh, nullptr);
  EXPECT_TRUE(received(*fresh, "$110=6000.000"));
  std::filesystem::remove_all(out);
}

}  // namespace
}  // namespace stepdance::sim::test
