// The core's memory map (IMXRT1060RM rev 3, 2.2 table 2-1 "system memory map"; DDI 0403E B3.1):
// RAM and flash as emulator memory, the peripheral and system spaces as register callbacks.
#include <unicorn/unicorn.h>

#include <cstdio>

#include "kernel/scheduler/scheduler.hpp"

#include "image/cpu/block_cache.hpp"
#include "image/cpu/image_chip.hpp"

namespace stepdance::sim::image {
namespace {

struct Memory {
  uint32_t base;
  uint32_t size_bytes;
  const char* name;
};

constexpr uint32_t kFlashBase = 0x60000000;
constexpr Memory kRam[] = {
    {0x00000000, 512u << 10, "ITCM"},    // FlexRAM as ITCM, at most 512 KB (IMXRT1060RM 31.3)
    {0x20000000, 512u << 10, "DTCM"},    // FlexRAM as DTCM, at most 512 KB
    {0x20200000, 1024u << 10, "OCRAM"},  // OCRAM2 (512 KB) + FlexRAM as OCRAM (at most 512 KB)
};
constexpr uint32_t kPeripheralBase = 0x40000000;                         // AIPS-1..5 and the rest up to the flash
constexpr uint32_t kSystemBase = 0xE0000000, kSystemBytes = 0x00100000;  // the PPB

std::string hex(uint32_t value) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%08X", value);
  return text;
}

}  // namespace

void ImageChip::map_memory() {
  for (const Memory& ram : kRam) uc_mem_map(uc_, ram.base, ram.size_bytes, UC_PROT_ALL);
  uc_mem_map(uc_, kFlashBase, flash_bytes_, UC_PROT_READ | UC_PROT_EXEC);
  // NOR flash outside the image reads erased (0xFF), as on a board fresh from the loader: the
  // EEPROM emulation at the flash's end then finds no data.
  const std::vector<uint8_t> erased(flash_bytes_, 0xFF);
  uc_mem_write(uc_, kFlashBase, erased.data(), erased.size());
  windows_[0] = {this, kPeripheralBase, false};
  windows_[1] = {this, kFlashBase + flash_bytes_, false};
  windows_[2] = {this, kSystemBase, true};
  const uint32_t sizes[] = {kFlashBase - kPeripheralBase, 0x80000000u - (kFlashBase + flash_bytes_), kSystemBytes};
  for (size_t i = 0; i < windows_.size(); ++i) {
    uc_mmio_map(uc_, windows_[i].base, sizes[i], &mmio_read, &windows_[i], &mmio_write, &windows_[i]);
  }
}

std::vector<ImageChip::MemoryWindow> ImageChip::memories() const {
  std::vector<MemoryWindow> list;
  for (const Memory& ram : kRam) list.push_back({ram.base, ram.size_bytes, UC_PROT_ALL});
  list.push_back({kFlashBase, flash_bytes_, UC_PROT_READ | UC_PROT_EXEC});
  return list;
}

bool ImageChip::place_segment(const ElfSegment& segment, std::string& error) {
  const uint64_t begin = segment.physical_address;
  const uint64_t end = begin + segment.memory_bytes;
  if (begin >= kFlashBase && end <= uint64_t{kFlashBase} + flash_bytes_) return true;
  for (const Memory& ram : kRam) {
    if (begin >= ram.base && end <= uint64_t{ram.base} + ram.size_bytes) return true;
  }
  error = "a segment at " + hex(segment.physical_address) + " (" + std::to_string(segment.memory_bytes) +
          " bytes) lies outside the flash (" + std::to_string(flash_bytes_ >> 20) + " MB), ITCM, DTCM and OCRAM";
  return false;
}

bool ImageChip::in_memory(uint32_t address, size_t bytes) const {
  const uint64_t end = uint64_t{address} + bytes;
  if (address >= kFlashBase && end <= uint64_t{kFlashBase} + flash_bytes_) return true;
  for (const Memory& ram : kRam) {
    if (address >= ram.base && end <= uint64_t{ram.base} + ram.size_bytes) return true;
  }
  return false;
}

bool ImageChip::read_memory(uint32_t address, void* data, size_t bytes) {
  return in_memory(address, bytes) && uc_mem_read(uc_, address, data, bytes) == UC_ERR_OK;
}

