// Faults on image boards: one fixture sketch per fault kind (tests/sim/image/fault_sketches, built
// into images by scripts/build-teensy.sh), each run alone on a Driver Module. The run must stop
// with the fault named, the sketch's function that faulted as the symbol, and the exit status the
// command line gives a crash (5) or a hang (6).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "../assembly/simulation_fixture.hpp"
#include "image/board/image_source.hpp"

namespace stepdance::sim::test {
namespace {

std::string fault_image(const std::string& name) {
  const char* moved = std::getenv("STEPDANCE_TEENSY_BUILD_DIR");
  const std::string root = moved != nullptr && *moved != '\0' ? std::string(moved) : source_path("build-teensy");
  return root + "/teensy41-serial/faults/" + name + ".elf";
}

struct FaultCase {
  std::string sketch;  ///< fixture folder and image name
  std::string fault;   ///< what the report must name
  std::string symbol;  ///< the sketch function the report must name
  EscapeCause cause;   ///< kCrashed (exit 5) or kHung (exit 6)
};

void PrintTo(const FaultCase& fault, std::ostream* out) { *out << fault.sketch; }

class FaultSketches : public ::testing::TestWithParam<FaultCase> {};

TEST_P(FaultSketches, StopTheRunNamingTheFaultAndTheFunction) {
  const FaultCase& fault = GetParam();
  const std::string image = fault_image(fault.sketch);
  ASSERT_TRUE(std::filesystem::is_regular_file(image)) << image << " is missing: scripts/build-teensy.sh builds it";
  const std::string scenario_text = "duration_s = 2\n[[board]]\nname = \"driver\"\nimage = \"" + image + "\"\n";
  const scenario::Scenario scenario = parse(scenario_text, source_path("tests/sim/image/fault_sketches/scenario.toml"));
  SimulationOptions options;
  plug_test_hooks(options);
  options.firmware = std::make_shared<image::ImageSource>();
  options.output_directory = test_output_dir("fault." + fault.sketch);
  options.write_vcd = false;
  SimulationError error;
  auto simulation = Simulation::create(scenario, options, error);
  ASSERT_NE(simulation, nullptr) << error.message;
  const SimulationReport report = simulation->finish();
  ASSERT_TRUE(report.sketch_stop.has_value()) << "the run was not stopped";
  const SketchStop& stop = *report.sketch_stop;
  EXPECT_EQ(stop.cause, fault.cause) << stop.message();
  EXPECT_NE(stop.what.find(fault.fault), std::string::npos) << stop.message();
  EXPECT_NE(stop.what.find(fault.symbol), std::string::npos) << stop.message();
  EXPECT_LT(stop.time_ns, 2 * kSecond);
}

INSTANTIATE_TEST_SUITE_P(
    Images, FaultSketches,
    ::testing::Values(FaultCase{"BusFault", "BusFault", "read_gated_timer()", EscapeCause::kCrashed},
                      FaultCase{"UsageFault", "UsageFault", "divide_by_zero()", EscapeCause::kCrashed},
                      FaultCase{"MemManage", "MemManage", "write_to_flash()", EscapeCause::kCrashed},
                      FaultCase{"HardFault", "HardFault", "hit_breakpoint()", EscapeCause::kCrashed},
                      FaultCase{"StackOverflow", "stack", "recurse(unsigned long)", EscapeCause::kCrashed},
                      FaultCase{"NoProgress", "progress", "wait_forever()", EscapeCause::kHung}),
    [](const ::testing::TestParamInfo<FaultCase>& param) { return param.param.sketch; });

}  // namespace
}  // namespace stepdance::sim::test
