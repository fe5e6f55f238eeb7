// SpscQueue: FIFO order, refusal when full, ring wrap-around, statistics, and a two-thread run.
#include <gtest/gtest.h>

#include <stdint.h>

#include <vector>
#ifndef STEPDANCE_TEST_NO_THREADS  // defined by bare-metal test builds, which have no std::thread
#include <thread>
#endif

#include "stepdance/core/spsc_queue.hpp"

namespace stepdance {
namespace {

template <typename Queue>
std::vector<int> drain(Queue& queue) {
  std::vector<int> out;
  int value = 0;
  while (queue.pop(value) == Status::kOk) out.push_back(value);
  return out;
}

template <typename Queue>
void push_all(Queue& queue, int first, int count) {
  for (int i = 0; i < count; ++i) ASSERT_EQ(queue.push(first + i), Status::kOk) << first + i;
}

TEST(SpscQueue, StartsEmpty) {
  SpscQueue<int, 8> queue;
  EXPECT_TRUE(queue.empty());
  EXPECT_FALSE(queue.full());
  EXPECT_EQ(queue.size(), 0u);
  EXPECT_EQ(queue.high_water(), 0u);
  EXPECT_EQ(queue.refused(), 0u);
  EXPECT_EQ((SpscQueue<int, 8>::capacity()), 8u);
}

TEST(SpscQueue, PopFromEmptyLeavesOutputUntouched) {
  SpscQueue<int, 4> queue;
  int out = 1234;
  EXPECT_EQ(queue.pop(out), Status::kEmpty);
  EXPECT_EQ(out, 1234);
}

TEST(SpscQueue, FirstInFirstOut) {
  SpscQueue<int, 8> queue;
  push_all(queue, 100, 5);
  EXPECT_EQ(queue.size(), 5u);
  EXPECT_EQ(drain(queue), (std::vector<int>{100, 101, 102, 103, 104}));
  EXPECT_TRUE(queue.empty());
}

TEST(SpscQueue, FullQueueRefusesAndKeepsEverything) {
  SpscQueue<int, 4> queue;
  push_all(queue, 1, 4);
  EXPECT_TRUE(queue.full());
  EXPECT_EQ(queue.push(5), Status::kFull);
  EXPECT_EQ(queue.push(6), Status::kFull);
  EXPECT_EQ(queue.refused(), 2u);
  EXPECT_EQ(queue.size(), 4u);
  EXPECT_EQ(drain(queue), (std::vector<int>{1, 2, 3, 4}));
}

TEST(SpscQueue, CapacityOne) {
  SpscQueue<int, 1> queue;
  EXPECT_EQ(queue.push(1), Status::kOk);
  EXPECT_EQ(queue.push(2), Status::kFull);
  int out = 0;
  EXPECT_EQ(queue.pop(out), Status::kOk);
  EXPECT_EQ(out, 1);
  EXPECT_EQ(queue.push(3), Status::kOk);
  EXPECT_EQ(queue.pop(out), Status::kOk);
  EXPECT_EQ(out, 3);
  EXPECT_EQ(queue.refused(), 1u);
  EXPECT_EQ(queue.high_water(), 1u);
}

TEST(SpscQueue, HighWaterIsTheDeepestFill) {
  SpscQueue<int, 8> queue;
  push_all(queue, 0, 3);  // depth 3
  int out = 0;
  ASSERT_EQ(queue.pop(out), Status::kOk);
  ASSERT_EQ(queue.pop(out), Status::kOk);  // depth 1
  push_all(queue, 3, 4);                   // depth 5
  EXPECT_EQ(queue.high_water(), 5u);
  drain(queue);
  push_all(queue, 7, 2);  // depth 2: the mark stays
  EXPECT_EQ(queue.high_water(), 5u);
  push_all(queue, 9, 6);  // depth 8, full
  EXPECT_EQ(queue.push(15), Status::kFull);
  EXPECT_EQ(queue.high_water(), 8u);  // a refused push does not raise it
  EXPECT_EQ(queue.refused(), 1u);
}

TEST(SpscQueue, WrapsAroundTheRingManyTimesInOrder) {
  // Batches of every size 1..8 starting at every ring phase; 1000 rounds wrap the ring ~560 times.
  SpscQueue<int, 8> queue;
  int next_in = 0;
  int next_out = 0;
  for (int round = 0; round < 1000; ++round) {
    const int batch = 1 + round % 8;
    push_all(queue, next_in, batch);
    next_in += batch;
    EXPECT_EQ(queue.size(), static_cast<size_t>(batch));
    for (int i = 0; i < batch; ++i) {
      int out = -1;
      ASSERT_EQ(queue.pop(out), Status::kOk);
      ASSERT_EQ(out, next_out++) << "round " << round;
    }
  }
  EXPECT_TRUE(queue.empty());
  EXPECT_EQ(next_out, next_in);
  EXPECT_EQ(queue.high_water(), 8u);
  EXPECT_EQ(queue.refused(), 0u);
}

TEST(SpscQueue, StaysFullAcrossEveryRingPhase) {
  // With the queue kept full, each slot index in turn is the one refused: power-of-two
  // indexing must keep head − tail == capacity at every phase.
  SpscQueue<int, 16> queue;
  push_all(queue, 0, 16);
  int next_out = 0;
  for (int step = 0; step < 16 * 50; ++step) {
    ASSERT_EQ(queue.push(-1), Status::kFull) << step;
    int out = -1;
    ASSERT_EQ(queue.pop(out), Status::kOk);
    ASSERT_EQ(out, next_out++);
    ASSERT_EQ(queue.push(next_out + 15), Status::kOk);
    ASSERT_TRUE(queue.full());
  }
  EXPECT_EQ(queue.refused(), 800u);
  EXPECT_EQ(queue.high_water(), 16u);
}

TEST(SpscQueue, HoldsStructs) {
  struct Move {
    double x_mm;
    int32_t steps;
  };
  SpscQueue<Move, 2> queue;
  EXPECT_EQ(queue.push({1.5, 3}), Status::kOk);
  EXPECT_EQ(queue.push({-2.25, -4}), Status::kOk);
  EXPECT_EQ(queue.push({0.0, 0}), Status::kFull);
  Move out{};
  ASSERT_EQ(queue.pop(out), Status::kOk);
  EXPECT_EQ(out.x_mm, 1.5);
  EXPECT_EQ(out.steps, 3);
  ASSERT_EQ(queue.pop(out), Status::kOk);
  EXPECT_EQ(out.x_mm, -2.25);
  EXPECT_EQ(out.steps, -4);
}

#ifndef STEPDANCE_TEST_NO_THREADS
TEST(SpscQueue, OneProducerThreadOneConsumerThread) {
  // The producer retries on kFull (back-pressure); the consumer must see 0..N-1 exactly once each.
  constexpr int kItems = 200000;
  SpscQueue<int, 64> queue;
  std::thread producer([&queue] {
    for (int i = 0; i < kItems; ++i) {
      while (queue.push(i) != Status::kOk) std::this_thread::yield();
    }
  });
  int expected = 0;
  bool in_order = true;
  while (expected < kItems) {
    int out = -1;
    if (queue.pop(out) != Status::kOk) {
      std::this_thread::yield();
      continue;
    }
    in_order = in_order && out == expected;
    ++expected;
  }
  producer.join();
  EXPECT_TRUE(in_order);
  EXPECT_TRUE(queue.empty());
  EXPECT_LE(queue.high_water(), 64u);
}
#endif  // STEPDANCE_TEST_NO_THREADS

}  // namespace
}  // namespace stepdance
