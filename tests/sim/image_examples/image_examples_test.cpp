// Examples on their firmware images: each example's scenario runs twice, once on the host-compiled
// sketch and once on the CI firmware image (scripts/build-teensy.sh, linked against the stand-in
// core) running on the emulated i.MX RT1062. The image run must move every motor by the same
// steps, draw the same drawing, and put the same frame words on every output port's wire from
// the first frame that carries a step; run to its end, it must also meet every expectation.
//
// Step-A-Sketch runs its first 14 s here (two pen clicks, the square): run to its 42 s end its
// image's frames part from the host run's at the third click (17.5 s; issue 37's notes).
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "../assembly/simulation_fixture.hpp"
#include "image/board/image_source.hpp"

namespace stepdance::sim::test {
namespace {

/// Where scripts/build-teensy.sh leaves the images (STEPDANCE_TEENSY_BUILD_DIR moves it).
std::string image_path(const std::string& teensy, const std::string& example) {
  const char* moved = std::getenv("STEPDANCE_TEENSY_BUILD_DIR");
  const std::string root = moved != nullptr && *moved != '\0' ? std::string(moved) : source_path("build-teensy");
  return root + "/" + teensy + "-serial/" + example + ".elf";
}

/// Every frame one output port plays, from the first that carries a step (idle ones included).
class FrameLog : public WireListener {
 public:
  bool wants_idle_frames() const override { return true; }
  void on_frame(SimTime, const protocol::FrameWords& words, SimTime) override {
    if (frames.empty() && words.step_bits == 0) return;
    frames.push_back(words);
  }
  std::vector<protocol::FrameWords> frames;
};

struct ExampleRun {
  std::unique_ptr<Simulation> simulation;
  SimulationReport report;
  std::map<std::string, FrameLog> wires;  ///< by "board:port"
  std::string drawing;
};

/// Runs `scenario` with the boards named in `images` on their images (the rest host-compiled).
ExampleRun run_example(const scenario::Scenario& scenario, const std::map<std::string, std::string>& images,
                       const std::string& name, std::optional<SimTime> duration) {
  SimulationOptions options;
  options.duration = duration;
  plug_test_hooks(options);
  options.firmware = std::make_shared<image::ImageSource>();
  options.images = images;
  options.output_directory = test_output_dir(name);
  options.write_vcd = false;
  std::filesystem::remove_all(*options.output_directory);
  ExampleRun result;
  SimulationError error;
  result.simulation = Simulation::create(scenario, options, error);
  EXPECT_NE(result.simulation, nullptr) << error.message;
  if (!result.simulation) return result;
  for (const scenario::BoardConfig& board : scenario.boards) {
    for (uint8_t port = 0; port < board.module->output_port_count; ++port) {
      FrameLog& log = result.wires[board.name + ":" + static_cast<char>('A' + port)];
      result.simulation->board(board.name)->add_wire_listener(port, &log);
    }
  }
  result.report = result.simulation->finish();
  result.drawing = result.simulation->drawing_svg();
  return result;
}

struct ImageExample {
  std::string folder;                            ///< examples/<folder>
  std::map<std::string, std::string> images;     ///< board name → image file (teensy41/… relative)
  double duration_s = 0;                         ///< > 0: run only this long (no expectations then)
};

void PrintTo(const ImageExample& example, std::ostream* out) { *out << example.folder; }

class ImageExamples : public ::testing::TestWithParam<ImageExample> {};

TEST_P(ImageExamples, RunLikeTheHostCompiledSketch) {
  const ImageExample& example = GetParam();
  std::map<std::string, std::string> images;
  for (const auto& [board, file] : example.images) {
    const std::string teensy = file.substr(0, file.find('/'));
    images[board] = image_path(teensy, file.substr(file.find('/') + 1));
    ASSERT_TRUE(std::filesystem::is_regular_file(images[board]))
        << images[board] << " is missing: scripts/build-teensy.sh builds it (the ctest fixture runs it)";
  }
  const scenario::Scenario scenario = load(source_path("examples/" + example.folder + "/scenario.toml"));
  std::optional<SimTime> duration;
  if (example.duration_s > 0) duration = from_seconds(example.duration_s);
  const ExampleRun host = run_example(scenario, {}, example.folder + ".host", duration);
  const ExampleRun image = run_example(scenario, images, example.folder + ".image", duration);
  ASSERT_TRUE(host.simulation && image.simulation);
  ASSERT_FALSE(image.report.sketch_stop) << image.report.sketch_stop->message();
  if (!duration) {
    ASSERT_TRUE(host.report.all_expectations_met());
    for (const ExpectationResult& result : image.report.expectations) EXPECT_TRUE(result.met) << result.message;
  }
  ASSERT_NE(host.drawing.find("<polyline"), std::string::npos) << "the host run drew nothing to compare";
  EXPECT_EQ(image.drawing, host.drawing);
  for (const auto& [wire, log] : host.wires) {
    const std::vector<protocol::FrameWords>& theirs = image.wires.at(wire).frames;
    SCOPED_TRACE(wire);
    ASSERT_EQ(theirs.empty(), log.frames.empty());
    const size_t compared = std::min(log.frames.size(), theirs.size());
    size_t first_difference = compared;
    for (size_t i = 0; i < compared && first_difference == compared; ++i) {
      if (log.frames[i].step_bits != theirs[i].step_bits || log.frames[i].dir_bits != theirs[i].dir_bits) first_difference = i;
    }
    EXPECT_EQ(first_difference, compared) << "frame words differ from the " << first_difference
                                           << "th frame after the first step";
  }
  for (const scenario::BoardConfig& board : scenario.boards) {
    for (char port = 'A'; port < 'A' + board.module->output_port_count; ++port) {
      const StepperDriver* ours = host.simulation->stepper(board.name, port);
      const StepperDriver* theirs = image.simulation->stepper(board.name, port);
      if (ours == nullptr) continue;
      EXPECT_EQ(theirs->position_steps(), ours->position_steps()) << board.name << ":" << port;
      EXPECT_EQ(theirs->forward_steps(), ours->forward_steps()) << board.name << ":" << port;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Examples, ImageExamples,
                         ::testing::Values(ImageExample{"StepASketch", {{"driver", "teensy41/StepASketch"}}, 14.0}),
                         [](const ::testing::TestParamInfo<ImageExample>& param) { return param.param.folder; });

}  // namespace
}  // namespace stepdance::sim::test
