// ViewSession on a polar turntable: updates carry the table's angle and the arm's radius.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "../assembly/simulation_fixture.hpp"
#include "page_model.hpp"
#include "view/view_session.hpp"

namespace stepdance::sim::view {
namespace {

using nlohmann::json;

constexpr double kPi = 3.14159265358979323846;

/// examples/PolarTurntable's sketch and timeline (the table turning, the lever moving the pen
/// out) on a polar machine: its motor A turns the table, B moves the arm (the sketch drives them
/// for a CoreXY plotter, so the drawing is not the example's; the motion is what counts here).
std::string turntable_scenario() {
  std::ifstream file(test::source_path("examples/PolarTurntable/scenario.toml"));
  std::stringstream text;
  text << file.rdbuf();
  std::string scenario =
      std::regex_replace(text.str(), std::regex(R"(\[machine\]\ntype = "corexy_plotter"\nboard = "driver"\n)"),
                         "[machine]\ntype = \"polar\"\nboard = \"driver\"\nangle = \"A\"\nradius = \"B\"\n"
                         "steps_per_rev = 3200\nsteps_per_mm = 80\n");
  return scenario.substr(0, scenario.find("[[expect]]"));
}

TEST(ViewTurntable, UpdatesCarryTheTablesAngleAndTheArmsRadius) {
  const std::string text = turntable_scenario();
  ASSERT_NE(text.find("type = \"polar\""), std::string::npos);
  auto simulation = test::create(test::parse(text, test::source_path("examples/PolarTurntable/scenario.toml")),
                                 "view_turntable", false);
  ASSERT_NE(simulation, nullptr);
  RunControl control;
  ViewSession session(*simulation, control);
  EXPECT_EQ(json::parse(session.hello())["machine"]["kind"], "polar");
  page_test::PageModel page;
  int moving = 0;
  for (SimTime t = 0; t < 8 * kSecond; t += 500 * kMillisecond) {  // the table turning, the arm moving out
    simulation->run_until(t + 500 * kMillisecond);
    page.apply(json::parse(session.update_now()));  // the table and pen come when they moved (version 2)
    ASSERT_TRUE(page.table.is_object());
    const json& update = json{{"table", page.table}, {"pen", page.pen}};
    // The documented geometry (sim/models/polar_turntable.hpp): θ = 2π · A steps / steps_per_rev,
    // r = B steps / steps_per_mm, and the pen on the paper at r (cos −θ, sin −θ).
    const double steps_a = static_cast<double>(simulation->stepper("driver", 'A')->position_steps());
    const double steps_b = static_cast<double>(simulation->stepper("driver", 'B')->position_steps());
    const double angle = 2 * kPi * steps_a / 3200, radius = steps_b / 80;
    EXPECT_NEAR(update["table"]["angle_rad"].get<double>(), angle, 1e-12);
    EXPECT_NEAR(update["table"]["radius_mm"].get<double>(), radius, 1e-12);
    EXPECT_NEAR(update["pen"]["x_mm"].get<double>(), radius * std::cos(-angle), 1e-9);
    EXPECT_NEAR(update["pen"]["y_mm"].get<double>(), radius * std::sin(-angle), 1e-9);
    if (steps_a != 0 && steps_b != 0) ++moving;
  }
  EXPECT_GT(moving, 3);  // the table turned and the arm moved: the check saw real motion
}

}  // namespace
}  // namespace stepdance::sim::view
