// The chip's peripheral address space.
#include "image/chip/peripheral_bus.hpp"

#include <algorithm>
#include <cstdio>

namespace stepdance::sim::image {
namespace {

std::string hex32(uint32_t value) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%08X", value);
  return text;
}

bool refuse(BusRefusal& refusal, BusRefusal::Kind kind) {
  refusal.kind = kind;
  return false;
}

}  // namespace

std::string BusRefusal::describe() const {
  std::string where = hex32(address);
  if (!block.empty()) where += " (" + block + ")";
  const std::string access =
      std::string(is_write ? "write" : "read") + " of " + std::to_string(bytes) + " byte" + (bytes == 1 ? "" : "s");
  switch (kind) {
    case Kind::kNoBlock: return access + " at " + where + ": no peripheral is modelled at this address";
    case Kind::kUnmodelled: return access + " at " + where + ": this register is not modelled";
    case Kind::kGateOff:
      return access + " at " + where + ": its clock gate CCM_CCGR" + std::to_string(gate.ccgr) + " CG" +
             std::to_string(gate.field) + " is off (a bus error on the chip)";
    case Kind::kBusError: return access + " at " + where + ": the block answers with a bus error";
    case Kind::kNone: break;
  }
  return access + " at " + where;
}

bool PeripheralBus::add(Peripheral& block) {
  const uint64_t begin = block.base();
  const uint64_t end = begin + block.size_bytes();
  for (const Peripheral* other : blocks_) {
    const uint64_t other_begin = other->base();
    if (begin < other_begin + other->size_bytes() && other_begin < end) return false;
  }
  const auto at = std::upper_bound(blocks_.begin(), blocks_.end(), block.base(),
                                   [](uint32_t base, const Peripheral* p) { return base < p->base(); });
  blocks_.insert(at, &block);
  return true;
}

Peripheral* PeripheralBus::find(uint32_t address) const {
  auto after = std::upper_bound(blocks_.begin(), blocks_.end(), address,
                                [](uint32_t a, const Peripheral* p) { return a < p->base(); });
  if (after == blocks_.begin()) return nullptr;
  Peripheral* block = *(after - 1);
  return address - block->base() < block->size_bytes() ? block : nullptr;
}

// The block that may answer, or null with `refusal` filled (no block, or its gate is off).
Peripheral* PeripheralBus::admit(uint32_t address, bool is_write, uint8_t bytes, BusRefusal& refusal) const {
  refusal = BusRefusal{};
  refusal.address = address;
  refusal.is_write = is_write;
  refusal.bytes = bytes;
  Peripheral* block = find(address);
  if (block == nullptr) {
    refuse(refusal, BusRefusal::Kind::kNoBlock);
    return nullptr;
  }
  char offset[16];
  std::snprintf(offset, sizeof offset, "+0x%X", address - block->base());
  refusal.block = std::string(block->name()) + offset;
  const ClockGate gate = block->gate();
  if (gate.ccgr >= 0 && gate_on_ && !gate_on_(gate)) {
    refusal.gate = gate;
    refuse(refusal, BusRefusal::Kind::kGateOff);
    return nullptr;
  }
  return block;
}

bool PeripheralBus::read(uint32_t address, uint8_t bytes, uint32_t& value, BusRefusal& refusal) const {
  Peripheral* block = admit(address, false, bytes, refusal);
  if (block == nullptr) return false;
  value = 0;
  const Access result = block->read(address - block->base(), bytes, value);
  if (result == Access::kOk) return true;
  return refuse(refusal, result == Access::kUnmodelled ? BusRefusal::Kind::kUnmodelled : BusRefusal::Kind::kBusError);
}

bool PeripheralBus::write(uint32_t address, uint8_t bytes, uint32_t value, BusRefusal& refusal) const {
  Peripheral* block = admit(address, true, bytes, refusal);
  if (block == nullptr) return false;
  const Access result = block->write(address - block->base(), bytes, value);
  if (result == Access::kOk) return true;
  return refuse(refusal, result == Access::kUnmodelled ? BusRefusal::Kind::kUnmodelled : BusRefusal::Kind::kBusError);
}

}  // namespace stepdance::sim::image
