// A self-rescheduling timer for the frame, kilohertz and loop ticks: no allocation per tick.
#pragma once

#include "common/sim_time.hpp"
#include "kernel/scheduler/event.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim {

/// Fires every period_ns from a first time until stopped. The timer requeues itself before it
/// calls back, so the callback may stop it, restart it or change its period.
class PeriodicTimer : public Event {
 public:
  /// Called at each tick with the tick's time in ns.
  using Callback = void (*)(void* context, SimTime time);

  PeriodicTimer(Scheduler& scheduler, Callback callback, void* context)
      : Event(&fire), scheduler_(scheduler), callback_(callback), context_(context) {}
  ~PeriodicTimer() { stop(); }

  /// Starts (or restarts) ticking at `first_ns`, then every `period_ns` (> 0).
  void start(SimTime first_ns, SimTime period_ns) {
    period_ns_ = period_ns;
    scheduler_.schedule(*this, first_ns);
  }
  /// Stops ticking; a pending tick is withdrawn.
  void stop() { scheduler_.cancel(*this); }
  /// True while a tick is pending.
  bool running() const { return scheduled(); }
  /// Ticking period in ns.
  SimTime period_ns() const { return period_ns_; }

 private:
  static void fire(Event& event, Scheduler& scheduler) {
    auto& timer = static_cast<PeriodicTimer&>(event);
    const SimTime tick = timer.time();
    scheduler.schedule(timer, tick + timer.period_ns_);
    timer.callback_(timer.context_, tick);
  }

  Scheduler& scheduler_;
  Callback callback_;
  void* context_;
  SimTime period_ns_ = 1;
};

}  // namespace stepdance::sim
