// More scenario errors, written inline: each text must fail with exactly the listed errors.
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "scenario/load_scenario.hpp"

namespace stepdance::sim::scenario {
namespace {

/// Inline texts read as if they sat next to the full fixture, so "../sketches/*.ino" exist.
const std::string kFile = std::string(STEPDANCE_SOURCE_DIR) + "/tests/sim/scenario/fixtures/full/inline.toml";

/// Lines 1..5 of every case: a run and a Driver Module with steppers in A and B, a servo in C.
const std::string kDriver =
    "duration_s = 5\n"
    "[[board]]\n"
    "name = \"driver\"\n"
    "sketch = \"../sketches/driver.ino\"\n"
    "sockets = { A = { device = \"stepper\" }, B = { device = \"stepper\" }, C = { device = \"servo\" } }\n";

/// "x0|x1|…" with `count` alternatives: repeated a thousand times, forty fit RE2's memory bound
/// and a hundred do not.
std::string many_alternatives(int count) {
  std::string text;
  for (int i = 0; i < count; ++i) text += (i == 0 ? "x" : "|x") + std::to_string(i);
  return text;
}

struct InlineCase {
  std::string name;
  /// Appended to kDriver, so its first line is line 6.
  std::string text;
  std::vector<std::pair<int, std::string>> errors;
};

void PrintTo(const InlineCase& c, std::ostream* out) { *out << c.name; }

std::vector<InlineCase> cases() {
  return {
      {"unknown_machine_type",
       "[machine]\ntype = \"delta\"\nboard = \"driver\"\narms = 3\n",
       {{7, "'type' must be \"corexy_plotter\", \"cartesian\" or \"polar\", got \"delta\""}}},
      {"machine_socket_reused_and_short_travel",
       "[machine]\ntype = \"corexy_plotter\"\nboard = \"driver\"\nmotor_b = \"A\"\ntravel_mm = [300]\n",
       {{9, "'motor_b' uses socket A, already used by 'motor_a'"},
        {10, "'travel_mm' must be two numbers in (0, 1,000,000] mm, e.g. [300, 218]"}}},
      {"machine_two_roles_one_socket",
       "[machine]\ntype = \"polar\"\nboard = \"driver\"\nangle = \"B\"\nradius = \"B\"\n",
       {{10, "'radius' uses socket B, already used by 'angle'"}}},
      {"travel_and_cartesian_axes",
       "[machine]\ntype = \"cartesian\"\nboard = \"driver\"\nx = \"C\"\nsteps_per_mm = { x = 80, w = 3 }\n",
       {{9, "'x' needs a stepper in socket C of board 'driver', but it holds a servo"},
        {10, "unknown key 'w' in steps_per_mm"}}},
      {"key_of_another_device_type",
       "[[device]]\nname = \"knob\"\ntype = \"encoder\"\nboard = \"driver\"\nconnector = \"ENC1\"\nbounce_ms = 5\n",
       {{11, "'bounce_ms' does not apply to an encoder"}}},
      {"connector_used_twice",
       "[[device]]\nname = \"a\"\ntype = \"button\"\nboard = \"driver\"\nconnector = \"D1\"\n"
       "[[device]]\nname = \"b\"\ntype = \"button\"\nboard = \"driver\"\nconnector = \"D1\"\n",
       {{15, "connector D1 of board 'driver' is already used by device 'a'"}}},
      {"limit_axis_the_machine_lacks",
       "[machine]\ntype = \"polar\"\nboard = \"driver\"\n"
       "[[device]]\nname = \"home\"\ntype = \"limit_switch\"\nboard = \"driver\"\nconnector = \"LIMIT_B\"\n"
       "axis = \"y\"\nat_mm = 0\n",
       {{14, "the polar machine has no 'y' axis"}}},
      {"pot_out_of_range",
       "[[device]]\nname = \"pot\"\ntype = \"potentiometer\"\nboard = \"driver\"\nconnector = \"A2\"\n"
       "[[at]]\ntime_s = 1\nset = \"pot\"\nposition = 1.5\n",
       {{14, "'position' must be in [0, 1], got 1.5"}}},
      {"serial_text_and_file",
       "[[at]]\ntime_s = 1\nserial = \"driver\"\ntext = \"x\"\nfile = \"commands.txt\"\n",
       {{10, "'serial' takes 'text' or 'file', not both"}}},
      {"click_past_the_end",
       "[[device]]\nname = \"pen\"\ntype = \"button\"\nboard = \"driver\"\nconnector = \"D2\"\n"
       "[[at]]\ntime_s = 4.95\nclick = \"pen\"\n",
       {{12, "the click releases at 5.05 s, after the end of the run (duration_s = 5)"}}},
      {"cable_values",
       "[[cable]]\nfrom = \"driver:D\"\nto = \"driver:B\"\ndelay_ns = -1\nglitch_width_ns = 0\n",
       {{9, "'delay_ns' must be in [0, 1,000,000,000] ns, got -1"},
        {10, "'glitch_width_ns' must be in [1, 1,000,000] ns, got 0"}}},
      {"cable_bad_form",
       "[[cable]]\nfrom = \"driver\"\nto = \"driver:E\"\n",
       {{7, "'from' must look like \"board:A\", got \"driver\""},
        {8, "board 'driver' (driver module) has no input port E"}}},
      {"port_check_shape",
       "[[expect]]\nport = \"driver:OUT_A\"\naxis = \"Q\"\n"
       "[[expect]]\nrejected = 2\nport = \"driver:OUT_A\"\n"
       "[[expect]]\ncable_counts_match = false\n",
       {{6, "a 'port' check needs 'forward', 'reverse' or both"},
        {8, "'axis' must be one of \"X\", \"Y\", \"R\", \"T\", \"Z\", \"E\", got \"Q\""},
        {11, "'rejected' counts pulses an input port refused: 'port' must be \"board:IN_A\""},
        {13, "'cable_counts_match' can only be true"}}},
      {"detail_of_another_check",
       "[machine]\ntype = \"corexy_plotter\"\nboard = \"driver\"\n[[expect]]\nstrokes = 2\ntolerance_mm = 0.1\n",
       {{11, "'tolerance_mm' only goes with 'pen_mm', 'bounds_mm', 'drawn_mm', 'z_mm' or 'traces'"}}},
      {"geometry_checks",
       "[machine]\ntype = \"corexy_plotter\"\nboard = \"driver\"\n"
       "[[expect]]\nbounds_mm = [0, 10, -1, 20]\n"
       "[[expect]]\nbounds_mm = [0, 1, 2]\n"
       "[[expect]]\ndrawn_mm = -3\n"
       "[[expect]]\ndrawn_mm = 30\ntolerance_mm = nan\n",
       {{10, "'bounds_mm' must be four numbers [x_min, y_min, x_max, y_max] with min <= max"},
        {12, "'bounds_mm' must be four numbers [x_min, y_min, x_max, y_max] with min <= max"},
        {14, "'drawn_mm' must be a finite length >= 0, got -3"},
        {17, "'tolerance_mm' must be a finite number"}}},
      {"pendulum_values",
       "[[device]]\nname = \"swing\"\ntype = \"pendulum\"\nboard = \"driver\"\nconnector = \"A1\"\n"
       "amplitude_deg = 200\nperiod_s = 0\nrelease_s = 9\nstart_count = 3\n"
       "[[at]]\ntime_s = 1\nturn = \"swing\"\ncounts = 5\n",
       {{10, "a pendulum cannot use connector A1 (use ENC1 or ENC2)"},
        {11, "'amplitude_deg' must be in (0, 170] °, got 200"},
        {12, "'period_s' must be in [0.01, 3,600] s, got 0"},
        {13, "'release_s' must be in [0, 5] s, got 9"},
        {14, "'start_count' does not apply to a pendulum"},
        {17, "'turn' needs an encoder, but 'swing' is a pendulum"}}},
      {"printer_checks_need_a_printer",
       "[machine]\ntype = \"corexy_plotter\"\nboard = \"driver\"\n"
       "[[expect]]\nz_mm = 3\n"
       "[[expect]]\nextruded_per_mm = 0.05\nrelative_tolerance = 2\n",
       {{10, "'z_mm' needs a cartesian [machine] with a 'z' socket"},
        {12, "'extruded_per_mm' needs a cartesian [machine] with an 'e' socket"},
        {13, "'relative_tolerance' must be in (0, 1), got 2"}}},
      {"five_bar_arm_values",
       "[[device]]\nname = \"arm\"\ntype = \"five_bar_arm\"\nboard = \"driver\"\nconnector = \"ENC1\"\n"
       "left_connector = \"ENC1\"\npath_mm = [[1, 2, -1]]\nspeed_mm_per_s = 0\n"
       "[[device]]\nname = \"other\"\ntype = \"five_bar_arm\"\nboard = \"driver\"\nconnector = \"ENC2\"\n"
       "path_mm = []\n"
       "[[expect]]\ntraces = \"ghost\"\n",
       {{11, "connector ENC1 of board 'driver' is already used by device 'arm'"},
        {12, "'path_mm' must be a list of [x, y] or [x, y, dwell_s] points (mm, s; dwell in 0..86400)"},
        {13, "'speed_mm_per_s' must be in (0, 10,000] mm/s, got 0"},
        {14, "[[device]] is missing required key 'left_connector'"},
        {19, "'path_mm' needs at least one point"},
        {21, "'traces' must name a five_bar_arm device, got 'ghost'"},
        {21, "'traces' needs a [machine]"}}},
      {"geometry_needs_a_machine", "[[expect]]\ndrawn_mm = 3\n", {{7, "'drawn_mm' needs a [machine]"}}},
      {"output_values",
       "[output]\npng_px_per_mm = 0\ncsv_interval_ms = -5\npen_up_travel = \"yes\"\nvcd_ports = [\"ghost:IN_A\", 3]\n",
       {{7, "'png_px_per_mm' must be in (0, 100] px/mm, got 0"},
        {8, "'csv_interval_ms' must be in [0.04, 86,400,000] ms, got -5"},
        {9, "'pen_up_travel' must be true or false, not a string"},
        {10, "unknown board 'ghost'"},
        {10, "'vcd_ports' must hold strings like \"board:OUT_A\", not an integer"}}},
      {"non_finite_and_huge_times",
       "[[device]]\nname = \"pen\"\ntype = \"button\"\nboard = \"driver\"\nconnector = \"D1\"\n"
       "[[at]]\ntime_s = nan\npress = \"pen\"\n[[at]]\ntime_s = 1e300\nrelease = \"pen\"\n",
       {{12, "'time_s' must be a finite number"}, {15, "'time_s' must be in [0, 86,400] s, got 1e+300"}}},
      {"host_without_steps_and_unknown_board",
       "[[host]]\nboard = \"driver\"\n[[host]]\nboard = \"ghost\"\n[[host.step]]\nsend = \"?\"\n",
       {{6, "a [[host]] needs at least one [[host.step]]"}, {9, "unknown board 'ghost'"}}},
      {"host_steps_that_are_wrong",
       "[[host]]\nboard = \"driver\"\n"
       "[[host.step]]\nsend = \"?\"\nwait = \"ok\"\n"
       "[[host.step]]\nwait = \"(\"\n"
       "[[host.step]]\nstream = \"G1 X1\"\nflow = \"xon\"\nbuffer_bytes = 0\n"
       "[[host.step]]\npause_s = -1\n"
       "[[host.step]]\nsend = \"x\"\ntimeout_s = 1\n"
       "[[host.step]]\nwait = \"ok\"\ntimeout_s = inf\n",
       {{10, "a step does one thing, but has both 'send' and 'wait'"},
        {12, "'wait' is not a valid regular expression (RE2 syntax): missing ): ("},
        {15, "'flow' must be \"ack\" or \"character_counting\", got \"xon\""},
        {16, "'buffer_bytes' must be in [1, 1,048,576] bytes, got 0"},
        {18, "'pause_s' must be in [0, 86,400] s, got -1"},
        {21, "'timeout_s' only goes with stream or wait"},
        {24, "'timeout_s' must be a finite number"}}},
      {"host_patterns_beyond_the_limits",
       "[[host]]\nboard = \"driver\"\n[[host.step]]\nsend = \"?\"\n"
       "[[host.step]]\nwait = '(a)\\99999999999999999999'\n"
       "[[host.step]]\nwait = '(ok)(?=x)'\n"
       "[[host.step]]\nwait = 'a{2,1001}'\n"
       "[[host.step]]\nwait = '(o)k{3}x{1000}\\1'\n"
       "[[host.step]]\nwait = '" +
           std::string(1001, 'a') +
           "'\n"
           "[[host.step]]\nwait = '(" +
           many_alternatives(100) +
           "){1000}'\n"
           "[[host.step]]\nwait = '(" +
           many_alternatives(40) + "){1000}'\n",
       {{11, "'wait' is not a valid regular expression (RE2 syntax): invalid escape sequence: \\9"},
        {13, "'wait' is not a valid regular expression (RE2 syntax): invalid perl operator: (?="},
        {15, "'wait' is not a valid regular expression (RE2 syntax): invalid repetition size: {2,1001}"},
        {17, "'wait' is not a valid regular expression (RE2 syntax): invalid escape sequence: \\1"},
        {19, "'wait' is longer than 1,000 characters (a reply check is a short pattern)"},
        {21, "'wait' is too complex: it compiles to more than 256 KiB (simplify it)"}}},
      {"host_check_patterns_beyond_the_limits",
       "[[host]]\nboard = \"driver\"\n[[host.step]]\nsend = \"?\"\n"
       "[[expect]]\nhost = \"driver\"\nreplies = [\"ok\", \"x{1001}\"]\n"
       "[[expect]]\nhost = \"driver\"\nreply = \"ok\"\nwithin_ms = 5\nafter = '(a{100}){100}'\n",
       {{12, "'replies' is not a valid regular expression (RE2 syntax): invalid repetition size: {1001}"},
        {17, "'after' is not a valid regular expression (RE2 syntax): invalid repetition size: {100}"}}},
      {"host_checks_that_are_wrong",
       "[[host]]\nboard = \"driver\"\n[[host.step]]\nsend = \"?\"\n"
       "[[expect]]\nhost = \"nobody\"\ncompleted = true\n"
       "[[expect]]\nhost = \"driver\"\n"
       "[[expect]]\nhost = \"driver\"\nreplies = [\"a\", \"b\"]\ncount = 2\n"
       "[[expect]]\nhost = \"driver\"\nreply = \"ok\"\nafter = \"G1\"\n",
       {{11, "no [[host]] client on board 'nobody'"},
        {13, "a 'host' check needs 'reply' (one regex) or 'replies' (regexes in order)"},
        {18, "'count' must be >= 0 and goes with a single 'reply'"},
        {22, "'after' goes with 'within_ms'"}}},
  };
}

class InlineErrors : public ::testing::TestWithParam<InlineCase> {};

TEST_P(InlineErrors, ReportsExactlyTheseErrors) {
  const InlineCase& bad = GetParam();
  const LoadResult result = parse_scenario(kDriver + bad.text, kFile);
  std::vector<std::string> expected;
  for (const auto& [line, message] : bad.errors)
    expected.push_back(kFile + ":" + std::to_string(line) + ": " + message);
  std::vector<std::string> actual;
  for (const Diagnostic& error : result.errors) actual.push_back(error.to_string());
  EXPECT_EQ(actual, expected);
}

INSTANTIATE_TEST_SUITE_P(Texts, InlineErrors, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<InlineCase>& param) { return param.param.name; });

TEST(InlineErrors, DurationMustBePositive) {
  const LoadResult result = parse_scenario("seed = -3\nduration_s = 0\n", kFile);
  ASSERT_EQ(result.errors.size(), 2u);
  EXPECT_EQ(result.errors[0].to_string(), kFile + ":1: 'seed' must be in [0, 9,223,372,036,854,775,807], got -3");
  EXPECT_EQ(result.errors[1].to_string(), kFile + ":2: 'duration_s' must be in [1e-09, 86,400] s, got 0");
}

TEST(InlineErrors, TheBaseTextIsValid) {
  const LoadResult result = parse_scenario(kDriver, kFile);
  EXPECT_TRUE(result.ok()) << result.error_text();
}

}  // namespace
}  // namespace stepdance::sim::scenario
