// ViewSession on Step-A-Sketch: hello, updates, inputs equal to timeline actions, bad messages.
#include <nlohmann/json.hpp>

#include "../assembly/simulation_fixture.hpp"
#include "page_model.hpp"
#include "view/view_session.hpp"

namespace stepdance::sim::view {
namespace {

using nlohmann::json;
using test::create;
using test::parse;
using test::source_path;

/// Step-A-Sketch on a CoreXY AxiDraw (examples/StepASketch): knob 1 moves x, 100 counts = 1 mm,
/// inverted (−counts → +x); the button on D1 toggles the pen. `timeline` is appended.
std::string step_a_sketch(const std::string& timeline) {
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
name = "knob_y"
type = "encoder"
board = "driver"
connector = "ENC2"
[[device]]
name = "pen_button"
type = "button"
board = "driver"
connector = "D1"
bounce_ms = 2
[output]
svg = "drawing.svg"
)" + timeline;
}

std::unique_ptr<Simulation> make(const std::string& timeline, const std::string& output) {
  return create(parse(step_a_sketch(timeline), source_path("examples/StepASketch/scenario.toml")), output, false);
}

json only_message(const std::vector<std::string>& replies) {
  EXPECT_EQ(replies.size(), 1u);
  return replies.empty() ? json() : json::parse(replies.front());
}

TEST(ViewSession, HelloDescribesTheMachineBoardsAndControls) {
  auto simulation = make("", "view_hello");
  RunControl control;
  ViewSession session(*simulation, control);
  const json hello = json::parse(session.hello());
  EXPECT_EQ(hello["type"], "hello");
  EXPECT_EQ(hello["version"], kProtocolVersion);
  EXPECT_EQ(hello["machine"]["kind"], "corexy_plotter");
  // The AxiDraw V3's travel, the page the SVG uses (docs/scenario-format.md: 300 × 218 mm).
  EXPECT_EQ(hello["machine"]["page_mm"], json::array({0, 300, 0, 218}));
  ASSERT_EQ(hello["boards"].size(), 1u);
  const json& board = hello["boards"][0];
  EXPECT_EQ(board["motors"], json::array({"A", "B"}));
  ASSERT_EQ(board["devices"].size(), 3u);
  EXPECT_EQ(board["devices"][0]["control"]["type"], "knob");
  EXPECT_EQ(board["devices"][0]["control"]["counts_per_turn"], 2400);  // 600 pulses × 4
  EXPECT_EQ(board["devices"][2]["control"]["type"], "button");
  EXPECT_EQ(board["devices"][2]["connector"], "D1");
}

// The pen goes down at (0, 0) and knob 1 turns one whole turn the other way (−2400 counts):
// the pen draws to (24, 0) mm, and the motors take a = −80 × (x + y) = −1920 and
// b = −80 × (x − y) = −1920 microsteps (80 microsteps a mm).
constexpr const char* kTimeline = R"(
[[at]]
time_s = 0.2
click = "pen_button"
[[at]]
time_s = 1.0
turn = "knob_x"
counts = -2400
over_s = 0.5
)";

TEST(ViewSession, ALimitSwitchIsAButtonToClickOrHold) {
  // A switch at x = 0 on LIMIT_A: the machine trips it, and a hand may hold it (a page button).
  auto simulation = make(R"(
[[device]]
name = "home_x"
type = "limit_switch"
board = "driver"
connector = "LIMIT_A"
axis = "x"
at_mm = -5
)",
                         "view_limit_switch");
  RunControl control;
  ViewSession session(*simulation, control);
  const json hello = json::parse(session.hello());
  const json& device = hello["boards"][0]["devices"][3];
  EXPECT_EQ(device["name"], "home_x");
  EXPECT_EQ(device["kind"], "limit_switch");
  EXPECT_EQ(device["control"]["type"], "button");
  for (const char* action : {"press", "release", "click"}) {
    EXPECT_TRUE(
        session.receive(std::string(R"({"type":"input","device":"home_x","action":")") + action + "\"}").empty())
        << action;
  }
  EXPECT_EQ(
      only_message(session.receive(R"({"type":"input","device":"home_x","action":"turn","counts":1})"))["message"],
      "input: a limit switch does not take \"turn\"");
}

