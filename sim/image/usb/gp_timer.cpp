// The USB controller's general-purpose timers (RM ch. 42, USB_nGPTIMERnCTRL): count down once
// per µs from GPTLD; the period is GPTLD + 1 µs ("load 999 for one millisecond").
#include "image/usb/gp_timer.hpp"

#include "image/usb/usb_registers.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image::usb {

GpTimer::Expiry::Expiry(GpTimer& owner) : Event(&GpTimer::on_expiry), timer(owner) {}

GpTimer::GpTimer(ChipContext& chip, void (*expired)(void*), void* context)
    : chip_(chip), expired_(expired), context_(context), expiry_(*this) {}

GpTimer::~GpTimer() { chip_.scheduler().cancel(expiry_); }

uint32_t GpTimer::count_now() const {
  if (!running_) return stopped_count_;
  const SimTime left_ns = zero_at_ns_ - chip_.now_ns();
  if (left_ns <= 0) return 0;
  // The count shows whole µs left before the expiry, minus the final µs it spends at 0.
  const SimTime left_us = (left_ns + kMicrosecond - 1) / kMicrosecond;
  return static_cast<uint32_t>(left_us - 1);
}

uint32_t GpTimer::read_control() const {
  return (running_ ? kGptRun : 0u) | (repeat_ ? kGptRepeat : 0u) | (count_now() & kGptCountMask);
}

void GpTimer::schedule_from(uint32_t count) {
  zero_at_ns_ = chip_.now_ns() + static_cast<SimTime>(count + 1) * kMicrosecond;
  chip_.scheduler().schedule(expiry_, zero_at_ns_);
}

void GpTimer::write_control(uint32_t value) {
  const uint32_t count = count_now();
  repeat_ = (value & kGptRepeat) != 0;
  const bool run = (value & kGptRun) != 0;
  const uint32_t start = (value & kGptReset) ? load_ : count;
  if (run) {
    running_ = true;
    schedule_from(start);
  } else {
    chip_.scheduler().cancel(expiry_);
    running_ = false;
    stopped_count_ = start;
  }
}

void GpTimer::reset() {
  chip_.scheduler().cancel(expiry_);
  running_ = repeat_ = false;
  load_ = stopped_count_ = 0;
}

void GpTimer::on_expiry(Event& event, Scheduler&) {
  GpTimer& timer = static_cast<Expiry&>(event).timer;
  if (timer.repeat_) {
    timer.schedule_from(timer.load_);
  } else {
    // One-shot: the count stays at 0 until software reloads it.
    timer.running_ = false;
    timer.stopped_count_ = 0;
  }
  timer.expired_(timer.context_);
}

}  // namespace stepdance::sim::image::usb