bool ImageChip::write_memory(uint32_t address, const void* data, size_t bytes) {
  return in_memory(address, bytes) && uc_mem_write(uc_, address, data, bytes) == UC_ERR_OK;
}

uint64_t ImageChip::mmio_read(uc_struct*, uint64_t offset, unsigned size, void* user) {
  const auto& window = *static_cast<MmioWindow*>(user);
  uint32_t value = 0;
  window.chip->access(window.system, window.base + static_cast<uint32_t>(offset), size, false, value);
  return value;
}

void ImageChip::mmio_write(uc_struct*, uint64_t offset, unsigned size, uint64_t value, void* user) {
  const auto& window = *static_cast<MmioWindow*>(user);
  auto word = static_cast<uint32_t>(value);
  window.chip->access(window.system, window.base + static_cast<uint32_t>(offset), size, true, word);
}

// One register access from the running image, at its instruction's time. A refusal ends the run.
void ImageChip::access(bool system, uint32_t address, unsigned size, bool is_write, uint32_t& value) {
  if (stop_ != nullptr) return;  // the run is ending: the rest of its block touches nothing
  if (calling_) {                // a debugger's call reads memory only (cpu_call.cpp)
    call_went_wrong("accessed the register at " + hex(address));
    return;
  }
  const uint32_t pc = note_access_position(address);
  in_access_ = true;
  PeripheralBus& bus = system ? system_bus_ : bus_;
  BusRefusal refusal;
  const auto bytes = static_cast<uint8_t>(size);
  const bool done = is_write ? bus.write(address, bytes, value, refusal) : bus.read(address, bytes, value, refusal);
  in_access_ = false;
  shorten_run();
  if (done) return;
  value = 0;
  if (refusal.kind == BusRefusal::Kind::kGateOff || refusal.kind == BusRefusal::Kind::kBusError) {
    core_.cfsr |= (1u << 9) | (1u << 15);  // BFSR.PRECISERR, BFARVALID (B3.2.15)
    core_.bfar = address;
    raise_fault(ImageStop::Kind::kBusFault, "BusFault: " + refusal.describe(), pc);
    return;
  }
  raise_fault(ImageStop::Kind::kUnmodelledAccess, "unmodelled register: " + refusal.describe(), pc);
}

// A register access may have queued an event (a timer started): the run must not pass it.
void ImageChip::shorten_run() {
  const uint64_t limit = cycles_at(scheduler_.next_time(time_of_cycle(run_limit_)));
  if (limit < run_limit_) run_limit_ = limit;
}

// Could `access` make an access at `address`, with the registers as they are now? (The base
// register is written back after the access, so it still holds the instruction's own value.)
bool ImageChip::could_access(const BlockAccess& access, uint32_t address) const {
  const uint32_t base = read_register(UC_ARM_REG_R0 + access.base);
  switch (access.mode) {
    case AddressMode::kOffset: return address - base == static_cast<uint32_t>(access.displacement);
    case AddressMode::kBase: return address == base;
    case AddressMode::kRegister: return address == base + (read_register(UC_ARM_REG_R0 + access.rm) << access.shift);
    case AddressMode::kRange: return address - (base + static_cast<uint32_t>(access.displacement)) < access.span;
    case AddressMode::kAny: return true;
  }
  return true;
}

// Which instruction of the running block makes this register access: the first load or store
// through a general register, from the one after the previous access's, whose address (worked
// out from the registers now) is this one; else the first candidate. Sets the access's cycle
// count and returns the instruction's address. (Exact unless an earlier load or store of the same
// block, recomputed with today's registers, also gives this address.)
uint32_t ImageChip::note_access_position(uint32_t address) {
  access_cycles_ = retired_;
  if (block_ == nullptr) return block_address_;
  const std::vector<BlockAccess>& list = block_->accesses;
  if (list.empty() || access_cursor_ >= list.size()) {
    access_cycles_ = list.empty() ? block_start_ : block_start_ + list.back().index;
    return block_address_ + (list.empty() ? 0 : list.back().offset);
  }
  size_t at = access_cursor_;
  for (size_t i = access_cursor_; i < list.size(); ++i) {
    if (could_access(list[i], address)) {
      at = i;
      break;
    }
  }
  access_cursor_ = list[at].multiple ? at : at + 1;
  access_cycles_ = block_start_ + list[at].index;
  return block_address_ + list[at].offset;
}

}  // namespace stepdance::sim::image
