// OutputFiles on its own: where each file of a run goes (the scenario's name, moved by --out,
// replaced by --vcd/--csv/--html), and which lines a VCD records.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "assembly/output_files.hpp"

namespace stepdance::sim {
namespace {

scenario::Scenario scenario_with_outputs() {
  scenario::Scenario scenario;
  scenario.file = "/runs/plot/scenario.toml";
  scenario.directory = "/runs/plot";
  scenario.output.directory = "/runs/plot/sim-out";
  scenario.output.svg = "/runs/plot/sim-out/drawing.svg";
  scenario.output.vcd = "/runs/plot/sim-out/wires.vcd";
  scenario.output.csv = "/runs/plot/sim-out/motion.csv";
  scenario.output.html = "";
  return scenario;
}

TEST(OutputFilesPaths, TheScenarioNamesStandWithoutOptions) {
  const scenario::Scenario scenario = scenario_with_outputs();
  const SimulationOptions options;
  const OutputFiles files(scenario, options);
  EXPECT_EQ(files.directory(), "/runs/plot/sim-out");
  EXPECT_EQ(files.path_of(scenario.output.svg), "/runs/plot/sim-out/drawing.svg");
  EXPECT_EQ(files.vcd_path(), "/runs/plot/sim-out/wires.vcd");
  EXPECT_EQ(files.csv_path(), "/runs/plot/sim-out/motion.csv");
  EXPECT_EQ(files.html_path(), "");
}

TEST(OutputFilesPaths, OutMovesEveryFileIntoItsFolderKeepingTheNameAndLeavesUnnamedOnesUnwritten) {
  const scenario::Scenario scenario = scenario_with_outputs();
  SimulationOptions options;
  options.output_directory = "/tmp/elsewhere";
  const OutputFiles files(scenario, options);
  EXPECT_EQ(files.directory(), "/tmp/elsewhere");
  EXPECT_EQ(files.path_of(scenario.output.svg), "/tmp/elsewhere/drawing.svg");
  EXPECT_EQ(files.vcd_path(), "/tmp/elsewhere/wires.vcd");
  EXPECT_EQ(files.path_of(""), "");
  EXPECT_EQ(files.html_path(), "");
}

TEST(OutputFilesPaths, ExactOptionPathsWinOverOutAndNoVcdDropsTheScenariosVcd) {
  const scenario::Scenario scenario = scenario_with_outputs();
  SimulationOptions options;
  options.output_directory = "/tmp/elsewhere";
  options.csv_file = "/data/run.csv";
  options.html_file = "/data/replay.html";
  options.write_vcd = false;
  const OutputFiles files(scenario, options);
  EXPECT_EQ(files.csv_path(), "/data/run.csv");
  EXPECT_EQ(files.html_path(), "/data/replay.html");
  EXPECT_EQ(files.vcd_path(), "");
}

std::vector<std::string> names_of(const std::vector<scenario::PortLineRef>& ports) {
  std::vector<std::string> names;
  for (const scenario::PortLineRef& port : ports) {
    names.push_back(port.board + (port.output ? ":OUT_" : ":IN_") + port.port);
  }
  return names;
}

TEST(OutputFilesVcdPorts, TheScenariosListStandsAndVcdAloneRecordsEveryOutputAndEveryCabledInput) {
  scenario::Scenario scenario = scenario_with_outputs();
  scenario.boards.resize(2);
  scenario.boards[0].name = "sender";
  scenario.boards[1].name = "receiver";
  scenario::CableConfig cable;
  cable.from = {"sender", 'A'};
  cable.to = {"receiver", 'B'};
  scenario.cables.push_back(cable);
  SimulationOptions options;
  options.vcd_file = "/tmp/all.vcd";
  const uint8_t outputs = kDriverModuleV1.output_port_count;
  std::vector<std::string> expected;
  for (const char* board : {"sender", "receiver"}) {
    for (char port = 'A'; port < 'A' + outputs; ++port) expected.push_back(std::string(board) + ":OUT_" + port);
  }
  expected.push_back("receiver:IN_B");
  EXPECT_EQ(names_of(OutputFiles(scenario, options).vcd_ports()), expected);
  // Ports named in the scenario are recorded as named, --vcd or not.
  scenario.output.vcd_ports = {{"sender", true, 'C'}};
  EXPECT_EQ(names_of(OutputFiles(scenario, options).vcd_ports()), (std::vector<std::string>{"sender:OUT_C"}));
  // Without --vcd and without a list, the scenario's (empty) list stands.
  scenario.output.vcd_ports.clear();
  EXPECT_TRUE(OutputFiles(scenario, SimulationOptions{}).vcd_ports().empty());
}

}  // namespace
}  // namespace stepdance::sim
