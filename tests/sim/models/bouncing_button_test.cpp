// BouncingButton: settled levels, bounce inside its window, determinism and polarity.
#include <gtest/gtest.h>

#include "models/bouncing_button.hpp"

namespace stepdance::sim {
namespace {

/// Edges strictly inside (from, to).
EdgeList edges_inside(const BouncingButton& button, SimTime from, SimTime to) {
  EdgeList inside;
  for (const Edge& edge : button.edges()) {
    if (edge.time > from && edge.time < to) inside.push_back(edge);
  }
  return inside;
}

TEST(BouncingButton, PressBouncesThenSettles) {
  BouncingButton button;  // 2 ms bounce, pressed = high, seed 1
  button.press(10 * kMillisecond);
  EXPECT_FALSE(button.level_at(10 * kMillisecond - 1));
  EXPECT_TRUE(button.level_at(10 * kMillisecond));
  const EdgeList bounce = edges_inside(button, 10 * kMillisecond, 12 * kMillisecond);
  ASSERT_GE(bounce.size(), 2u);
  ASSERT_LE(bounce.size(), 6u);
  EXPECT_EQ(bounce.size() % 2, 0u);
  bool level = true;
  for (const Edge& edge : bounce) {
    EXPECT_NE(edge.level, level);  // each bounce edge toggles
    level = edge.level;
  }
  EXPECT_FALSE(bounce.front().level);
  EXPECT_FALSE(button.level_at(bounce.front().time));
  for (SimTime t = 12 * kMillisecond; t < 20 * kMillisecond; t += kMillisecond) EXPECT_TRUE(button.level_at(t));
  EXPECT_TRUE(button.pressed_at(10 * kMillisecond));
}

TEST(BouncingButton, ReleaseSettlesLowAfterTheBounceTime) {
  BouncingButton button;
  button.press(0);
  button.release(100 * kMillisecond);
  EXPECT_TRUE(button.level_at(100 * kMillisecond - 1));
  EXPECT_FALSE(button.level_at(100 * kMillisecond));
  EXPECT_GE(edges_inside(button, 100 * kMillisecond, 102 * kMillisecond).size(), 2u);
  EXPECT_FALSE(button.level_at(102 * kMillisecond));
  EXPECT_FALSE(button.pressed_at(100 * kMillisecond));
}

TEST(BouncingButton, TheSameSeedGivesTheSameEdges) {
  ButtonSettings other_seed;
  other_seed.seed = 2;
  BouncingButton first;
  BouncingButton second;
  BouncingButton third(other_seed);
  for (BouncingButton* button : {&first, &second, &third}) button->click(50 * kMillisecond, 100 * kMillisecond);
  ASSERT_EQ(first.edges().size(), second.edges().size());
  for (size_t i = 0; i < first.edges().size(); ++i) {
    EXPECT_EQ(first.edges()[i].time, second.edges()[i].time);
    EXPECT_EQ(first.edges()[i].level, second.edges()[i].level);
  }
  bool differs = first.edges().size() != third.edges().size();
  for (size_t i = 0; !differs && i < first.edges().size(); ++i)
    differs = first.edges()[i].time != third.edges()[i].time;
  EXPECT_TRUE(differs);
}

TEST(BouncingButton, PressedLowButtonIdlesHigh) {
  ButtonSettings settings;
  settings.pressed_level = false;
  settings.bounce = 0;
  BouncingButton button(settings);
  button.click(1 * kMillisecond, 5 * kMillisecond);
  EXPECT_TRUE(button.idle_level());
  EXPECT_TRUE(button.level_at(0));
  EXPECT_FALSE(button.level_at(1 * kMillisecond));
  EXPECT_FALSE(button.level_at(6 * kMillisecond - 1));
  EXPECT_TRUE(button.level_at(6 * kMillisecond));
  EXPECT_EQ(button.edges().size(), 2u);  // no bounce
}

TEST(BouncingButton, ANextTransitionCutsTheBounceShort) {
  BouncingButton button;
  button.click(0, 1 * kMillisecond);  // the press would bounce until 2 ms
  const EdgeList& edges = button.edges();
  for (size_t i = 1; i < edges.size(); ++i) EXPECT_LT(edges[i - 1].time, edges[i].time);
  size_t release = 0;
  while (release < edges.size() && edges[release].time < 1 * kMillisecond) ++release;
  ASSERT_LT(release, edges.size());
  EXPECT_EQ(edges[release].time, 1 * kMillisecond);
  EXPECT_FALSE(edges[release].level);
  EXPECT_TRUE(edges[release - 1].level);  // the press bounce ended settled high
  EXPECT_FALSE(button.level_at(3 * kMillisecond));
}

TEST(BouncingButton, RepeatedPressesChangeNothing) {
  ButtonSettings settings;
  settings.bounce = 0;
  BouncingButton button(settings);
  button.press(1000);
  button.press(2000);
  button.release(3000);
  button.release(4000);
  ASSERT_EQ(button.edges().size(), 2u);
  EXPECT_EQ(button.edges()[0].time, 1000);
  EXPECT_EQ(button.edges()[1].time, 3000);
}

TEST(BouncingButton, TransitionsMayBeScheduledOutOfOrder) {
  ButtonSettings settings;
  settings.bounce = 0;
  BouncingButton button(settings);
  button.release(3000);
  button.press(1000);
  EXPECT_TRUE(button.level_at(2000));
  EXPECT_FALSE(button.level_at(3000));
}

}  // namespace
}  // namespace stepdance::sim