TEST(ViewSession, InputsGiveExactlyTheStepsAndStrokeOfTheSameTimelineActions) {
  auto scripted = make(kTimeline, "view_scripted");
  scripted->run_until(3 * kSecond);
  auto live = make("", "view_live");
  RunControl control;
  ViewSession session(*live, control);
  live->run_until(200 * kMillisecond);
  EXPECT_TRUE(session.receive(R"({"type":"input","device":"pen_button","action":"click"})").empty());
  live->run_until(1000 * kMillisecond);
  EXPECT_TRUE(
      session.receive(R"({"type":"input","device":"knob_x","action":"turn","counts":-2400,"over_ms":500})").empty());
  live->run_until(3 * kSecond);
  for (Simulation* simulation : {scripted.get(), live.get()}) {
    EXPECT_EQ(simulation->stepper("driver", 'A')->position_steps(), -1920);
    EXPECT_EQ(simulation->stepper("driver", 'B')->position_steps(), -1920);
    ASSERT_EQ(simulation->machine()->strokes().size(), 1u);
    EXPECT_EQ(simulation->machine()->strokes()[0].front(), (PenPoint{0, 0}));
    EXPECT_EQ(simulation->machine()->strokes()[0].back(), (PenPoint{24, 0}));
  }
  EXPECT_EQ(live->stepper("driver", 'A')->forward_steps(), scripted->stepper("driver", 'A')->forward_steps());
  EXPECT_EQ(live->stepper("driver", 'A')->reverse_steps(), scripted->stepper("driver", 'A')->reverse_steps());
  EXPECT_EQ(live->machine()->strokes(), scripted->machine()->strokes());
  EXPECT_EQ(live->drawing_svg(), scripted->drawing_svg());
}

TEST(ViewSession, UpdatesCarryTheDrawingAndComeAtMostSixtyTimesASecond) {
  auto simulation = make(kTimeline, "view_updates");
  RunControl control;
  ViewSession session(*simulation, control);
  page_test::PageModel page;
  int updates = 0;
  double wall_s = 0;
  for (SimTime t = 0; t < 3 * kSecond; t += kMillisecond) {
    simulation->run_until(t + kMillisecond);
    wall_s += 0.001;  // 1 ms of wall time a step: 3000 steps → at most 3 / (1/60) + 1 = 181 updates
    if (const auto text = session.update(wall_s)) {
      ++updates;
      page.apply(json::parse(*text));
    }
  }
  EXPECT_LE(updates, 181);
  EXPECT_GE(updates, 170);  // the run moves on (t_s, the frame count): every due update is made
  ASSERT_EQ(page.strokes.size(), 1u);
  EXPECT_EQ(page.strokes[0].front(), std::make_pair(0.0, 0.0));
  EXPECT_EQ(page.strokes[0].back(), std::make_pair(24.0, 0.0));
  page.apply(json::parse(session.update_now()));
  EXPECT_EQ(page.motors["driver A"]["steps"], -1920);
  EXPECT_EQ(page.motors["driver A"]["rate_steps_per_s"], 0);  // at rest since the turn ended at 1.5 s
  EXPECT_TRUE(page.pen["down"]);                              // one click: the pen stays down
}

// Version 2's deltas: an update carries a part only when it differs from what the page has.
TEST(ViewSession, UpdatesCarryOnlyWhatChanged) {
  auto simulation = make(kTimeline, "view_deltas");
  RunControl control;
  ViewSession session(*simulation, control);
  simulation->run_until(800 * kMillisecond);  // the pen went down at 0.2 s; the turn starts at 1.0 s
  const json first = json::parse(session.update_now());
  for (const char* part : {"run", "pen", "motors", "boards"}) EXPECT_TRUE(first.contains(part)) << part;
  simulation->run_until(900 * kMillisecond);  // nothing moved: time and the frame count did
  const json still = json::parse(session.update_now());
  for (const char* part : {"run", "pen", "strokes", "motors", "console"}) EXPECT_FALSE(still.contains(part)) << part;
  ASSERT_TRUE(still.contains("boards"));
  EXPECT_EQ(still["boards"][0]["frames"].get<int64_t>() - first["boards"][0]["frames"].get<int64_t>(),
            100 * 25);                         // 0.1 s of 25 kHz frames
  simulation->run_until(1200 * kMillisecond);  // the turn under way: the pen, both motors, a stroke
  const json moving = json::parse(session.update_now());
  EXPECT_TRUE(moving.contains("pen"));
  EXPECT_EQ(moving["motors"].size(), 2u);
  EXPECT_EQ(moving["strokes"].size(), 1u);
}

