// Cable: exact edge times after delay, stretch and glitch injection, and the counters.
#include <gtest/gtest.h>

#include "models/cable.hpp"

namespace stepdance::sim {
namespace {

constexpr SimTime kUs = kMicrosecond;
constexpr SimTime kFrame = 40 * kUs;

/// One frame from t0: X forward (STEP 2..4 µs, DIR 1..5 µs) then E reverse (STEP 6..13 µs).
PortWaveform two_pulse_frame(SimTime t0 = 0) {
  PortWaveform frame;
  frame.step = {{t0 + 2 * kUs, true}, {t0 + 4 * kUs, false}, {t0 + 6 * kUs, true}, {t0 + 13 * kUs, false}};
  frame.dir = {{t0 + 1 * kUs, true}, {t0 + 5 * kUs, false}};
  return frame;
}

EdgeList edges(std::initializer_list<std::pair<SimTime, bool>> list) {
  EdgeList out;
  for (const auto& [time, level] : list) out.push_back(Edge{time, level});
  return out;
}

void expect_edges(const EdgeList& actual, const EdgeList& expected) {
  ASSERT_EQ(actual.size(), expected.size());
  for (size_t i = 0; i < actual.size(); ++i) {
    EXPECT_EQ(actual[i].time, expected[i].time) << "edge " << i;
    EXPECT_EQ(actual[i].level, expected[i].level) << "edge " << i;
  }
}

TEST(Cable, APlainCablePassesEverythingUnchanged) {
  Cable cable;
  const PortWaveform out = cable.transmit(two_pulse_frame(), 0, kFrame);
  expect_edges(out.step, two_pulse_frame().step);
  expect_edges(out.dir, two_pulse_frame().dir);
  EXPECT_EQ(cable.counters().pulses_in, 2u);
  EXPECT_EQ(cable.counters().pulses_passed, 2u);
}

TEST(Cable, DelayMovesBothLines) {
  CableSettings settings;
  settings.delay = 150;
  Cable cable(settings);
  const PortWaveform out = cable.transmit(two_pulse_frame(), 0, kFrame);
  expect_edges(out.step, edges({{2150, true}, {4150, false}, {6150, true}, {13150, false}}));
  expect_edges(out.dir, edges({{1150, true}, {5150, false}}));
}

TEST(Cable, StretchMovesEveryFallingEdge) {
  CableSettings settings;
  settings.stretch = 400;
  Cable cable(settings);
  const PortWaveform out = cable.transmit(two_pulse_frame(), 0, kFrame);
  expect_edges(out.step, edges({{2000, true}, {4400, false}, {6000, true}, {13400, false}}));
  expect_edges(out.dir, two_pulse_frame().dir);
}

TEST(Cable, ShrinkingBelowZeroWidthRemovesThePulse) {
  CableSettings settings;
  settings.stretch = -2500;
  Cable cable(settings);
  const PortWaveform out = cable.transmit(two_pulse_frame(), 0, kFrame);
  expect_edges(out.step, edges({{6000, true}, {10500, false}}));
  EXPECT_EQ(cable.counters().pulses_removed, 1u);
  EXPECT_EQ(cable.counters().pulses_passed, 1u);
}

TEST(Cable, StretchingIntoTheNextPulseMergesThem) {
  CableSettings settings;
  settings.stretch = 2000;
  Cable cable(settings);
  const PortWaveform out = cable.transmit(two_pulse_frame(), 0, kFrame);
  expect_edges(out.step, edges({{2000, true}, {15000, false}}));
  EXPECT_EQ(cable.counters().pulses_merged, 1u);
  EXPECT_EQ(cable.counters().pulses_passed, 1u);
}

TEST(Cable, GlitchesFillOnlyIdleSlotsInsideTheWindow) {
  CableSettings settings;
  settings.glitch_every = 10 * kUs;
  settings.glitch_width = 500;
  settings.delay = 100;
  Cable cable(settings);
  // Slot 10 µs falls in the E pulse (6..13 µs); 20 and 30 µs are idle; 40 µs is the next window's.
  const PortWaveform first = cable.transmit(two_pulse_frame(), 0, kFrame);
  expect_edges(first.step, edges({{2100, true},
                                  {4100, false},
                                  {6100, true},
                                  {13100, false},
                                  {20100, true},
                                  {20600, false},
                                  {30100, true},
                                  {30600, false}}));
  const PortWaveform second = cable.transmit(PortWaveform{}, kFrame, 2 * kFrame);
  expect_edges(second.step, edges({{40100, true},
                                   {40600, false},
                                   {50100, true},
                                   {50600, false},
                                   {60100, true},
                                   {60600, false},
                                   {70100, true},
                                   {70600, false}}));
  EXPECT_EQ(cable.counters().glitches_injected, 6u);
  EXPECT_EQ(cable.counters().glitches_skipped, 1u);
  EXPECT_EQ(cable.counters().pulses_passed, 2u);
}

TEST(Cable, GlitchesKeepClearOfStretchedPulsesAndWindowEnds) {
  CableSettings settings;
  settings.stretch = 400;  // X 2..4.4 µs, E 6..13.4 µs
  settings.glitch_every = 4400;
  settings.glitch_width = 500;
  Cable cable(settings);
  // Slots: 4.4 (touches X's fall), 8.8 and 13.2 (inside E) skipped; 17.6 .. 35.2 injected;
  // 39.6 would end at 40.1 µs, past the window, so it is skipped.
  const PortWaveform out = cable.transmit(two_pulse_frame(), 0, kFrame);
  expect_edges(out.step, edges({{2000, true},
                                {4400, false},
                                {6000, true},
                                {13400, false},
                                {17600, true},
                                {18100, false},
                                {22000, true},
                                {22500, false},
                                {26400, true},
                                {26900, false},
                                {30800, true},
                                {31300, false},
                                {35200, true},
                                {35700, false}}));
  EXPECT_EQ(cable.counters().glitches_injected, 5u);
  EXPECT_EQ(cable.counters().glitches_skipped, 4u);
}

TEST(Cable, APulseOpenAtAWindowEndContinuesInTheNext) {
  CableSettings settings;
  settings.stretch = 500;
  Cable cable(settings);
  PortWaveform first;
  first.step = {{38 * kUs, true}};
  PortWaveform second;
  second.step = {{41 * kUs, false}};
  expect_edges(cable.transmit(first, 0, kFrame).step, edges({{38000, true}}));
  expect_edges(cable.transmit(second, kFrame, 2 * kFrame).step, edges({{41500, false}}));
  EXPECT_EQ(cable.counters().pulses_in, 1u);
  EXPECT_EQ(cable.counters().pulses_passed, 1u);
}

TEST(Cable, AnOpenPulseShrunkIntoThePastFallsAtTheWindowStart) {
  CableSettings settings;
  settings.stretch = -2000;
  Cable cable(settings);
  PortWaveform first;
  first.step = {{38 * kUs, true}};
  PortWaveform second;
  second.step = {{41 * kUs, false}};
  cable.transmit(first, 0, kFrame);
  expect_edges(cable.transmit(second, kFrame, 2 * kFrame).step, edges({{40000, false}}));
}

}  // namespace
}  // namespace stepdance::sim
