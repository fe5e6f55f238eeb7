// The live view asks each kind for its page state: the test-only kinds (test_crank.hpp,
// test_gauge.hpp) declare their own parts ("cranks", "gauge") and give them, and the view sends
// them in hello and in its updates — with no file of sim/view/ or web/view/ naming them.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "sim/assembly/simulation_fixture.hpp"
#include "sim/kinds/test_crank.hpp"
#include "sim/kinds/test_gauge.hpp"
#include "view/view_session.hpp"

namespace stepdance::sim::test {
namespace {

using nlohmann::json;

/// StepASketch (knob 1 on ENC1 moves motor A) with a crank on ENC1 turning −1200 counts/s for
/// 2 s, and a gauge on socket A.
std::string scenario_text() {
  return "duration_s = 3\n"
         "[[board]]\nname = \"driver\"\nsketch = \"" +
         source_path("examples/StepASketch/StepASketch.ino") +
         "\"\n"
         "sockets = { A = { device = \"stepper\" }, B = { device = \"stepper\" } }\n"
         "[machine]\ntype = \"test_gauge\"\nboard = \"driver\"\n"
         "[[device]]\nname = \"crank\"\ntype = \"test_crank\"\nboard = \"driver\"\nconnector = \"ENC1\"\n"
         "counts_per_s = -1200\nstop_s = 2\n";
}

class TestKindsPage : public ::testing::Test {
 protected:
  void SetUp() override {
    simulation_ = create(parse(scenario_text(), "/tmp/test_kinds_page/scenario.toml"), "test_kinds_page", false);
    ASSERT_NE(simulation_, nullptr);
    session_ = std::make_unique<view::ViewSession>(*simulation_, control_);
  }
  json update_at(SimTime time) {
    simulation_->run_until(time);
    return json::parse(session_->update_now());
  }

  ScopedKind<DeviceRegistry> crank_{test_crank_kind()};
  ScopedKind<MachineRegistry> gauge_{test_gauge_kind()};
  std::unique_ptr<Simulation> simulation_;
  view::RunControl control_;
  std::unique_ptr<view::ViewSession> session_;
};

TEST_F(TestKindsPage, HelloDeclaresTheirParts) {
  const json hello = json::parse(session_->hello());
  EXPECT_EQ(hello["machine"]["kind"], "test_gauge");
  EXPECT_EQ(hello["machine"]["parts"], json::array({"gauge"}));
  const json& device = hello["boards"][0]["devices"][0];
  EXPECT_EQ(device["name"], "crank");
  EXPECT_EQ(device["parts"], json::array({"cranks"}));
  EXPECT_FALSE(device["control"].contains("counts_per_turn"));  // the crank's own device adds none
}

TEST_F(TestKindsPage, UpdatesCarryTheirStateWhenItChanges) {
  // −1200 counts/s: −600 counts at 0.5 s, −2400 from 2 s on (the crank stops).
  const json first = update_at(500 * kMillisecond);
  EXPECT_EQ(first["cranks"], json::parse(R"([{"device": "crank", "count": -600}])"));
  EXPECT_TRUE(first.contains("gauge"));  // the first update carries every part

  const json again = update_at(500 * kMillisecond);  // nothing moved: neither part again
  EXPECT_FALSE(again.contains("cranks"));
  EXPECT_FALSE(again.contains("gauge"));

  EXPECT_EQ(update_at(2500 * kMillisecond)["cranks"], json::parse(R"([{"device": "crank", "count": -2400}])"));
  // StepASketch moves x by counts / 100 mm, motor A −80 steps a mm (its channels inverted):
  // −2400 counts are −1920 steps once the sketch has caught up.
  const json last = update_at(3 * kSecond);
  EXPECT_FALSE(last.contains("cranks"));  // stopped at 2 s: unchanged since 2.5 s
  const json whole = [&] {
    session_->start_over();
    return json::parse(session_->update_now());
  }();
  EXPECT_EQ(whole["cranks"], json::parse(R"([{"device": "crank", "count": -2400}])"));
  EXPECT_EQ(whole["gauge"], json::parse(R"({"steps": -1920})"));
}

}  // namespace
}  // namespace stepdance::sim::test
