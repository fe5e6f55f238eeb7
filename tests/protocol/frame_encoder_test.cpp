// Frame encoder: every signal set and direction pattern checked against a µs-by-µs wire model.
#include <gtest/gtest.h>

#include <stdint.h>

#include <string>
#include <vector>

#include "stepdance/protocol/frame_encoder.hpp"

namespace stepdance::protocol {
namespace {

// ---- An independent model of the wire, built from the protocol rules only ------------------
//
// Rules: bit n is the line level from n µs to n+1 µs. Pulses are laid out in index order; the
// first rises at 2 µs, each is followed by a 2 µs gap; widths are 2..7 µs for X..E. A forward
// pulse's DIR is high from 1 µs before STEP rises to 1 µs after STEP falls. A set fits when its
// last STEP pulse has fallen by 31 µs (bit 31 stays low).

constexpr int kWidthUs[6] = {2, 3, 4, 5, 6, 7};
constexpr const char* kNames = "XYRTZE";

struct ModelPulse {
  int signal;
  int rise_us;  // STEP goes high at this time
  int fall_us;  // STEP goes low at this time
  bool forward;
};

bool has(uint8_t mask, int signal) { return (mask >> signal) & 1u; }

// The STEP pulses of `mask`, placed in index order.
std::vector<ModelPulse> lay_out(uint8_t mask, uint8_t forward_mask) {
  std::vector<ModelPulse> pulses;
  int now_us = 2;
  for (int signal = 0; signal < 6; ++signal) {
    if (!has(mask, signal)) continue;
    pulses.push_back({signal, now_us, now_us + kWidthUs[signal], has(forward_mask, signal)});
    now_us += kWidthUs[signal] + 2;
  }
  return pulses;
}

bool model_fits(uint8_t mask) {
  const std::vector<ModelPulse> pulses = lay_out(mask, 0);
  return pulses.empty() || pulses.back().fall_us <= 31;
}

// Samples both lines once per microsecond and packs the levels into words.
FrameWords simulate_wire(const std::vector<ModelPulse>& pulses) {
  FrameWords words;
  for (int t = 0; t < 32; ++t) {
    bool step = false;
    bool dir = false;
    for (const ModelPulse& p : pulses) {
      step = step || (p.rise_us <= t && t < p.fall_us);
      dir = dir || (p.forward && p.rise_us - 1 <= t && t < p.fall_us + 1);
    }
    if (step) words.step_bits |= 1u << t;
    if (dir) words.dir_bits |= 1u << t;
  }
  return words;
}

// Which requested signals go out: carried (priority) ones first, then the others, each in
// index order, each taken only if the set chosen so far still fits.
uint8_t model_selection(uint8_t active, uint8_t priority) {
  uint8_t chosen = 0;
  for (int pass = 0; pass < 2; ++pass) {
    const uint8_t candidates = pass == 0 ? (active & priority) : active;
    for (int signal = 0; signal < 6; ++signal) {
      const uint8_t with = static_cast<uint8_t>(chosen | (1u << signal));
      if (has(candidates, signal) && model_fits(with)) chosen = with;
    }
  }
  return chosen;
}

std::string names(uint8_t mask) {
  std::string out;
  for (int signal = 0; signal < 6; ++signal) {
    if (has(mask, signal)) out += kNames[signal];
  }
  return out.empty() ? "-" : out;
}

EncodedFrame encode(uint8_t active, uint8_t forward, uint8_t priority = 0) {
  FrameRequest request;
  request.active_mask = active;
  request.forward_mask = forward;
  request.priority_mask = priority;
  return encode_frame(request);
}

// Checks one request against the model, words and masks.
void expect_matches_model(uint8_t active, uint8_t forward, uint8_t priority) {
  SCOPED_TRACE("active " + names(active) + " forward " + names(forward & active) + " priority " +
               names(priority & active));
  const uint8_t sent = model_selection(active, priority);
  const FrameWords expected = simulate_wire(lay_out(sent, forward));
  const EncodedFrame frame = encode(active, forward, priority);
  EXPECT_EQ(frame.sent_mask, sent);
  EXPECT_EQ(frame.carried_mask, active & ~sent & 0x3F);
  EXPECT_EQ(frame.words.step_bits, expected.step_bits);
  EXPECT_EQ(frame.words.dir_bits, expected.dir_bits);
}

// Every subset of `mask`, including 0 and mask itself.
std::vector<uint8_t> subsets(uint8_t mask) {
  std::vector<uint8_t> out;
  uint8_t sub = mask;
  while (true) {
    out.push_back(sub);
    if (sub == 0) break;
    sub = static_cast<uint8_t>((sub - 1) & mask);
  }
  return out;
}

// Recovers (rise, fall) pairs of high runs from a word; bit 32 and beyond are low.
std::vector<std::pair<int, int>> high_runs(uint32_t word) {
  std::vector<std::pair<int, int>> runs;
  for (int t = 0; t < 32; ++t) {
    const bool now = (word >> t) & 1u;
    const bool before = t > 0 && ((word >> (t - 1)) & 1u);
    if (now && !before) runs.push_back({t, t});
    if (now) runs.back().second = t + 1;
  }
  return runs;
}

// ---- Literal, hand-computed frames --------------------------------------------------------

TEST(FrameEncoderLiteral, EmptyRequestIsAnIdleFrame) {
  const EncodedFrame frame = encode(0, 0x3F, 0x3F);
  EXPECT_EQ(frame.words.step_bits, 0u);
  EXPECT_EQ(frame.words.dir_bits, 0u);
  EXPECT_EQ(frame.sent_mask, 0);
  EXPECT_EQ(frame.carried_mask, 0);
}

TEST(FrameEncoderLiteral, XAloneForwardAndReverse) {
  const EncodedFrame forward = encode(0b000001, 0b000001);
  EXPECT_EQ(forward.words.step_bits, 0x0000000Cu);  // bits 2..3
  EXPECT_EQ(forward.words.dir_bits, 0x0000001Eu);   // bits 1..4
  EXPECT_EQ(forward.sent_mask, 0b000001);
  EXPECT_EQ(forward.carried_mask, 0);

  const EncodedFrame reverse = encode(0b000001, 0);
  EXPECT_EQ(reverse.words.step_bits, 0x0000000Cu);
  EXPECT_EQ(reverse.words.dir_bits, 0u);
}

TEST(FrameEncoderLiteral, EachSignalAloneStartsAtTwoMicroseconds) {
  // STEP bits 2..(1+w), forward DIR bits 1..(2+w), for w = 2..7.
  const uint32_t step[6] = {0x0000000C, 0x0000001C, 0x0000003C, 0x0000007C, 0x000000FC, 0x000001FC};
  const uint32_t dir[6] = {0x0000001E, 0x0000003E, 0x0000007E, 0x000000FE, 0x000001FE, 0x000003FE};
  for (int signal = 0; signal < 6; ++signal) {
    SCOPED_TRACE(kNames[signal]);
    const uint8_t bit = static_cast<uint8_t>(1u << signal);
    const EncodedFrame frame = encode(bit, bit);
    EXPECT_EQ(frame.words.step_bits, step[signal]);
    EXPECT_EQ(frame.words.dir_bits, dir[signal]);
    EXPECT_EQ(encode(bit, 0).words.dir_bits, 0u);
  }
}

TEST(FrameEncoderLiteral, AllSixForwardDropsEToTheNextFrame) {
  // X[2,4) Y[6,9) R[11,15) T[17,22) Z[24,30); E would need [32,39).
  const EncodedFrame frame = encode(0x3F, 0x3F);
  EXPECT_EQ(frame.words.step_bits, 0x3F3E79CCu);
  EXPECT_EQ(frame.words.dir_bits, 0x7FFFFFFEu);  // abutting windows: bits 1..30
  EXPECT_EQ(frame.sent_mask, 0b011111);
  EXPECT_EQ(frame.carried_mask, 0b100000);
}

TEST(FrameEncoderLiteral, AllSixAlternatingDirections) {
  // X, R, Z forward; Y, T reverse: DIR bits 1..4, 10..15, 23..30.
  const EncodedFrame frame = encode(0x3F, 0b010101);
  EXPECT_EQ(frame.words.step_bits, 0x3F3E79CCu);
  EXPECT_EQ(frame.words.dir_bits, 0x7F80FC1Eu);
  EXPECT_EQ(encode(0x3F, 0).words.dir_bits, 0u);
}

TEST(FrameEncoderLiteral, XYRTEFillsTheFrameExactly) {
  // E[24,31) ends at 31 µs: fits. Its DIR window [23,32) reaches bit 31.
  const EncodedFrame frame = encode(0b101111, 0b101111);
  EXPECT_EQ(frame.words.step_bits, 0x7F3E79CCu);
  EXPECT_EQ(frame.words.dir_bits, 0xFFFFFFFEu);
  EXPECT_EQ(frame.sent_mask, 0b101111);
  EXPECT_EQ(frame.carried_mask, 0);
}

TEST(FrameEncoderLiteral, ZAndEAlonePackFromTheStart) {
  // Z[2,8) E[10,17); DIR [1,9) and [9,18) abut.
  const EncodedFrame frame = encode(0b110000, 0b110000);
  EXPECT_EQ(frame.words.step_bits, 0x0001FCFCu);
  EXPECT_EQ(frame.words.dir_bits, 0x0003FFFEu);
}

TEST(FrameEncoderLiteral, PriorityEIsServedFirstAndZWaits) {
  // E first (9 µs), then X, Y, R, T fit (31 µs in all); Z would need 39.
  const EncodedFrame frame = encode(0x3F, 0x3F, 0b100000);
  EXPECT_EQ(frame.sent_mask, 0b101111);
  EXPECT_EQ(frame.carried_mask, 0b010000);
  EXPECT_EQ(frame.words.step_bits, 0x7F3E79CCu);  // still laid out in index order
  EXPECT_EQ(frame.words.dir_bits, 0xFFFFFFFEu);
}

// ---- Exhaustive checks against the wire model ----------------------------------------------

TEST(FrameEncoderModel, ModelAgreesWithTheReferenceFacts) {
  // The model alone: signals are lost only for five-signal sets with both Z and E, and for the
  // full set; always E.
  for (uint8_t active = 1; active < 64; ++active) {
    const uint8_t sent = model_selection(active, 0);
    const bool z_and_e = has(active, 4) && has(active, 5);
    const int count = __builtin_popcount(active);
    const bool loses = count == 6 || (count == 5 && z_and_e);
    EXPECT_EQ(sent, loses ? (active & 0b011111) : active) << names(active);
  }
}

TEST(FrameEncoderModel, EveryCombinationAndDirectionPattern) {
  int checked = 0;
  for (uint8_t active = 1; active < 64; ++active) {
    for (uint8_t forward : subsets(active)) {
      expect_matches_model(active, forward, 0);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 728);  // 3^6 − 1: each signal absent, reverse or forward; not all absent
}

TEST(FrameEncoderModel, EveryCombinationWithEveryPriority) {
  for (uint8_t active = 1; active < 64; ++active) {
    for (uint8_t priority : subsets(active)) {
      expect_matches_model(active, 0x3F, priority);
      expect_matches_model(active, 0b010101, priority);
    }
  }
}

TEST(FrameEncoderModel, MaskBitsOutsideTheRequestAreIgnored) {
  for (uint8_t active = 1; active < 64; ++active) {
    const EncodedFrame plain = encode(active, active);
    const EncodedFrame noisy = encode(active | 0xC0, active | 0xC0 | 0x3F, 0xC0);
    EXPECT_EQ(noisy.words.step_bits, plain.words.step_bits) << names(active);
    EXPECT_EQ(noisy.words.dir_bits, plain.words.dir_bits) << names(active);
    EXPECT_EQ(noisy.sent_mask, plain.sent_mask) << names(active);
    EXPECT_EQ(noisy.carried_mask, plain.carried_mask) << names(active);
  }
}

TEST(FrameEncoderModel, CarriedCombinationsAreExactlyTheReferenceFive) {
  std::vector<std::string> carried_sets;
  for (uint8_t active = 1; active < 64; ++active) {
    const EncodedFrame frame = encode(active, 0);
    if (frame.carried_mask != 0) {
      carried_sets.push_back(names(active));
      EXPECT_EQ(frame.carried_mask, 0b100000) << names(active);
    }
    EXPECT_EQ(signals_fit(active), frame.carried_mask == 0) << names(active);
  }
  const std::vector<std::string> expected = {"XYRZE", "XYTZE", "XRTZE", "YRTZE", "XYRTZE"};
  EXPECT_EQ(carried_sets, expected);
}

TEST(FrameEncoderModel, PulsePositionsAndDirWindowsFollowTheRules) {
  // Reads the pulses back out of the words: widths in index order, 2 µs gaps, first at 2 µs,
  // and each forward DIR window exactly one µs wider on both sides.
  for (uint8_t active = 1; active < 64; ++active) {
    SCOPED_TRACE(names(active));
    const EncodedFrame frame = encode(active, 0x3F);
    const auto steps = high_runs(frame.words.step_bits);
    int expected_rise = 2;
    size_t index = 0;
    for (int signal = 0; signal < 6; ++signal) {
      if (!has(frame.sent_mask, signal)) continue;
      ASSERT_LT(index, steps.size());
      EXPECT_EQ(steps[index].first, expected_rise);
      EXPECT_EQ(steps[index].second - steps[index].first, kWidthUs[signal]);
      EXPECT_LE(steps[index].second, 31);
      expected_rise = steps[index].second + 2;
      ++index;
    }
    EXPECT_EQ(index, steps.size());
    // All forward: one DIR run from 1 µs before the first rise to 1 µs after the last fall.
    const auto dirs = high_runs(frame.words.dir_bits);
    ASSERT_EQ(dirs.size(), 1u);
    EXPECT_EQ(dirs[0].first, steps.front().first - 1);
    EXPECT_EQ(dirs[0].second, steps.back().second + 1);
  }
}

TEST(FrameEncoderCarry, CarriedSignalIsServedFirstInTheNextFrame) {
  // All six signals requested every frame; the carried one gets priority next frame.
  // Frame 1: E carried. Frame 2 (E first): Z carried. Frame 3 (Z first): E carried again.
  const uint8_t expected_carried[3] = {0b100000, 0b010000, 0b100000};
  uint8_t carried = 0;
  for (int frame_index = 0; frame_index < 3; ++frame_index) {
    const EncodedFrame frame = encode(0x3F, 0x3F, carried);
    EXPECT_EQ(frame.carried_mask, expected_carried[frame_index]) << "frame " << frame_index;
    EXPECT_EQ(frame.sent_mask & carried, carried) << "frame " << frame_index;
    carried = frame.carried_mask;
  }
}

TEST(FrameEncoderCarry, AnyCarriedSetThatFitsIsAlwaysSent) {
  for (uint8_t active = 1; active < 64; ++active) {
    for (uint8_t priority : subsets(active)) {
      if (!model_fits(priority)) continue;
      const EncodedFrame frame = encode(active, 0, priority);
      EXPECT_EQ(frame.sent_mask & priority, priority) << names(active) << "/" << names(priority);
    }
  }
}

TEST(FrameEncoderCarry, TwoCarriedSignalsCrowdOutLaterOnes) {
  // Z and E first (17 µs), then X (21), Y (26); R would need 32, T 33.
  const EncodedFrame frame = encode(0x3F, 0, 0b110000);
  EXPECT_EQ(frame.sent_mask, 0b110011);
  EXPECT_EQ(frame.carried_mask, 0b001100);
  // X[2,4) Y[6,9) Z[11,17) E[19,26)
  EXPECT_EQ(frame.words.step_bits, 0x03F9F9CCu);
  EXPECT_EQ(frame.words.dir_bits, 0u);
}

}  // namespace
}  // namespace stepdance::protocol
