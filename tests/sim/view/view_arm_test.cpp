// ViewSession on the pantograph (a five-bar arm moved by a hand): updates carry its linkage.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "../assembly/simulation_fixture.hpp"
#include "page_model.hpp"
#include "view/view_session.hpp"

namespace stepdance::sim::view {
namespace {

using nlohmann::json;

double distance(const json& a, const json& b) {
  return std::hypot(a[0].get<double>() - b[0].get<double>(), a[1].get<double>() - b[1].get<double>());
}

TEST(ViewArm, UpdatesCarryTheArmsLinkageWithItsLinksLengths) {
  const std::string path = test::source_path("examples/Pantograph/scenario.toml");
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  auto simulation = test::create(test::parse(text.str(), path), "view_arm", false);
  ASSERT_NE(simulation, nullptr);
  RunControl control;
  ViewSession session(*simulation, control);
  page_test::PageModel page;
  int seen = 0;
  json first_stylus;
  bool moved = false;
  for (SimTime t = 0; t < 12 * kSecond; t += 250 * kMillisecond) {
    simulation->run_until(t + 250 * kMillisecond);
    page.apply(json::parse(session.update_now()));  // an arm comes when it moved (version 2)
    ASSERT_EQ(page.arms.count("arm"), 1u);
    const json& arm = page.arms["arm"];
    EXPECT_EQ(arm["device"], "arm");
    // The original pantograph's build (docs/scenario-format.md, five_bar_arm; the model's
    // defaults): pivots 60 mm apart, arms 145.75 and 134 mm, links 169 and 178.3 mm, the stylus
    // 28.82 mm from the elbow.
    EXPECT_NEAR(distance(arm["right_pivot"], arm["left_pivot"]), 60, 1e-9);
    EXPECT_NEAR(distance(arm["right_pivot"], arm["c"]), 145.75, 1e-9);
    EXPECT_NEAR(distance(arm["left_pivot"], arm["d"]), 134, 1e-9);
    EXPECT_NEAR(distance(arm["c"], arm["e"]), 169, 1e-9);
    EXPECT_NEAR(distance(arm["d"], arm["e"]), 178.3, 1e-9);
    EXPECT_NEAR(distance(arm["e"], arm["t"]), 28.82, 1e-9);
    if (first_stylus.is_null()) first_stylus = arm["t"];
    moved = moved || distance(first_stylus, arm["t"]) > 10;
    ++seen;
  }
  EXPECT_EQ(seen, 48);
  EXPECT_TRUE(moved);  // the hand moved the stylus: the linkage followed
}

}  // namespace
}  // namespace stepdance::sim::view
