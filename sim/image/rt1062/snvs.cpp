// SNVS real-time clocks (RM §20.3).
#include "image/rt1062/snvs.hpp"

#include "image/rt1062/register_bits.hpp"
#include "image/rt1062/tick_clock.hpp"

namespace stepdance::sim::image::rt1062 {
namespace {

// Offsets (RM §20.3.1): HPCR 0x08, HPSR 0x14, HPRTCMR 0x24, HPRTCLR 0x28, LPCR 0x38, LPSR 0x4C,
// LPSRTCMR 0x50, LPSRTCLR 0x54.
constexpr uint32_t kHpcr = 0x08, kHpsr = 0x14, kHpRtcMr = 0x24, kHpRtcLr = 0x28, kLpcr = 0x38, kLpsr = 0x4C,
                   kLpSrtcMr = 0x50, kLpSrtcLr = 0x54;
constexpr uint32_t kRtcEnable = 1u << 0, kHpTimeSync = 1u << 16, kSrtcEnable = 1u << 0;
constexpr uint64_t kMask47 = (uint64_t{1} << 47) - 1u;
constexpr uint32_t kRtcHz = 32768u;

}  // namespace

uint64_t Snvs::Counter::now(SimTime time_ns) const {
  if (!running) return value;
  return (value + TickClock(origin_ns, kRtcHz, 1).ticks_at(time_ns)) & kMask47;
}

void Snvs::Counter::set_running(bool run, SimTime time_ns) {
  value = now(time_ns);
  origin_ns = time_ns;
  running = run;
}

void Snvs::Counter::set(uint64_t count, SimTime time_ns) {
  value = count & kMask47;
  origin_ns = time_ns;
}

bool Snvs::read_word(uint32_t word, uint32_t& value) const {
  const SimTime now = context_.now_ns();
  switch (word) {
    case kHpcr: value = hpcr_; return true;
    case kHpsr: value = 0; return true;  // no alarms, no security violations
    case kHpRtcMr: value = static_cast<uint32_t>(hp_.now(now) >> 32); return true;
    case kHpRtcLr: value = static_cast<uint32_t>(hp_.now(now)); return true;
    case kLpcr: value = lpcr_; return true;
    case kLpsr: value = 0; return true;
    case kLpSrtcMr: value = static_cast<uint32_t>(srtc_.now(now) >> 32); return true;
    case kLpSrtcLr: value = static_cast<uint32_t>(srtc_.now(now)); return true;
    default: return false;
  }
}

Access Snvs::read(uint32_t offset, uint8_t bytes, uint32_t& value) {
  uint32_t word = 0;
  if (!read_word(offset & ~3u, word)) return Access::kUnmodelled;
  value = lane_read(word, offset, bytes);
  return Access::kOk;
}

bool Snvs::write_word(uint32_t word, uint32_t value) {
  const SimTime now = context_.now_ns();
  switch (word) {
    case kHpcr:
      hpcr_ = value & ~kHpTimeSync;
      if (value & kHpTimeSync) hp_.set(srtc_.now(now), now);
      hp_.set_running(hpcr_ & kRtcEnable, now);
      return true;
    case kLpcr:
      lpcr_ = value;
      srtc_.set_running(lpcr_ & kSrtcEnable, now);
      return true;
    case kHpsr:
    case kLpsr: return true;  // write-1-to-clear flags that never set
    case kHpRtcMr: hp_.set((hp_.now(now) & 0xFFFFFFFFu) | (uint64_t{value & 0x7FFFu} << 32), now); return true;
    case kHpRtcLr: hp_.set((hp_.now(now) & ~uint64_t{0xFFFFFFFFu}) | value, now); return true;
    case kLpSrtcMr: srtc_.set((srtc_.now(now) & 0xFFFFFFFFu) | (uint64_t{value & 0x7FFFu} << 32), now); return true;
    case kLpSrtcLr: srtc_.set((srtc_.now(now) & ~uint64_t{0xFFFFFFFFu}) | value, now); return true;
    default: return false;
  }
}

Access Snvs::write(uint32_t offset, uint8_t bytes, uint32_t value) {
  const uint32_t word = offset & ~3u;
  uint32_t current = 0;
  if (!read_word(word, current)) return Access::kUnmodelled;
  write_word(word, lane_merge(current, offset, bytes, value));
  return Access::kOk;
}

}  // namespace stepdance::sim::image::rt1062
