// The NVIC's bookkeeping: priorities, grouping, masks, levels (DDI 0403E B1.5.4, B3.4).
#include "image/cpu/exception_state.hpp"

#include <gtest/gtest.h>

namespace stepdance::sim::image {
namespace {

constexpr unsigned irq(unsigned n) { return kFirstIrq + n; }

TEST(ExceptionState, TakesTheHighestPriorityThenTheLowestNumber) {
  ExceptionState state;
  for (unsigned n : {1u, 2u, 3u}) state.set_enabled(irq(n), true);
  state.set_priority(irq(1), 0x80);
  state.set_priority(irq(2), 0x40);
  state.set_priority(irq(3), 0x40);
  state.set_pending(irq(1), true);
  state.set_pending(irq(3), true);
  state.set_pending(irq(2), true);
  EXPECT_EQ(state.next_to_take(Masks{}), irq(2));
  state.activate(irq(2));
  EXPECT_EQ(state.next_to_take(Masks{}), 0u);  // 3 has the same priority: no preemption
  state.deactivate(irq(2));
  EXPECT_EQ(state.next_to_take(Masks{}), irq(3));
}

TEST(ExceptionState, SubpriorityDoesNotPreempt) {
  ExceptionState state;
  state.set_priority_group(6);  // group = bit 7 only
  state.set_enabled(irq(0), true);
  state.set_enabled(irq(1), true);
  state.set_priority(irq(0), 0x40);
  state.set_priority(irq(1), 0x00);
  state.set_pending(irq(0), true);
  state.activate(irq(0));
  state.set_pending(irq(1), true);
  EXPECT_EQ(state.next_to_take(Masks{}), 0u);  // 0x00 and 0x40 are both group 0
  state.set_priority_group(5);                 // group = bits [7:6]: now 0x00 < 0x40
  EXPECT_EQ(state.next_to_take(Masks{}), irq(1));
}

TEST(ExceptionState, MasksHoldOffByPriority) {
  ExceptionState state;
  state.set_enabled(irq(0), true);
  state.set_priority(irq(0), 0x40);
  state.set_pending(irq(0), true);
  EXPECT_EQ(state.next_to_take(Masks{true, false, 0}), 0u);      // PRIMASK
  EXPECT_EQ(state.next_to_take(Masks{false, false, 0x40}), 0u);  // BASEPRI 0x40 masks 0x40
  EXPECT_EQ(state.next_to_take(Masks{false, false, 0x50}), irq(0));
  state.set_pending(kHardFault, true);
  EXPECT_EQ(state.next_to_take(Masks{true, false, 0}), static_cast<unsigned>(kHardFault));
  EXPECT_EQ(state.next_to_take(Masks{false, true, 0}), 0u);  // FAULTMASK: not even HardFault
}

TEST(ExceptionState, AHighLevelPendsAgainAfterItsHandler) {
  ExceptionState state;
  state.set_enabled(irq(5), true);
  state.set_line(5, true);
  EXPECT_TRUE(state.pending(irq(5)));
  state.activate(irq(5));
  EXPECT_FALSE(state.pending(irq(5)));
  state.deactivate(irq(5));
  EXPECT_TRUE(state.pending(irq(5)));  // still high
  state.set_pending(irq(5), false);
  EXPECT_TRUE(state.pending(irq(5)));  // clearing a high line: pends again
  state.set_line(5, false);
  state.set_pending(irq(5), false);
  EXPECT_FALSE(state.pending(irq(5)));
}

TEST(ExceptionState, PrioritiesKeepFourBits) {
  ExceptionState state;
  state.set_priority(irq(9), 0xFF);
  EXPECT_EQ(state.priority(irq(9)), 0xF0);
  EXPECT_EQ(state.priority(kHardFault), -1);
  EXPECT_EQ(state.priority(kNmi), -2);
}

}  // namespace
}  // namespace stepdance::sim::image
