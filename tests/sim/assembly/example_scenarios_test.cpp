// Every example's batch scenarios run, and every [[expect]] in them holds (live.toml files are
// for --live and are left out). A new example is covered as soon as it has a scenario.
#include <algorithm>
#include <filesystem>

#include "simulation_fixture.hpp"

namespace stepdance::sim::test {
namespace {

std::vector<std::string> example_scenarios() {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(source_path("examples"))) {
    if (entry.path().extension() != ".toml" || entry.path().filename() == "live.toml") continue;
    if (entry.path().string().find("sim-out") != std::string::npos) continue;
    files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

class ExampleScenario : public ::testing::TestWithParam<std::string> {};

TEST_P(ExampleScenario, EveryExpectationHolds) {
  const scenario::Scenario loaded = load(GetParam());
  ASSERT_FALSE(loaded.expectations.empty()) << GetParam() << " checks nothing";
  auto simulation = create(loaded, "example_" + std::to_string(std::hash<std::string>{}(GetParam())), false);
  ASSERT_NE(simulation, nullptr);
  const SimulationReport report = simulation->finish();
  for (const ExpectationResult& result : report.expectations) EXPECT_TRUE(result.met) << result.message;
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = std::filesystem::relative(info.param, source_path("examples")).replace_extension().string();
  std::replace_if(
      name.begin(), name.end(), [](char c) { return !isalnum(static_cast<unsigned char>(c)); }, '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(Examples, ExampleScenario, ::testing::ValuesIn(example_scenarios()), test_name);

}  // namespace
}  // namespace stepdance::sim::test
