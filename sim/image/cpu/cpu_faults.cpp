// Faults and stalls: what stops the image, and the report (fault, PC, symbol, backtrace).
#include <unicorn/unicorn.h>

#include <cstdio>

#include "image/cpu/block_cache.hpp"
#include "image/cpu/image_chip.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image {
namespace {

// QEMU's exception numbers as unicorn passes them to the interrupt hook (target/arm/cpu.h).
constexpr uint32_t kExcpUdef = 1, kExcpSwi = 2, kExcpPrefetchAbort = 3, kExcpDataAbort = 4, kExcpBkpt = 7;
constexpr uint32_t kExcpExceptionExit = 8, kExcpNocp = 17, kExcpInvstate = 18, kExcpUnaligned = 22;

std::string hex(uint32_t value) {
  char text[16];
  std::snprintf(text, sizeof text, "0x%08X", value);
  return text;
}

}  // namespace

void ImageChip::on_interrupt(uc_struct*, uint32_t intno, void* user) {
  auto& chip = *static_cast<ImageChip*>(user);
  if (chip.calling_) {
    chip.call_went_wrong("raised exception " + std::to_string(intno));
    return;
  }
  const uint32_t pc = chip.read_register(UC_ARM_REG_PC);
  switch (intno) {
    case kExcpExceptionExit:
      chip.return_from_exception(pc | 1u);
      if (chip.stop_ == nullptr) chip.take_pending_exception();  // tail-chain
      break;
    case kExcpSwi:
      chip.pend_exception(kSvCall);
      chip.take_pending_exception();
      break;
    case kExcpUdef:
      chip.core_.cfsr |= 1u << 16;  // UFSR.UNDEFINSTR
      chip.fault(kUsageFault, "UsageFault: undefined instruction", pc);
      break;
    case kExcpNocp:
      chip.core_.cfsr |= 1u << 19;  // UFSR.NOCP
      chip.fault(kUsageFault, "UsageFault: a coprocessor (FPU) instruction with the coprocessor disabled", pc);
      break;
    case kExcpInvstate:
      chip.core_.cfsr |= 1u << 17;  // UFSR.INVSTATE
      chip.fault(kUsageFault, "UsageFault: invalid state (a branch to an ARM-state address)", pc);
      break;
    case kExcpUnaligned:
      chip.core_.cfsr |= 1u << 24;  // UFSR.UNALIGNED
      chip.fault(kUsageFault, "UsageFault: unaligned access", pc);
      break;
    case kExcpBkpt:
      chip.core_.hfsr |= 1u << 31;  // HFSR.DEBUGEVT: no debugger attached
      chip.raise_fault(ImageStop::Kind::kHardFault, "HardFault: breakpoint (BKPT) with no debugger", pc);
      break;
    case kExcpPrefetchAbort:
    case kExcpDataAbort: chip.fault(kBusFault, "BusFault: the emulator reported an abort", pc); break;
    default:
      chip.raise_fault(ImageStop::Kind::kHardFault,
                       "HardFault: exception " + std::to_string(intno) + " from the emulator", pc);
  }
  if (chip.stop_ != nullptr) {
    chip.we_stopped_ = true;
    uc_emu_stop(chip.uc_);
  }
}

// Unicorn 2.0.1 sends WFE and YIELD here too (QEMU's EXCP_YIELD), with the PC after them; an
// undefined instruction comes with the PC on it.
bool ImageChip::on_invalid_instruction(uc_struct* uc, void* user) {
  auto& chip = *static_cast<ImageChip*>(user);
  if (chip.calling_) {
    chip.call_went_wrong("ran an undefined instruction");
    return false;
  }
  const uint32_t pc = chip.read_register(UC_ARM_REG_PC);
  uint16_t before[2] = {0, 0};
  if (chip.read_memory(pc - 4, before, 4)) {
    const bool wfe = before[1] == 0xBF20 || (before[0] == 0xF3AF && before[1] == 0x8002);
    const bool yield = before[1] == 0xBF10 || (before[0] == 0xF3AF && before[1] == 0x8001);
    if (wfe || yield) {
      chip.yielded_ = yield;  // the run goes on at pc (YIELD) or sleeps first (WFE)
      return true;
    }
  }
  chip.core_.cfsr |= 1u << 16;  // UFSR.UNDEFINSTR
  chip.fault(kUsageFault, "UsageFault: undefined instruction", pc);
  chip.we_stopped_ = true;
  uc_emu_stop(uc);
  return true;
}

