// ReplayRecorder on Step-A-Sketch: instants, inputs, strokes, the wire, and its capacities.
#include <set>

#include <nlohmann/json.hpp>

#include "../assembly/simulation_fixture.hpp"
#include "page_model.hpp"
#include "view/replay_recorder.hpp"

namespace stepdance::sim::view {
namespace {

using nlohmann::json;
using test::create;
using test::parse;
using test::source_path;

/// Step-A-Sketch for 3 s: the pen button clicked at 0.2 s (held 100 ms, the timeline's click),
/// knob 1 turned −2400 counts from 1.0 s to 1.5 s: the pen draws from (0, 0) to (24, 0) mm
/// (100 counts a mm, inverted).
std::string scenario_text() {
  return R"(duration_s = 3
seed = 1
[[board]]
name = "driver"
sketch = "StepASketch.ino"
module = "driver"
[board.sockets]
A = { device = "stepper", microsteps = 16 }
B = { device = "stepper", microsteps = 16 }
C = { device = "servo" }
[machine]
type = "corexy_plotter"
board = "driver"
[[device]]
name = "knob_x"
type = "encoder"
board = "driver"
connector = "ENC1"
[[device]]
name = "pen_button"
type = "button"
board = "driver"
connector = "D1"
bounce_ms = 2
[output]
svg = "drawing.svg"
[[at]]
time_s = 0.2
click = "pen_button"
[[at]]
time_s = 1.0
turn = "knob_x"
counts = -2400
over_s = 0.5
)";
}

/// Runs the scenario recorded with `limits` (instants `interval_ns` apart, 0: as the limits
/// give) and returns the recording.
json record(const ReplayLimits& limits, const std::string& output, SimTime interval_ns = 0) {
  auto simulation = create(parse(scenario_text(), source_path("examples/StepASketch/scenario.toml")), output, false);
  if (interval_ns == 0) interval_ns = replay_interval_ns(simulation->duration(), limits);
  ReplayRecorder recorder(*simulation, interval_ns, limits);
  recorder.attach_pacer();
  simulation->finish();
  return recorder.recording();
}

/// The sample whose update is nearest `t_s`.
const json& at(const json& recording, double t_s) {
  const json* best = &recording["samples"][0];
  for (const json& sample : recording["samples"]) {
    if (std::abs(sample["update"]["t_s"].get<double>() - t_s) <
        std::abs((*best)["update"]["t_s"].get<double>() - t_s)) {
      best = &sample;
    }
  }
  return *best;
}

TEST(ReplayRecorder, IntervalIsAThirtiethOfASecondOrTheDurationOverTheMostInstants) {
  const ReplayLimits limits;  // 30 a second, 20,000 at most
  EXPECT_EQ(replay_interval_ns(42 * kSecond, limits), 33333333);
  // 3 hours at 30 a second would be 324,000 instants: 10,800 s / 19,999 → 541 ms (whole ms up).
  EXPECT_EQ(replay_interval_ns(3 * 3600 * kSecond, limits), 541 * kMillisecond);
}

TEST(ReplayRecorder, RecordsEveryInstantThenTheEnd) {
  const json recording = record(ReplayLimits{}, "replay_instants");
  EXPECT_EQ(recording["format"], "stepdance-replay");
  EXPECT_EQ(recording["version"], kReplayFormatVersion);
  EXPECT_TRUE(recording["complete"]);
  EXPECT_EQ(recording["hello"]["type"], "hello");
  // Instants k × 33,333,333 ns before 3 s: k = 0 … 90 (90 × 33.33 ms = 2.99999997 s); then the end.
  const json& samples = recording["samples"];
  ASSERT_EQ(samples.size(), 92u);
  for (size_t k = 0; k + 1 < samples.size(); ++k) {
    EXPECT_NEAR(samples[k]["update"]["t_s"].get<double>(), k * 0.033333333, 1e-9);
  }
  EXPECT_EQ(samples.back()["update"]["t_s"], 3.0);
}

TEST(ReplayRecorder, InputsAreTheTimelineAtEachInstant) {
  const json recording = record(ReplayLimits{}, "replay_inputs");
  // The click holds the button from 0.2 s to 0.3 s.
  EXPECT_EQ(at(recording, 0.1)["inputs"]["pen_button"]["pressed"], false);
  EXPECT_EQ(at(recording, 0.2333)["inputs"]["pen_button"]["pressed"], true);
  EXPECT_EQ(at(recording, 0.3333)["inputs"]["pen_button"]["pressed"], false);
  // The turn: 0 before 1.0 s, −2400 from 1.5 s on.
  EXPECT_EQ(at(recording, 0.9)["inputs"]["knob_x"]["counts"], 0);
  const double midway = at(recording, 1.2667)["inputs"]["knob_x"]["counts"].get<double>();
  EXPECT_LT(midway, 0);
  EXPECT_GT(midway, -2400);
  EXPECT_EQ(at(recording, 2.0)["inputs"]["knob_x"]["counts"], -2400);
  EXPECT_EQ(recording["samples"].back()["inputs"]["knob_x"]["counts"], -2400);
}

TEST(ReplayRecorder, TheUpdatesAddUpToTheStrokeAndTheFinalPen) {
  const json recording = record(ReplayLimits{}, "replay_strokes");
  page_test::PageModel page;
  for (const json& sample : recording["samples"]) page.apply(sample["update"]);
  ASSERT_EQ(page.strokes.size(), 1u);
  EXPECT_EQ(page.strokes[0].front(), std::make_pair(0.0, 0.0));
  EXPECT_EQ(page.strokes[0].back(), std::make_pair(24.0, 0.0));
  EXPECT_EQ(page.pen["x_mm"], 24);
  EXPECT_EQ(page.pen["down"], true);
}

TEST(ReplayRecorder, TheWireAroundAnInstantHoldsStepdancePulses) {
  const json recording = record(ReplayLimits{}, "replay_wire");
  const json& wire = recording["wire"];
  EXPECT_EQ(wire["ports"], json::array({"driver:OUT_A", "driver:OUT_B", "driver:OUT_C", "driver:OUT_D"}));
  EXPECT_EQ(wire["window_ns"], 400000);
  // The pulse widths of the motion stream: X 2 µs … E 7 µs (signals.hpp).
  EXPECT_EQ(wire["pulse_widths_us"], json({{"X", 2}, {"Y", 3}, {"R", 4}, {"T", 5}, {"Z", 6}, {"E", 7}}));
  // While the knob turns the motors step: frames on A and B within ±200 µs; before the click
  // nothing moves.
  EXPECT_TRUE(at(recording, 0.1)["wire"].empty());
  const json& moving = at(recording, 1.2667)["wire"];
  std::set<int> ports;
  for (const json& frame : moving) {
    ports.insert(frame[0].get<int>());
    EXPECT_GE(frame[1].get<int64_t>(), -200000);
    EXPECT_LE(frame[1].get<int64_t>(), 200000);
    // Every STEP pulse lasts 2 to 7 µs.
    const uint32_t bits = frame[2];
    for (int bit = 0; bit < 32;) {
      if (((bits >> bit) & 1u) == 0) {
        ++bit;
        continue;
      }
      int end = bit;
      while (end < 32 && ((bits >> end) & 1u) != 0) ++end;
      EXPECT_GE(end - bit, 2);
      EXPECT_LE(end - bit, 7);
      bit = end;
    }
  }
  EXPECT_TRUE(ports.count(0) == 1 && ports.count(1) == 1);
  EXPECT_EQ(wire["frames_not_kept"], 0);
}

TEST(ReplayRecorder, CapacitiesAreStatedNotSilent) {
  ReplayLimits few;
  few.max_samples = 10;
  // 3 s / 9 intervals → 334 ms (whole ms up): 9 instants before 3 s, then the end.
  EXPECT_EQ(replay_interval_ns(3 * kSecond, few), 334 * kMillisecond);
  EXPECT_TRUE(record(few, "replay_spread")["complete"]);
  // Instants 1/30 s apart (a live run's): the 11th one, at 0.333 s, is past the capacity.
  const json recording = record(few, "replay_capacity", 33333333);
  EXPECT_FALSE(recording["complete"]);
  ASSERT_EQ(recording["samples"].size(), 10u);
  EXPECT_EQ(recording["note"],
            "the recording reached its capacity of 10 instants at 0.333 s; the run went on without it");
  ReplayLimits small;
  small.max_bytes = 20000;
  const json cut = record(small, "replay_bytes");
  EXPECT_FALSE(cut["complete"]);
  EXPECT_LE(cut.dump().size(), 20000u + cut["hello"].dump().size() + 2000u);
  EXPECT_NE(cut["note"].get<std::string>().find("capacity of 20000 bytes"), std::string::npos);
}

TEST(ReplayRecorder, FramesBeyondTheWindowCapacityAreCounted) {
  ReplayLimits one;
  one.max_frames_per_window = 1;
  const json recording = record(one, "replay_one_frame");
  std::map<int, int> per_port;
  for (const json& frame : at(recording, 1.2667)["wire"]) ++per_port[frame[0].get<int>()];
  for (const auto& [port, count] : per_port) EXPECT_EQ(count, 1) << port;
  EXPECT_GT(at(recording, 1.2667)["wire_frames_not_kept"].get<int>(), 0);
  EXPECT_GT(recording["wire"]["frames_not_kept"].get<int>(), 0);
}

}  // namespace
}  // namespace stepdance::sim::view
