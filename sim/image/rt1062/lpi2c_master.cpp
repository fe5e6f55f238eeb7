// The LPI2C master's command engine: the transmit FIFO at the bus's pace, segments → whole
// BoardIo transfers, received bytes, and the status flags (RM §47.3 functional description).
#include <algorithm>

#include "image/rt1062/lpi2c.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image {
namespace {

// MTDR commands (RM §47.4.1.18): 0 transmit, 1 receive, 2 stop, 4 start + address.
constexpr uint32_t kTransmit = 0, kReceive = 1, kStop = 2, kStart = 4;
constexpr uint32_t kEpf = 1u << 8, kSdf = 1u << 9, kNdf = 1u << 10, kAlf = 1u << 11, kFef = 1u << 12;
constexpr uint32_t kPltf = 1u << 13;
constexpr uint32_t kMen = 1u << 0;
// BoardIo::i2c_transfer results (stepdance::hal::I2cResult).
constexpr int kOk = 2, kAddressNack = 3, kDataNack = 4, kTimeout = 6;

uint32_t command_of(uint16_t word) { return (word >> 8) & 7u; }

}  // namespace

SimTime Lpi2c::duration_ns(uint16_t word) const {
  const uint32_t hz = scl_hz();
  const SimTime bit_ns = hz == 0 ? 10000 : (kSecond + hz / 2) / hz;  // 100 kHz if unknown
  switch (command_of(word)) {
    case kStart: return 10 * bit_ns;  // START, 8 address bits, ACK
    case kReceive: return 9 * bit_ns * ((word & 0xFFu) + 1);
    case kStop: return bit_ns;
    default: return 9 * bit_ns;
  }
}

void Lpi2c::advance(SimTime now_ns) {
  while (step(now_ns)) {
  }
  if (mcr_ & kMen) execute_known_write(now_ns);  // a STOP or START just queued behind the data
}

bool Lpi2c::step(SimTime now_ns) {
  if (!(mcr_ & kMen) || halted_ || tx_.empty()) return false;
  const uint16_t word = tx_.front().word;
  if (!head_started_) {
    head_started_ = true;
    head_start_ns_ = std::max(line_free_ns_, tx_.front().queued_ns);
    if (head_start_ns_ > now_ns) {
      head_started_ = false;
      return false;
    }
    if (command_of(word) == kReceive) apply(word, head_start_ns_);  // the read runs as its bytes come
  }
  const SimTime done = head_start_ns_ + duration_ns(word);
  if (done > now_ns || halted_) return false;
  if (command_of(word) != kReceive) apply(word, done);
  if (halted_) return false;
  // A write segment whose last byte has gone out with nothing queued behind it: the master holds
  // the bus and the segment is complete as far as the world can tell (Wire's endTransmission(false)).
  const bool stalled = tx_.size() == 1 && segment_.open && !segment_.is_read && !segment_.executed &&
                       (command_of(word) == kTransmit || command_of(word) == kStart);
  if (stalled && execute(done, 0) == kAddressNack) return false;  // the last command stays queued
  tx_.pop_front();
  head_started_ = false;
  line_free_ns_ = done;
  execute_known_write(done);
  return !halted_;
}

void Lpi2c::execute_known_write(SimTime at_ns) {
  if (halted_ || !segment_.open || segment_.is_read || segment_.executed) return;
  // The bytes queued up to the segment's STOP or next START, if one is queued already.
  size_t queued = 0;
  while (queued < tx_.size() && command_of(tx_[queued].word) == kTransmit) ++queued;
  if (queued == tx_.size()) return;  // its end is not known yet
  for (size_t i = 0; i < queued; ++i) segment_.written.push_back(static_cast<uint8_t>(tx_[i].word & 0xFFu));
  const int result = execute(at_ns, 0);
  if (result == kOk) {
    segment_.prefetched = queued;
  } else if (result == kDataNack) {
    tx_.erase(tx_.begin(), tx_.begin() + static_cast<std::ptrdiff_t>(queued));  // the bytes went out
    head_started_ = false;
  }
}

void Lpi2c::apply(uint16_t word, SimTime at_ns) {
  const uint8_t data = static_cast<uint8_t>(word & 0xFFu);
  switch (command_of(word)) {
    case kStart:
      if (segment_.open && !segment_.executed && execute(at_ns, 0) != kOk) return;  // a repeated START
      if (segment_.open) flags_ |= kEpf;
      segment_ = Segment{true, false, static_cast<uint8_t>(data >> 1), (data & 1u) != 0, {}};
      bus_busy_ = true;
      break;
    case kTransmit:
      if (!segment_.open || segment_.is_read) {
        flags_ |= kFef;  // data without a START (RM §47.4.1.4 FEF)
        break;
      }
      if (segment_.prefetched > 0) {  // its byte already went with the transfer
        --segment_.prefetched;
        break;
      }
      if (segment_.executed) {  // more bytes after a stall: a further write to the same address
        segment_.executed = false;
        segment_.written.clear();
      }
      segment_.written.push_back(data);
      break;
    case kReceive:
      if (!segment_.open || !segment_.is_read || segment_.executed) {
        flags_ |= kFef;
        break;
      }
      execute(at_ns, static_cast<size_t>(data) + 1u);
      break;
    case kStop:
      if (segment_.open && !segment_.executed && execute(at_ns, 0) != kOk) return;
      segment_ = Segment{};
      bus_busy_ = false;
      flags_ |= kSdf | kEpf;
      break;
    default: break;  // refused when written
  }
}

int Lpi2c::execute(SimTime at_ns, size_t read_length) {
  uint8_t data[256] = {};
  SimTime wire_ns = 0;
  const uint8_t bus = instance_ == 1 ? 0 : 1;
  const int result = io_.i2c_transfer(at_ns, bus, scl_hz(), segment_.address, segment_.written.data(),
                                      segment_.written.size(), data, read_length, wire_ns);
  segment_.executed = true;
  chip_.stop_cpu_run();
  if (result == kOk) {
    const SimTime byte_ns = duration_ns(0);
    for (size_t i = 0; i < read_length; ++i) rx_.emplace_back(at_ns + byte_ns * static_cast<SimTime>(i + 1), data[i]);
    return result;
  }
  // A NACK or a broken bus: the master stops with the flag up (Wire clears the FIFO and sends STOP).
  flags_ |= result == kAddressNack || result == kDataNack ? kNdf : result == kTimeout ? kPltf : kAlf;
  halted_ = true;
  return result;
}

void Lpi2c::schedule_wake(SimTime now_ns) {
  if (!(mcr_ & kMen) || halted_ || tx_.empty()) {
    chip_.scheduler().cancel(wake_);
    return;
  }
  const SimTime start = head_started_ ? head_start_ns_ : std::max(line_free_ns_, tx_.front().queued_ns);
  const SimTime at = std::max(now_ns, start + (head_started_ ? duration_ns(tx_.front().word) : 0));
  if (!wake_.scheduled() || wake_.time() != at) chip_.scheduler().schedule(wake_, at);
}

}  // namespace stepdance::sim::image
