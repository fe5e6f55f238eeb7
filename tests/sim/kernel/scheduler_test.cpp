// The discrete-event kernel: (time, sequence) order, periodic timers, pooled one-shots, nesting.
#include <gtest/gtest.h>

#include <random>
#include <set>
#include <tuple>
#include <vector>

#include "kernel/scheduler/one_shot_pool.hpp"
#include "kernel/scheduler/periodic_timer.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim {
namespace {

// The id of the model's earliest event, or −1.
int first_of(const std::set<std::tuple<SimTime, uint64_t, int>>& model) {
  return model.empty() ? -1 : std::get<2>(*model.begin());
}

struct Recorder {
  std::vector<std::pair<SimTime, int>> seen;
};

struct Tagged : Event {
  Tagged(Recorder& into, int value) : Event(&fire), recorder(into), tag(value) {}
  static void fire(Event& event, Scheduler& scheduler) {
    auto& self = static_cast<Tagged&>(event);
    self.recorder.seen.emplace_back(scheduler.now(), self.tag);
  }
  Recorder& recorder;
  int tag;
};

TEST(SchedulerTest, RunsEventsInTimeThenInsertionOrder) {
  Scheduler scheduler;
  Recorder recorder;
  Tagged a(recorder, 1), b(recorder, 2), c(recorder, 3), d(recorder, 4);
  scheduler.schedule(a, 30);
  scheduler.schedule(b, 10);
  scheduler.schedule(c, 30);
  scheduler.schedule(d, 20);
  scheduler.run_until(100);
  const std::vector<std::pair<SimTime, int>> expected{{10, 2}, {20, 4}, {30, 1}, {30, 3}};
  EXPECT_EQ(recorder.seen, expected);
  EXPECT_EQ(scheduler.now(), 100);
}

TEST(SchedulerTest, RescheduleMovesAndCancelRemoves) {
  Scheduler scheduler;
  Recorder recorder;
  Tagged a(recorder, 1), b(recorder, 2), c(recorder, 3);
  scheduler.schedule(a, 10);
  scheduler.schedule(b, 20);
  scheduler.schedule(c, 30);
  scheduler.schedule(a, 40);
  scheduler.cancel(b);
  EXPECT_FALSE(b.scheduled());
  scheduler.run_until(35);
  EXPECT_EQ(recorder.seen, (std::vector<std::pair<SimTime, int>>{{30, 3}}));
  EXPECT_EQ(scheduler.pending(), 1u);
  scheduler.run_until(40);
  EXPECT_EQ(recorder.seen.back(), (std::pair<SimTime, int>{40, 1}));
}

TEST(SchedulerTest, PastTimesAreRaisedToNow) {
  Scheduler scheduler;
  Recorder recorder;
  Tagged a(recorder, 1);
  scheduler.run_until(50);
  scheduler.schedule(a, 10);
  EXPECT_EQ(a.time(), 50);
}

TEST(PeriodicTimerTest, TicksAtEveryPeriodUntilStopped) {
  Scheduler scheduler;
  std::vector<SimTime> ticks;
  PeriodicTimer timer(
      scheduler, [](void* context, SimTime time) { static_cast<std::vector<SimTime>*>(context)->push_back(time); },
      &ticks);
  timer.start(5, 40);
  scheduler.run_until(125);
  EXPECT_EQ(ticks, (std::vector<SimTime>{5, 45, 85, 125}));
  timer.stop();
  scheduler.run_until(1000);
  EXPECT_EQ(ticks.size(), 4u);
}

TEST(OneShotPoolTest, DeliversPayloadsAndReusesEvents) {
  Scheduler scheduler;
  std::vector<std::pair<SimTime, int>> got;
  OneShotPool<int> pool(
      scheduler,
      [](void* context, SimTime time, const int& value) {
        static_cast<std::vector<std::pair<SimTime, int>>*>(context)->emplace_back(time, value);
      },
      &got);
  for (int round = 0; round < 3; ++round) {
    for (int i = 0; i < 300; ++i) pool.post(scheduler.now() + 1000 - i, i);
    scheduler.run_until(scheduler.now() + 2000);
  }
  ASSERT_EQ(got.size(), 900u);
  EXPECT_EQ(got.front().second, 299);  // the latest post was the earliest time
  EXPECT_EQ(pool.capacity(), 512u);    // two chunks, reused in rounds 2 and 3
}

TEST(SchedulerTest, NestedRunUntilHandlesEventsInsideAHandler) {
  Scheduler scheduler;
  Recorder recorder;
  Tagged inner(recorder, 2), after(recorder, 3);
  struct Waiter : Event {
    explicit Waiter(Recorder& r) : Event(&fire), recorder(r) {}
    static void fire(Event& event, Scheduler& scheduler) {
      auto& self = static_cast<Waiter&>(event);
      self.recorder.seen.emplace_back(scheduler.now(), 1);
      scheduler.run_until(scheduler.now() + 100);  // like delay(): the world moves on
      self.recorder.seen.emplace_back(scheduler.now(), 10);
    }
    Recorder& recorder;
  } waiter(recorder);
  scheduler.schedule(waiter, 10);
  scheduler.schedule(inner, 50);
  scheduler.schedule(after, 200);
  scheduler.run_until(300);
  const std::vector<std::pair<SimTime, int>> expected{{10, 1}, {50, 2}, {110, 10}, {200, 3}};
  EXPECT_EQ(recorder.seen, expected);
}

// The slots, their heap and the time index against the plainest model of the contract: an
// ordered set of (time, order of scheduling, event). 200,000 random schedules (150 distinct
// times, so many events share one; some in the past), cancels and steps, with handlers that
// reschedule themselves as the periodic timers do.
TEST(SchedulerTest, MatchesAnOrderedSetModelOverRandomOperations) {
  std::set<std::tuple<SimTime, uint64_t, int>> model;
  std::vector<std::set<std::tuple<SimTime, uint64_t, int>>::iterator> where;
  uint64_t order = 0;
  std::mt19937_64 random(20261128);
  std::vector<int> fired;
  struct Probe : Event {
    Probe() : Event(&fire) {}
    static void fire(Event& event, Scheduler& scheduler) {
      auto& self = static_cast<Probe&>(event);
      self.log->push_back(self.id);
      if (self.again_ns > 0) scheduler.schedule(self, scheduler.now() + self.again_ns);
    }
    int id = 0;
    SimTime again_ns = 0;
    std::vector<int>* log = nullptr;
  };
  constexpr int kEvents = 300;
  std::vector<Probe> probes(kEvents);
  Scheduler scheduler;  // after the probes: it lets go of them when it ends
  where.resize(kEvents);
  std::vector<bool> queued(kEvents, false);
  for (int i = 0; i < kEvents; ++i) {
    probes[i].id = i;
    probes[i].log = &fired;
    probes[i].again_ns = i % 7 == 0 ? 40 * (1 + i % 3) : 0;
  }
  auto model_schedule = [&](int id, SimTime time) {
    if (queued[id]) model.erase(where[id]);
    where[id] = model.emplace(std::max(time, scheduler.now()), order++, id).first;
    queued[id] = true;
  };
  for (int op = 0; op < 200000; ++op) {
    const int id = static_cast<int>(random() % kEvents);
    const unsigned kind = static_cast<unsigned>(random() % 10);
    if (kind < 6) {
      const SimTime time = scheduler.now() - 20 + static_cast<SimTime>(random() % 150) * 40;
      scheduler.schedule(probes[id], time);
      model_schedule(id, time);
    } else if (kind < 7) {
      scheduler.cancel(probes[id]);
      if (queued[id]) model.erase(where[id]);
      queued[id] = false;
    } else {
      const SimTime end = scheduler.now() + static_cast<SimTime>(random() % 60) * 40;
      const bool expected = !model.empty() && std::get<0>(*model.begin()) <= end;
      fired.clear();
      ASSERT_EQ(scheduler.step(end), expected) << "operation " << op;
      if (!expected) continue;
      const auto [time, unused, first] = *model.begin();
      model.erase(model.begin());
      queued[first] = false;
      ASSERT_EQ(fired, std::vector<int>{first}) << "operation " << op;
      ASSERT_EQ(scheduler.now(), time);
      if (probes[first].again_ns > 0) model_schedule(first, time + probes[first].again_ns);
    }
    ASSERT_EQ(scheduler.pending(), model.size()) << "operation " << op;
    for (int probe : {id, first_of(model)}) {
      if (probe < 0) continue;
      ASSERT_EQ(probes[probe].scheduled(), queued[probe]) << "operation " << op;
    }
    ASSERT_EQ(scheduler.next_time(-1), model.empty() ? -1 : std::get<0>(*model.begin()));
  }
}

}  // namespace
}  // namespace stepdance::sim
