// The emulated host's timeline: attach, debounce, bus reset, recovery, then a tick per
// (micro)frame while enumeration or serial traffic moves (USB 2.0 §7.1.7, §8.4.3.1).
#include "image/usb/usb_host.hpp"

#include <cstdio>

#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image::usb {
namespace {

constexpr SimTime kMicroframeNs = 125 * kMicrosecond;
constexpr SimTime kFrameNs = kMillisecond;
constexpr SimTime kDetachedPollNs = 10 * kMillisecond;  // between looks at a port with no device
constexpr int kHighSpeedTransactions = 13;              // USB 2.0 table 5-10: 512-byte bulk, per microframe
constexpr int kFullSpeedTransactions = 19;              // USB 2.0 table 5-9: 64-byte bulk, per frame

}  // namespace

UsbHost::Tick::Tick(UsbHost& owner) : Event(&UsbHost::on_tick), host(owner) {}

UsbHost::UsbHost(ChipContext& chip, BoardIo& world, UsbDevicePort& device, HostOptions options)
    : chip_(chip), world_(world), device_(device), options_(options), tick_(*this) {}

UsbHost::~UsbHost() { chip_.scheduler().cancel(tick_); }

void UsbHost::start(SimTime start_ns) { chip_.scheduler().schedule(tick_, start_ns); }

void UsbHost::on_tick(Event& event, Scheduler&) { static_cast<Tick&>(event).host.run_tick(); }

SimTime UsbHost::period_ns() const { return record_.speed == BusSpeed::kHigh ? kMicroframeNs : kFrameNs; }

SimTime UsbHost::next_boundary(SimTime period) const {
  const SimTime now = chip_.now_ns();
  if (now < epoch_ns_) return epoch_ns_;
  return epoch_ns_ + ((now - epoch_ns_) / period + 1) * period;
}

void UsbHost::schedule_at(SimTime time_ns) { chip_.scheduler().schedule(tick_, time_ns); }

void UsbHost::wake() {
  if (phase_ == Phase::kFailed) return;
  SimTime target = chip_.now_ns();
  if (phase_ == Phase::kEnumerating || phase_ == Phase::kRunning) target = next_boundary(period_ns());
  if (phase_ == Phase::kDebounce || phase_ == Phase::kReset || phase_ == Phase::kRecovery) return;
  if (tick_.scheduled() && tick_.time() <= target) return;
  schedule_at(target);
  chip_.stop_cpu_run();  // the CPU's run must end by the new tick
}

void UsbHost::fail(const std::string& why) {
  char prefix[64];
  std::snprintf(prefix, sizeof prefix, "usb host at %.6f s: ", to_seconds(chip_.now_ns()));
  failure_ = prefix + why;
  phase_ = Phase::kFailed;
  chip_.scheduler().cancel(tick_);
  if (on_failure_) on_failure_(failure_);
}

void UsbHost::advance_phase() {
  const SimTime now = chip_.now_ns();
  switch (phase_) {
    case Phase::kDebounce:
      device_.bus_reset_begin();
      phase_ = Phase::kReset;
      phase_until_ns_ = now + options_.reset_ns;
      break;
    case Phase::kReset:
      record_.speed = device_.bus_reset_end();
      epoch_ns_ = now;
      phase_ = Phase::kRecovery;
      phase_until_ns_ = now + options_.reset_recovery_ns;
      break;
    default:
      phase_ = Phase::kEnumerating;
      phase_until_ns_ = now;
      step_ = 0;
      current_address_ = 0;
      max_packet0_ = 64;
      control_active_ = false;
      begin_next_request();
      break;
  }
  schedule_at(phase_ == Phase::kEnumerating ? now : phase_until_ns_);
}

void UsbHost::run_tick() {
  const SimTime now = chip_.now_ns();
  if (phase_ == Phase::kFailed) return;
  if (!device_.attached()) {
    if (phase_ != Phase::kDetached) control_active_ = false;
    phase_ = Phase::kDetached;
    schedule_at(now + kDetachedPollNs);
    return;
  }
  if (phase_ == Phase::kDetached) {
    record_ = HostRecord{};
    record_.attached_ns = now;
    phase_ = Phase::kDebounce;
    phase_until_ns_ = now + options_.attach_debounce_ns;
    schedule_at(phase_until_ns_);
    return;
  }
  if (phase_ == Phase::kDebounce || phase_ == Phase::kReset || phase_ == Phase::kRecovery) {
    advance_phase();
    return;
  }
  if (now < phase_until_ns_) {  // a recovery interval inside enumeration (SET_ADDRESS)
    schedule_at(phase_until_ns_);
    return;
  }
  int budget = record_.speed == BusSpeed::kHigh ? kHighSpeedTransactions : kFullSpeedTransactions;
  bool busy = send_line_state();
  busy = run_control(budget) || busy;
  if (phase_ == Phase::kFailed) return;
  if (phase_ == Phase::kRunning) busy = run_bulk(budget) || busy;
  if (now < phase_until_ns_) {
    schedule_at(phase_until_ns_);
  } else {
    schedule_at(next_boundary(busy ? period_ns() : kFrameNs));
  }
}

}  // namespace stepdance::sim::image::usb
