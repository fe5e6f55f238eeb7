// The DisplayAndKnob example end to end: the menu changes the knobs' ratio and the drawing with
// it; the time any loop pass spends on I2C at 400 kHz; a missing display and a broken bus.
#include <algorithm>

#include "kinds/expectations/screen_text.hpp"
#include "models/ssd1306_display.hpp"
#include "simulation_fixture.hpp"

namespace stepdance::sim::test {
namespace {

scenario::Scenario example() { return load(source_path("examples/DisplayAndKnob/scenario.toml")); }

TEST(DisplayAndKnobScenario, MenuDoublesTheRatioAndTheSecondLineIsTwiceAsLong) {
  auto simulation = create(example(), "display_and_knob", false);
  ASSERT_NE(simulation, nullptr);
  const SimulationReport report = simulation->finish();
  for (const ExpectationResult& result : report.expectations) EXPECT_TRUE(result.met) << result.message;
  // 2000 counts along x at 0.01 mm/count, then 2000 along y after two detents of 0.005:
  // 20 mm and 2000 × 0.02 = 40 mm.
  const std::vector<Polyline>& strokes = simulation->machine()->strokes();
  ASSERT_EQ(strokes.size(), 1u);
  EXPECT_NEAR(strokes[0].front().x_mm, 50.0, 1e-9);
  EXPECT_NEAR(simulation->machine()->pen_position().x_mm - 50.0, 20.0, 1e-9);
  EXPECT_NEAR(simulation->machine()->pen_position().y_mm - 50.0, 40.0, 1e-9);
}

TEST(DisplayAndKnobScenario, NoLoopPassSpendsMoreThanOneDataChunkOnTheWire) {
  auto simulation = create(example(), "display_and_knob_timing", false);
  ASSERT_NE(simulation, nullptr);
  simulation->finish();
  const I2cTiming& timing = simulation->board("driver")->i2c().timing();
  // The longest transfer is a 32-byte data chunk: control byte + 32 data bytes + the address =
  // 34 bytes of 9 bits, plus START and STOP, at 2.5 µs a bit (400 kHz): 308 × 2.5 = 770 µs.
  EXPECT_EQ(timing.max_loop_pass_ns, 770 * kMicrosecond);
  EXPECT_GT(timing.loop_passes_with_i2c, 100u);
}

TEST(DisplayAndKnobScenario, MissingDisplayIsReportedAndTheDrawingIsUnaffected) {
  scenario::Scenario without = example();
  without.devices.erase(std::remove_if(without.devices.begin(), without.devices.end(),
                                       [](const scenario::DeviceConfig& d) { return d.name == "screen"; }),
                        without.devices.end());
  without.expectations.erase(
      std::remove_if(without.expectations.begin(), without.expectations.end(),
                     [](const scenario::Expectation& e) { return e.kind == &screen_text_expectation(); }),
      without.expectations.end());
  auto simulation = create(without, "display_and_knob_missing", false);
  ASSERT_NE(simulation, nullptr);
  const SimulationReport report = simulation->finish();  // returns: nothing waits for the display
  for (const ExpectationResult& result : report.expectations) EXPECT_TRUE(result.met) << result.message;
  const std::string& console = simulation->board("driver")->console().text();
  EXPECT_NE(console.find("OledDisplay: QWIIC1 address 60: address nack, retrying every second"), std::string::npos)
      << console;
  EXPECT_EQ(console.find("OledDisplay: ready"), std::string::npos);
}

TEST(DisplayAndKnobScenario, BusHeldLowIsABusErrorAndNothingHangs) {
  scenario::Scenario broken = example();
  broken.expectations.clear();
  auto simulation = create(broken, "display_and_knob_bus_error", false);
  ASSERT_NE(simulation, nullptr);
  simulation->board("driver")->i2c().set_fault(1, I2cBusFault::kLineHeldLow);
  simulation->finish();
  const std::string& console = simulation->board("driver")->console().text();
  EXPECT_NE(console.find("OledDisplay: QWIIC1 address 60: bus error"), std::string::npos) << console;
  EXPECT_NE(console.find("QwiicTwist: QWIIC1 address 63: bus error"), std::string::npos) << console;
  // The pen still draws; the menu never saw the knob, so y moved 2000 counts at 0.01 mm = 20 mm.
  EXPECT_NEAR(simulation->machine()->pen_position().y_mm - 50.0, 20.0, 1e-9);
}

}  // namespace
}  // namespace stepdance::sim::test