TEST(ViewSession, APausedRunSendsNothing) {
  auto simulation = make(kTimeline, "view_paused");
  RunControl control;
  ViewSession session(*simulation, control);
  simulation->run_until(1200 * kMillisecond);  // mid-turn: the motors have a rate
  ASSERT_TRUE(session.update(0.0));
  ASSERT_TRUE(session.receive(R"({"type":"run","action":"pause"})").empty());
  const auto paused = session.update(1.0);  // says "paused", once
  ASSERT_TRUE(paused);
  EXPECT_EQ(json::parse(*paused)["run"]["paused"], true);
  for (int second = 2; second < 60; ++second) EXPECT_FALSE(session.update(second)) << second;
  EXPECT_EQ(session.updates_made(), 2u);
}

// A page that follows the deltas has what a new page gets in its first, whole update.
TEST(ViewSession, DeltasAddUpToTheWholeState) {
  auto simulation = make(kTimeline, "view_delta_sum");
  RunControl control;
  ViewSession session(*simulation, control);
  page_test::PageModel page;
  for (SimTime t = 100 * kMillisecond; t <= 3 * kSecond; t += 100 * kMillisecond) {
    simulation->run_until(t);
    page.apply(json::parse(session.update_now()));
    ViewSession fresh(*simulation, control);
    page_test::PageModel whole;
    whole.apply(json::parse(fresh.update_now()));
    EXPECT_TRUE(page.same_state(whole)) << "at " << to_seconds(t) << " s";
  }
}

// A page that asks for hello starts over: its next update is the whole state, the drawing from
// its first stroke.
TEST(ViewSession, HelloStartsThePageOver) {
  auto simulation = make(kTimeline, "view_hello_again");
  RunControl control;
  ViewSession session(*simulation, control);
  simulation->run_until(3 * kSecond);
  page_test::PageModel before;
  before.apply(json::parse(session.update_now()));
  EXPECT_EQ(only_message(session.receive(R"({"type":"hello"})"))["type"], "hello");
  page_test::PageModel after;
  after.apply(json::parse(session.update_now()));
  EXPECT_TRUE(after.same_state(before));
  ASSERT_EQ(after.strokes.size(), 1u);
  EXPECT_EQ(after.strokes[0].back(), std::make_pair(24.0, 0.0));
}

// Off the paper: knob 1 turned the "natural" way (+2400 counts, inverted: −24 mm along x) takes
// the pen past the travel area's x = 0 edge; the update says so the moment it does, with where
// and when it left (the turn starts at 1.0 s from x = 0; one microstep is 1/80 mm, the area's
// tolerance), and again when it is back inside after turning back.
TEST(ViewSession, UpdatesMarkThePenLeavingTheTravelArea) {
  auto simulation = make(R"(
[[at]]
time_s = 1.0
turn = "knob_x"
counts = 2400
over_s = 0.5
[[at]]
time_s = 2.0
turn = "knob_x"
counts = -4800
over_s = 1
)",
                         "view_travel");
  RunControl control;
  ViewSession session(*simulation, control);
  page_test::PageModel page;
  simulation->run_until(900 * kMillisecond);
  page.apply(json::parse(session.update_now()));
  EXPECT_EQ(page.travel["excursions"], 0);
  EXPECT_EQ(page.travel["outside"], false);
  simulation->run_until(1600 * kMillisecond);
  page.apply(json::parse(session.update_now()));
  EXPECT_EQ(page.travel["excursions"], 1);
  EXPECT_EQ(page.travel["outside"], true);
  ASSERT_EQ(page.travel["first_points"].size(), 1u);
  const json& left = page.travel["first_points"][0];
  EXPECT_GE(left["t_s"].get<double>(), 1.0);
  EXPECT_LT(left["t_s"].get<double>(), 1.05);  // 24 mm in 0.5 s: 0.1 mm in about 2 ms
  EXPECT_LT(left["x_mm"].get<double>(), -1.0 / 80);
  EXPECT_GT(left["x_mm"].get<double>(), -0.1);
  EXPECT_NEAR(page.travel["first_points"][0]["y_mm"].get<double>(), 0, 0.1);
  simulation->run_until(3 * kSecond);
  page.apply(json::parse(session.update_now()));
  EXPECT_EQ(page.travel["excursions"], 1);
  EXPECT_EQ(page.travel["outside"], false);                         // back at x = +24 mm
  EXPECT_EQ(simulation->machine()->stats().travel_excursions, 1u);  // what the summary counts
}