bool ImageChip::on_unmapped(uc_struct*, int type, uint64_t address, int size, int64_t, void* user) {
  auto& chip = *static_cast<ImageChip*>(user);
  const auto where = static_cast<uint32_t>(address);
  if (chip.calling_) {
    if (type == UC_MEM_FETCH_UNMAPPED) return chip.call_fetch(where);
    chip.call_went_wrong("accessed " + hex(where) + " outside its memory");
    return false;
  }
  if (type == UC_MEM_READ_PROT || type == UC_MEM_WRITE_PROT || type == UC_MEM_FETCH_PROT) {
    chip.protection_fault(type, where, size);
    return false;
  }
  const bool fetch = type == UC_MEM_FETCH_UNMAPPED;
  if (fetch) {
    chip.core_.cfsr |= 1u << 8;  // BFSR.IBUSERR
    chip.fault(kBusFault, "BusFault: instruction fetch from " + hex(where) + ", where no memory is", where);
    return false;
  }
  const bool write = type == UC_MEM_WRITE_UNMAPPED || type == UC_MEM_WRITE_PROT;
  const uint32_t pc = chip.note_access_position(where);
  const uint32_t sp = chip.read_register(UC_ARM_REG_SP);
  if (chip.stack_overflows(sp) && where < sp + 256 && where + 256 > sp) {
    chip.stack_fault(sp, pc);  // a push past the bottom into unmapped memory
    return false;
  }
  chip.core_.cfsr |= (1u << 9) | (1u << 15);  // BFSR.PRECISERR, BFARVALID
  chip.core_.bfar = where;
  const std::string access =
      std::string(write ? "write" : "read") + " of " + std::to_string(size) + " bytes at " + hex(where);
  chip.fault(kBusFault, "BusFault: " + access + ", where no memory is", pc);
  return false;
}

// A synchronous fault: taken as itself if enabled and above the execution priority, else
// escalated to HardFault (B1.5.10 "priority escalation"). Either way the run stops at the
// handler's entry: nothing the simulation can observe follows a fault.
void ImageChip::fault(unsigned exception, const std::string& what, uint32_t pc) {
  const Masks none{};
  const bool takeable =
      exceptions_.enabled(exception) && exceptions_.priority(exception) < exceptions_.execution_priority(none);
  ImageStop::Kind kind = exception == kUsageFault ? ImageStop::Kind::kUsageFault
                         : exception == kBusFault ? ImageStop::Kind::kBusFault
                                                  : ImageStop::Kind::kMemManage;
  if (takeable) {
    raise_fault(kind, what, pc);
    return;
  }
  core_.hfsr |= 1u << 30;  // HFSR.FORCED
  raise_fault(ImageStop::Kind::kHardFault, "HardFault (escalated: its handler is disabled or masked): " + what, pc);
}

void ImageChip::raise_fault(ImageStop::Kind kind, const std::string& what, uint32_t pc) {
  if (stop_ != nullptr) return;  // the first reason stands
  stop_ = std::make_unique<ImageStop>();
  stop_->kind = kind;
  stop_->what = what;
  stop_->pc = pc & ~1u;
  stop_->symbol = image_.symbols.function_name(stop_->pc);
  stop_->backtrace = backtrace(stop_->pc, read_register(UC_ARM_REG_LR), read_register(UC_ARM_REG_SP));
  stop_->exit_code = kind == ImageStop::Kind::kNoProgress ? kExitNoProgress : kExitCrash;
  // The access's time, or the block boundary reached (a fault inside a block: the block's end).
  stop_->time_ns = in_run_ ? time_of_cycle(in_access_ ? access_cycles_ : retired_) : scheduler_.now();
  end_run_ = true;
}

void ImageChip::finish_stop() {
  if (stopped_ || stop_ == nullptr) return;
  stopped_ = true;
  scheduler_.cancel(event_);
  for (auto& listener : stop_listeners_) listener(*stop_);
}

}  // namespace stepdance::sim::image
