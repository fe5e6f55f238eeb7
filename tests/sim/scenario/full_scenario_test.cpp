// Parsing valid scenario fixtures: every section of the full example, defaults, other machines.
#include <gtest/gtest.h>

#include <string>

#include "kinds/devices/button.hpp"
#include "kinds/devices/encoder.hpp"
#include "kinds/devices/limit_switch.hpp"
#include "kinds/devices/potentiometer.hpp"
#include "kinds/expectations/cable_counts.hpp"
#include "kinds/expectations/motor_steps.hpp"
#include "kinds/expectations/pen_position.hpp"
#include "kinds/expectations/port_pulses.hpp"
#include "kinds/expectations/rejected.hpp"
#include "kinds/expectations/strokes.hpp"
#include "kinds/machines/cartesian.hpp"
#include "kinds/machines/corexy_plotter.hpp"
#include "kinds/machines/polar_turntable.hpp"
#include "scenario/load_scenario.hpp"

namespace stepdance::sim::scenario {
namespace {

const std::string kFixtures = std::string(STEPDANCE_SOURCE_DIR) + "/tests/sim/scenario/fixtures";

Scenario load_ok(const std::string& path) {
  LoadResult result = load_scenario(path);
  EXPECT_TRUE(result.ok()) << result.error_text();
  return result.scenario;
}

TEST(FullScenario, TopLevelAndPaths) {
  const Scenario s = load_ok(kFixtures + "/full/scenario.toml");
  EXPECT_EQ(s.file, kFixtures + "/full/scenario.toml");
  EXPECT_EQ(s.directory, kFixtures + "/full");
  EXPECT_EQ(s.duration, 12500 * kMillisecond);
  EXPECT_EQ(s.seed, 42u);
}

TEST(FullScenario, AFolderMeansItsScenarioToml) {
  const Scenario s = load_ok(kFixtures + "/full");
  EXPECT_EQ(s.file, kFixtures + "/full/scenario.toml");
  EXPECT_EQ(s.boards.size(), 2u);
}

TEST(FullScenario, Boards) {
  const Scenario s = load_ok(kFixtures + "/full");
  ASSERT_EQ(s.boards.size(), 2u);
  const BoardConfig& driver = s.boards[0];
  EXPECT_EQ(driver.name, "driver");
  EXPECT_EQ(driver.sketch, kFixtures + "/sketches/driver.ino");
  EXPECT_STREQ(driver.module->name, "Driver Module v1.0");
  EXPECT_EQ(driver.loop_period_us, 250);
  EXPECT_EQ(driver.frame_phase_us, 0);
  EXPECT_EQ(driver.line, 5);
  ASSERT_EQ(driver.sockets.size(), 4u);
  EXPECT_EQ(driver.sockets[0].port, 'A');
  EXPECT_EQ(driver.sockets[0].device, SocketDevice::kStepper);
  EXPECT_EQ(driver.sockets[0].microsteps, 16);
  EXPECT_EQ(driver.sockets[0].full_steps_per_rev, 200);
  EXPECT_EQ(driver.sockets[1].microsteps, 32);
  EXPECT_EQ(driver.sockets[1].full_steps_per_rev, 400);
  EXPECT_EQ(driver.sockets[2].device, SocketDevice::kServo);
  EXPECT_EQ(driver.sockets[2].build, ServoBuild::k180deg);
  EXPECT_EQ(driver.sockets[3].port, 'D');
  ASSERT_NE(driver.socket('C'), nullptr);
  EXPECT_EQ(driver.socket('C')->line, 13);

  const BoardConfig& basic = s.boards[1];
  EXPECT_STREQ(basic.module->name, "Basic Module v1.0");
  EXPECT_EQ(basic.loop_period_us, 200);
  EXPECT_EQ(basic.frame_phase_us, 17);
  EXPECT_TRUE(basic.sockets.empty());
  EXPECT_EQ(s.board("basic"), &basic);
  EXPECT_EQ(s.board("nope"), nullptr);
}

TEST(FullScenario, Machine) {
  const Scenario s = load_ok(kFixtures + "/full");
  ASSERT_TRUE(s.machine.has_value());
  EXPECT_EQ(s.machine->board, "driver");
  EXPECT_EQ(s.machine->line, 22);
  const auto* corexy = s.machine->settings_as<CorexyConfig>();
  ASSERT_NE(corexy, nullptr);
  EXPECT_EQ(corexy->motor_a, 'A');
  EXPECT_EQ(corexy->motor_b, 'B');
  EXPECT_EQ(corexy->pen_servo, 'C');
  EXPECT_EQ(corexy->steps_per_mm, 80);
  EXPECT_EQ(corexy->pen_down_below_us, 1450);
  EXPECT_EQ(corexy->travel_x_mm, 300);
  EXPECT_EQ(corexy->travel_y_mm, 218.5);
}

TEST(FullScenario, Devices) {
  const Scenario s = load_ok(kFixtures + "/full");
  ASSERT_EQ(s.devices.size(), 5u);
  const DeviceConfig& knob_x = s.devices[0];
  EXPECT_EQ(knob_x.kind, &encoder_kind());
  EXPECT_EQ(knob_x.board, "basic");
  EXPECT_EQ(knob_x.connector, Connector::kEnc1);
  ASSERT_NE(knob_x.settings_as<EncoderConfig>(), nullptr);
  EXPECT_EQ(knob_x.settings_as<EncoderConfig>()->pulses_per_revolution, 600);
  EXPECT_EQ(knob_x.settings_as<EncoderConfig>()->start_count, 0);
  const DeviceConfig& knob_y = *s.device("knob_y");
  EXPECT_EQ(knob_y.connector, Connector::kEnc2);
  ASSERT_NE(knob_y.settings_as<EncoderConfig>(), nullptr);
  EXPECT_EQ(knob_y.settings_as<EncoderConfig>()->pulses_per_revolution, 1000);
  EXPECT_EQ(knob_y.settings_as<EncoderConfig>()->start_count, -5);
  const DeviceConfig& speed = *s.device("speed");
  EXPECT_EQ(speed.kind, &potentiometer_kind());
  EXPECT_EQ(speed.connector, Connector::kA1);
  ASSERT_NE(speed.settings_as<PotentiometerConfig>(), nullptr);
  EXPECT_EQ(speed.settings_as<PotentiometerConfig>()->position, 0.25);
  const DeviceConfig& pen = *s.device("pen");
  EXPECT_EQ(pen.kind, &button_kind());
  EXPECT_EQ(pen.connector, Connector::kD1);
  ASSERT_NE(pen.settings_as<ButtonConfig>(), nullptr);
  EXPECT_EQ(pen.settings_as<ButtonConfig>()->bounce_ms, 3.5);
  EXPECT_FALSE(pen.settings_as<ButtonConfig>()->pressed_level_high);
  const DeviceConfig& home = *s.device("home_x");
  EXPECT_EQ(home.kind, &limit_switch_kind());
  EXPECT_EQ(home.connector, Connector::kLimitA);
  EXPECT_EQ(connector_name(home.connector), "LIMIT_A");
  const LimitSwitchConfig* limit = home.settings_as<LimitSwitchConfig>();
  ASSERT_NE(limit, nullptr);
  EXPECT_EQ(limit->axis, MachineAxis::kX);
  EXPECT_EQ(limit->at_mm, -1);
  EXPECT_FALSE(limit->active_above);
  EXPECT_EQ(home.line, 58);
}

TEST(FullScenario, Cables) {
  const Scenario s = load_ok(kFixtures + "/full");
  ASSERT_EQ(s.cables.size(), 1u);
  const CableConfig& cable = s.cables[0];
  EXPECT_EQ(cable.from.board, "basic");
  EXPECT_EQ(cable.from.port, 'A');
  EXPECT_EQ(cable.to.board, "driver");
  EXPECT_EQ(cable.to.port, 'A');
  EXPECT_EQ(cable.settings.delay, 20);
  EXPECT_EQ(cable.settings.stretch, -400);
  EXPECT_EQ(cable.settings.glitch_every, 1000 * kMicrosecond);
  EXPECT_EQ(cable.settings.glitch_width, 300);
}

TEST(FullScenario, TimelineIsSortedByTimeKeepingFileOrderForTies) {
  const Scenario s = load_ok(kFixtures + "/full");
  ASSERT_EQ(s.timeline.size(), 8u);
  const std::vector<Action>& t = s.timeline;
  EXPECT_EQ(t[0].type, ActionType::kTurn);
  EXPECT_EQ(t[0].target, "knob_x");
  EXPECT_EQ(t[0].time, 500 * kMillisecond);
  EXPECT_EQ(t[0].counts, 2400);
  EXPECT_EQ(t[0].over, 2 * kSecond);
  EXPECT_EQ(t[1].target, "knob_y");  // 2 s, first in the file
  EXPECT_EQ(t[1].counts, -1200);
  EXPECT_EQ(t[1].over, 1500 * kMillisecond);
  EXPECT_EQ(t[1].line, 74);
  EXPECT_EQ(t[2].type, ActionType::kClick);  // 2 s, second in the file
  EXPECT_EQ(t[2].hold, 50 * kMillisecond);
  EXPECT_EQ(t[3].type, ActionType::kSet);
  EXPECT_EQ(t[3].position, 0.75);
  EXPECT_EQ(t[4].type, ActionType::kSerial);
  EXPECT_EQ(t[4].target, "driver");
  EXPECT_EQ(t[4].serial_bytes, "G0 X10\n");
  EXPECT_EQ(t[4].serial_file, "");
  EXPECT_EQ(t[5].serial_bytes, "G0 X10 Y10\nG1 X20\n");
  EXPECT_EQ(t[5].serial_file, kFixtures + "/full/commands.txt");
  EXPECT_EQ(t[6].type, ActionType::kPress);
  EXPECT_EQ(t[6].time, 5 * kSecond);
  EXPECT_EQ(t[7].type, ActionType::kRelease);
}

TEST(FullScenario, Output) {
  const Scenario s = load_ok(kFixtures + "/full");
  const OutputConfig& out = s.output;
  const std::string dir = kFixtures + "/full/out";
  EXPECT_EQ(out.directory, dir);
  EXPECT_EQ(out.svg, dir + "/picture.svg");
  EXPECT_EQ(out.png, "");
  EXPECT_EQ(out.png_px_per_mm, 8);
  EXPECT_TRUE(out.pen_up_travel);
  EXPECT_EQ(out.vcd, dir + "/wires.vcd");
  ASSERT_EQ(out.vcd_ports.size(), 2u);
  EXPECT_EQ(out.vcd_ports[0].board, "basic");
  EXPECT_TRUE(out.vcd_ports[0].output);
  EXPECT_EQ(out.vcd_ports[1].board, "driver");
  EXPECT_FALSE(out.vcd_ports[1].output);
  EXPECT_EQ(out.vcd_ports[1].port, 'A');
  EXPECT_EQ(out.csv, dir + "/positions.csv");
  EXPECT_EQ(out.csv_interval_ms, 5);
  EXPECT_EQ(out.summary, dir + "/summary.json");
}

TEST(FullScenario, Expectations) {
  const Scenario s = load_ok(kFixtures + "/full");
  ASSERT_EQ(s.expectations.size(), 6u);
  const std::vector<Expectation>& e = s.expectations;
  EXPECT_EQ(e[0].kind, &motor_steps_expectation());
  ASSERT_NE(e[0].settings_as<MotorStepsCheck>(), nullptr);
  EXPECT_EQ(e[0].settings_as<MotorStepsCheck>()->motor.board, "driver");
  EXPECT_EQ(e[0].settings_as<MotorStepsCheck>()->motor.port, 'A');
  EXPECT_EQ(e[0].settings_as<MotorStepsCheck>()->steps, 3200);
  EXPECT_EQ(e[1].kind, &pen_position_expectation());
  const PenPositionCheck* pen = e[1].settings_as<PenPositionCheck>();
  ASSERT_NE(pen, nullptr);
  EXPECT_EQ(pen->x_mm, 10);
  EXPECT_EQ(pen->y_mm, 5.5);
  EXPECT_EQ(pen->tolerance_mm, 0.05);
  EXPECT_EQ(e[2].kind, &strokes_expectation());
  ASSERT_NE(e[2].settings_as<StrokesCheck>(), nullptr);
  EXPECT_EQ(e[2].settings_as<StrokesCheck>()->strokes, 3);
  EXPECT_EQ(e[3].kind, &port_pulses_expectation());
  const PortPulsesCheck* port = e[3].settings_as<PortPulsesCheck>();
  ASSERT_NE(port, nullptr);
  EXPECT_EQ(port->port.board, "basic");
  EXPECT_TRUE(port->port.output);
  EXPECT_EQ(port->signal, 0);
  EXPECT_EQ(port->forward, 2400);
  EXPECT_EQ(port->reverse, 0);
  EXPECT_EQ(e[4].kind, &cable_counts_expectation());
  EXPECT_EQ(e[5].kind, &rejected_expectation());
  const RejectedCheck* rejected = e[5].settings_as<RejectedCheck>();
  ASSERT_NE(rejected, nullptr);
  EXPECT_EQ(rejected->rejected, 0);
  EXPECT_FALSE(rejected->port.output);
}

TEST(OtherMachines, CartesianWithDefaultsAndInlineSockets) {
  const Scenario s = load_ok(kFixtures + "/cartesian");
  EXPECT_EQ(s.seed, 1u);
  ASSERT_EQ(s.boards[0].sockets.size(), 3u);
  EXPECT_EQ(s.boards[0].socket('D')->microsteps, 8);
  const auto* cartesian = s.machine->settings_as<CartesianConfig>();
  ASSERT_NE(cartesian, nullptr);
  EXPECT_EQ(cartesian->x, 'A');
  EXPECT_EQ(cartesian->y, 'B');
  EXPECT_EQ(cartesian->z, 'D');
  EXPECT_FALSE(cartesian->e.has_value());
  EXPECT_EQ(cartesian->x_steps_per_mm, 100);
  EXPECT_EQ(cartesian->y_steps_per_mm, 80);
  EXPECT_EQ(cartesian->z_steps_per_mm, 800);
  EXPECT_EQ(cartesian->e_steps_per_mm, 93);
  EXPECT_EQ(cartesian->pen_down_at_or_below_mm, 0.2);
  // No [output]: every default, inside the scenario's folder.
  EXPECT_EQ(s.output.directory, kFixtures + "/cartesian/sim-out");
  EXPECT_EQ(s.output.svg, kFixtures + "/cartesian/sim-out/drawing.svg");
  EXPECT_EQ(s.output.png, kFixtures + "/cartesian/sim-out/drawing.png");
  EXPECT_EQ(s.output.vcd, "");
  EXPECT_EQ(s.output.csv, "");
  EXPECT_EQ(s.output.summary, kFixtures + "/cartesian/sim-out/summary.json");
  EXPECT_EQ(s.output.png_px_per_mm, 4);
  EXPECT_EQ(s.output.csv_interval_ms, 10);
  EXPECT_FALSE(s.output.pen_up_travel);
  EXPECT_TRUE(s.timeline.empty());
  EXPECT_TRUE(s.expectations.empty());
}

TEST(OtherMachines, PolarWithAPenServo) {
  const Scenario s = load_ok(kFixtures + "/polar");
  const auto* polar = s.machine->settings_as<PolarConfig>();
  ASSERT_NE(polar, nullptr);
  EXPECT_EQ(polar->angle, 'C');
  EXPECT_EQ(polar->radius, 'B');
  EXPECT_EQ(polar->pen_servo, 'D');
  EXPECT_EQ(polar->steps_per_rev, 6400);
  EXPECT_EQ(polar->steps_per_mm, 80);
  EXPECT_EQ(polar->pen_down_below_us, 1500);
}

TEST(ParseScenario, TextIsReadAsIfFromTheGivenFile) {
  const std::string file = kFixtures + "/full/inline.toml";
  const LoadResult result = parse_scenario(
      "duration_s = 1\n[[board]]\nname = \"b\"\nsketch = \"../sketches/basic.ino\"\nmodule = \"basic\"\n", file);
  ASSERT_TRUE(result.ok()) << result.error_text();
  EXPECT_EQ(result.scenario.boards[0].sketch, kFixtures + "/sketches/basic.ino");
  EXPECT_FALSE(result.scenario.machine.has_value());
}

}  // namespace
}  // namespace stepdance::sim::scenario