TEST(ViewSession, SaveGivesTheSvgTheRunWritesAtThatInstant) {
  auto simulation = make(kTimeline, "view_save");
  RunControl control;
  ViewSession session(*simulation, control);
  simulation->run_until(3 * kSecond);
  const json drawing = only_message(session.receive(R"({"type":"save"})"));
  EXPECT_EQ(drawing["type"], "drawing");
  const SimulationReport report = simulation->finish();
  std::ifstream file(test::test_output_dir("view_save") + "/drawing.svg");
  std::stringstream bytes;
  bytes << file.rdbuf();
  EXPECT_EQ(drawing["svg"], bytes.str());
}

// The board's warnings reach the page with each update: each kind with its count and the first
// report's detail (tests/sim/assembly/fixtures/HostFeatures warns once per "warn" line).
TEST(ViewSession, UpdatesCarryEachBoardsWarnings) {
  const char* const scenario = R"(
duration_s = 0.5
[[board]]
name = "board"
sketch = "HostFeatures.ino"
[board.sockets]
A = { device = "stepper" }
[[at]]
time_s = 0.1
serial = "board"
text = "warn\nwarn\n"
[output]
svg = ""
png = ""
)";
  auto simulation = create(parse(scenario, source_path("tests/sim/assembly/fixtures/HostFeatures/scenario.toml")),
                           "view_warnings", false);
  ASSERT_NE(simulation, nullptr);
  RunControl control;
  ViewSession session(*simulation, control);
  simulation->run_until(50 * kMillisecond);
  EXPECT_EQ(json::parse(session.update_now())["boards"][0]["warnings"], json::array());
  simulation->run_until(200 * kMillisecond);
  const json warnings = json::parse(session.update_now())["boards"][0]["warnings"];
  EXPECT_EQ(warnings, json::parse(R"([{"name": "fixture: overrun", "count": 2, "detail": "warned over serial"}])"));
}

TEST(ViewSession, BadMessagesGetAClearErrorAndChangeNothing) {
  auto simulation = make("", "view_bad");
  RunControl control;
  ViewSession session(*simulation, control);
  simulation->run_until(100 * kMillisecond);
  const std::pair<std::string, std::string> cases[] = {
      {"{not json", "not a JSON object"},
      {"[1,2]", "not a JSON object"},
      {R"({"kind":"input"})", "no \"type\""},
      {R"({"type":"launch"})", "unknown message type \"launch\""},
      {R"({"type":"input","device":"nothing","action":"turn","counts":1})", "input: no device named \"nothing\""},
      {R"({"type":"input","device":"knob_x","action":"press"})", "input: an encoder does not take \"press\""},
      {R"({"type":"input","device":"knob_x","action":"turn","counts":1.5})", "input: turn needs \"counts\""},
      {R"({"type":"input","device":"pen_button","action":"click","hold_ms":-1})", "input: \"hold_ms\" must be"},
      {R"({"type":"console","board":"nobody","text":"x"})", "console: no board named \"nobody\""},
      {R"({"type":"run","action":"speed","speed":3})", "run: \"speed\" must be 1, 10 or \"max\""},
      {std::string(kMaxInputBytes + 1, ' '), "message of 4097 bytes refused: at most 4096"},
  };
  for (const auto& [text, error] : cases) {
    const json reply = only_message(session.receive(text));
    EXPECT_EQ(reply["type"], "error") << text;
    EXPECT_EQ(reply["message"].get<std::string>().rfind(error, 0), 0u) << reply["message"];
  }
  simulation->run_until(3 * kSecond);
  EXPECT_EQ(simulation->stepper("driver", 'A')->position_steps(), 0);
  EXPECT_TRUE(simulation->machine()->strokes().empty());
  EXPECT_FALSE(control.paused);
  EXPECT_EQ(control.speed, 1.0);
}

TEST(ViewSession, RunControlMessagesSetTheSharedControl) {
  auto simulation = make("", "view_run");
  RunControl control;
  ViewSession session(*simulation, control);
  EXPECT_TRUE(session.receive(R"({"type":"run","action":"pause"})").empty());
  EXPECT_TRUE(control.paused);
  EXPECT_TRUE(session.receive(R"({"type":"run","action":"speed","speed":"max"})").empty());
  EXPECT_EQ(control.speed, 0.0);
  EXPECT_TRUE(session.receive(R"({"type":"run","action":"speed","speed":10})").empty());
  EXPECT_EQ(control.speed, 10.0);
  EXPECT_TRUE(session.receive(R"({"type":"run","action":"resume"})").empty());
  EXPECT_FALSE(control.paused);
}

}  // namespace
}  // namespace stepdance::sim::view
