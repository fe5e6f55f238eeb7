// QwiicTwistModel: the hand's events applied in time order before each transfer.
#include "models/qwiic_twist_model.hpp"

#include <algorithm>
#include <cstdlib>

namespace stepdance::sim {
namespace {

constexpr uint8_t kStatus = 0x01, kEnable = 0x04, kCount = 0x05, kDifference = 0x07;
constexpr uint8_t kSinceMovement = 0x09, kSinceButton = 0x0B;
constexpr uint8_t kMoved = 1u << 0, kHeld = 1u << 1, kClicked = 1u << 2;

uint16_t saturated_ms(SimTime elapsed) {
  const SimTime ms = elapsed / kMillisecond;
  return static_cast<uint16_t>(std::clamp<SimTime>(ms, 0, 0xFFFF));
}

}  // namespace

QwiicTwistModel::QwiicTwistModel(uint8_t id) {
  registers_[0x00] = id;
  registers_[0x02] = 1;  // firmware 1.2
  registers_[0x03] = 2;
}

void QwiicTwistModel::turn(SimTime time, int64_t detents, SimTime over) {
  const int64_t steps = std::llabs(detents);
  for (int64_t i = 0; i < steps; ++i) {
    // Detent i+1 of n lands at time + over × (i+1) / n.
    const SimTime at = time + (steps == 0 ? 0 : over * (i + 1) / steps);
    events_.emplace(at, detents > 0 ? Event::kDetentForward : Event::kDetentBack);
  }
}

void QwiicTwistModel::press(SimTime time) { events_.emplace(time, Event::kPress); }
void QwiicTwistModel::release(SimTime time) { events_.emplace(time, Event::kRelease); }
void QwiicTwistModel::click(SimTime time, SimTime hold) {
  press(time);
  release(time + hold);
}

void QwiicTwistModel::apply(SimTime time, Event event) {
  switch (event) {
    case Event::kDetentForward:
    case Event::kDetentBack: {
      const int16_t step = event == Event::kDetentForward ? 1 : -1;
      set16(kCount, static_cast<uint16_t>(static_cast<int16_t>(get16(kCount)) + step));
      set16(kDifference, static_cast<uint16_t>(static_cast<int16_t>(get16(kDifference)) + step));
      registers_[kStatus] |= kMoved;
      last_movement_ = time;
      break;
    }
    case Event::kPress:
      registers_[kStatus] |= kHeld;
      last_button_ = time;
      break;
    case Event::kRelease:
      registers_[kStatus] = static_cast<uint8_t>((registers_[kStatus] & ~kHeld) | kClicked);
      last_button_ = time;
      break;
  }
}

void QwiicTwistModel::advance_to(SimTime time) {
  while (!events_.empty() && events_.begin()->first <= time) {
    apply(events_.begin()->first, events_.begin()->second);
    events_.erase(events_.begin());
  }
  refresh_timers(time);
}

void QwiicTwistModel::refresh_timers(SimTime time) {
  set16(kSinceMovement, saturated_ms(time - last_movement_));
  set16(kSinceButton, saturated_ms(time - last_button_));
}

bool QwiicTwistModel::write(SimTime time, const uint8_t* data, size_t length) {
  advance_to(time);
  ++writes_;
  if (length == 0) return true;
  uint8_t address = data[0];
  for (size_t i = 1; i < length; ++i, ++address) {
    if (address >= registers_.size()) return false;                       // past the map: refused
    if (address == 0x00 || address == 0x02 || address == 0x03) continue;  // ID and version are read only
    // Status: a write replaces moved and clicked; held is read only (SparkFun firmware 1.x).
    registers_[address] = address != kStatus
                              ? data[i]
                              : static_cast<uint8_t>((registers_[kStatus] & kHeld) | (data[i] & (kMoved | kClicked)));
    // Clearing a timer restarts it from now.
    if (address == kSinceMovement || address == kSinceMovement + 1) last_movement_ = time;
    if (address == kSinceButton || address == kSinceButton + 1) last_button_ = time;
  }
  // The pointer stays where the write left it, for a read that follows.
  registers_pointer_ = data[0];
  return true;
}

void QwiicTwistModel::read(SimTime time, uint8_t* data, size_t length) {
  advance_to(time);
  ++reads_;
  uint8_t address = registers_pointer_;
  for (size_t i = 0; i < length; ++i, ++address) data[i] = address < registers_.size() ? registers_[address] : 0xFF;
}

int16_t QwiicTwistModel::count_at(SimTime time) {
  advance_to(time);
  return static_cast<int16_t>(get16(kCount));
}

bool QwiicTwistModel::interrupt_active() const {
  const uint8_t enabled = registers_[kEnable];
  const uint8_t status = registers_[kStatus];
  return ((enabled & 0x01) && (status & kMoved)) || ((enabled & 0x02) && (status & kClicked));
}

void QwiicTwistModel::set16(uint8_t address, uint16_t value) {
  registers_[address] = static_cast<uint8_t>(value & 0xFF);
  registers_[address + 1] = static_cast<uint8_t>(value >> 8);
}

uint16_t QwiicTwistModel::get16(uint8_t address) const {
  return static_cast<uint16_t>(registers_[address] | (registers_[address + 1] << 8));
}

}  // namespace stepdance::sim
