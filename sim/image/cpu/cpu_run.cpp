// Running the core as a scheduler event: instructions counted per translation block, runs cut
// at the next event, exceptions taken between blocks.
#include <unicorn/unicorn.h>

#include "image/cpu/block_cache.hpp"
#include "image/cpu/image_chip.hpp"
#include "image/cpu/system_blocks.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image {
namespace {

/// An address no code runs at: uc_emu_start's "until" (the emulator stops only when we say).
constexpr uint64_t kNoUntil = 0xFFFFFFFE;

}  // namespace

void ImageChip::install_hooks() {
  uc_hook hook;
  uc_hook_add(uc_, &hook, UC_HOOK_BLOCK, reinterpret_cast<void*>(&on_block), this, 1, 0);
  uc_hook_add(uc_, &hook, UC_HOOK_INTR, reinterpret_cast<void*>(&on_interrupt), this, 1, 0);
  uc_hook_add(uc_, &hook, UC_HOOK_INSN_INVALID, reinterpret_cast<void*>(&on_invalid_instruction), this, 1, 0);
  uc_hook_add(uc_, &hook, UC_HOOK_MEM_UNMAPPED | UC_HOOK_MEM_PROT, reinterpret_cast<void*>(&on_unmapped), this, 1, 0);
}

void ImageChip::CpuEvent::fire(Event& event, Scheduler&) { static_cast<CpuEvent&>(event).chip->run(); }

Masks ImageChip::masks() const {
  Masks masks;
  masks.primask = (read_register(UC_ARM_REG_PRIMASK) & 1) != 0;
  masks.faultmask = (read_register(UC_ARM_REG_FAULTMASK) & 1) != 0;
  masks.basepri = static_cast<uint8_t>(read_register(UC_ARM_REG_BASEPRI));
  return masks;
}

// One firing: run from now to the next queued event (or kMaxSliceNs), then requeue.
void ImageChip::run() {
  if (stopped_) return;
  const SimTime now = scheduler_.now();
  // Park this event at the slice's end first: while it fires it still heads the queue.
  scheduler_.schedule(event_, now + kMaxSliceNs);
  const uint64_t limit = cycles_at(scheduler_.next_time(now + kMaxSliceNs));
  end_run_ = false;
  run_limit_ = limit;
  while (!stopped_ && stop_ == nullptr && retired_ < run_limit_ && !end_run_) {
    if (mpu_applied_ != core_.mpu_generation) apply_mpu();
    recheck_ = false;
    take_pending_exception();
    if (stop_ != nullptr) break;
    if (step_block_ != nullptr) {
      step_through_block();
      continue;
    }
    run_slice();
  }
  if (stop_ != nullptr) finish_stop();
  if (stopped_) return;
  if (asleep_) {
    scheduler_.cancel(event_);  // pend_exception() wakes the core
    return;
  }
  const SimTime next = time_of_cycle(retired_);
  scheduler_.schedule(event_, next > now ? next : now);
}

// Runs the emulator until the block hook ends it (limit, a pend, a stop) or a fault does.
void ImageChip::run_slice() {
  in_run_ = true;
  we_stopped_ = false;
  yielded_ = false;
  const uint32_t pc = read_register(UC_ARM_REG_PC) | 1u;
  const uc_err error = uc_emu_start(uc_, pc, kNoUntil, 0, 0);
  restore_stopped_block_pc();
  in_run_ = false;
  block_ = nullptr;
  if (stop_ != nullptr || we_stopped_) return;
  if (error != UC_ERR_OK) {
    raise_fault(ImageStop::Kind::kHardFault, std::string("HardFault: the emulator stopped: ") + uc_strerror(error),
                read_register(UC_ARM_REG_PC));
    return;
  }
  if (!yielded_) sleep_until_interrupt();  // the emulator returned by itself: WFI or WFE
}

// WFI or WFE: the core sleeps until something pends an exception (it then wakes at that time;
// B1.5.19 lets a WFI wake for any reason, so a pend it would not take wakes it too). If no
// interrupt could ever wake it (one that would preempt with PRIMASK clear), that is no progress.
// Sleep cycles pass as time, not instructions.
void ImageChip::sleep_until_interrupt() {
  Masks wake = masks();
  wake.primask = false;
  if (!exceptions_.can_be_interrupted(wake, system_blocks_->systick().ticking()) && !exceptions_.any_pending()) {
    raise_fault(ImageStop::Kind::kNoProgress,
                "no progress: the core sleeps (WFI/WFE) with no interrupt enabled that could wake it",
                read_register(UC_ARM_REG_PC));
    return;
  }
  asleep_ = true;
  end_run_ = true;
}

void ImageChip::wake() {
  asleep_ = false;
  const uint64_t now = cycles_at(scheduler_.now());
  if (now > retired_) {
    slept_ += now - retired_;
    retired_ = now;
  }
  scheduler_.schedule(event_, scheduler_.now());
}

void ImageChip::on_block(uc_struct* uc, uint64_t address, uint32_t size, void* user) {
  auto& chip = *static_cast<ImageChip*>(user);
  if (chip.stepping_) return;  // counted one by one by step_through_block
  if (chip.calling_) {
    chip.call_instructions_ += chip.blocks_->get(static_cast<uint32_t>(address), size).instructions;
    if (chip.call_instructions_ > kMaxCallInstructions) chip.call_went_wrong("ran past its instruction budget");
    return;
  }
  for (Watch& watch : chip.watches_) {
    if (watch.address != address || watch.fired_at == chip.retired_) continue;
    watch.fired_at = chip.retired_;  // once per arrival, though a stop may make the block start twice
    watch.listener(chip.instructions(), chip.time_of_cycle(chip.retired_));
  }
  const ThumbBlock& block = chip.blocks_->get(static_cast<uint32_t>(address), size);
  if (chip.block_must_stop(block, static_cast<uint32_t>(address))) {
    chip.we_stopped_ = true;
    chip.block_stop_pc_ = static_cast<uint32_t>(address) | 1u;  // restore_stopped_block_pc()
    uc_emu_stop(uc);                                            // before the block runs: the PC stays at its start
    return;
  }
  chip.block_ = &block;
  chip.block_address_ = static_cast<uint32_t>(address);
  chip.access_cursor_ = 0;
  chip.block_start_ = chip.retired_;
  chip.retired_ += block.instructions;
  chip.handler_costs_[chip.current_exception_].instructions += block.instructions;
}

// True if the run must end before `block`: the limit is reached, the run was ended, an exception
// has become takeable, or the block is a spin nothing can interrupt (a stop).
bool ImageChip::block_must_stop(const ThumbBlock& block, uint32_t address) {
  if (stop_ != nullptr || end_run_ || retired_ >= run_limit_ || mpu_applied_ != core_.mpu_generation) return true;
  if (check_sp_ && stack_pointer_overflowed(address)) return true;
  check_sp_ = block.lowers_sp;
  if (recheck_ || check_masks_) {
    recheck_ = false;
    if (exceptions_.any_pending() && exceptions_.next_to_take(masks()) != 0) return true;
  }
  if (block.branches_to_itself) return spin(address);
  if (!block.divides.empty() && (core_.ccr & CoreRegisters::kCcrDiv0Trp) != 0) {
    step_block_ = &block;  // run it one instruction at a time to check each divisor
    step_address_ = address;
    return true;
  }
  return false;
}

// CCR.DIV_0_TRP with a divide in the block: the emulator does not trap a divide by zero, so the
// block runs one instruction at a time and each divide's divisor is read before it runs.
void ImageChip::step_through_block() {
  const ThumbBlock& block = *step_block_;
  const uint32_t start = step_address_;
  step_block_ = nullptr;
  stepping_ = true;
  // The cached translation has no per-instruction stop: drop it so the step count applies.
  uc_ctl_remove_cache(uc_, start, start + block.bytes);
  for (uint32_t n = 0; n < block.instructions && stop_ == nullptr; ++n) {
    const uint32_t pc = read_register(UC_ARM_REG_PC);
    if (pc < start || pc - start >= 0x10000) break;  // left the block (a branch, an exception)
    for (const BlockDivide& divide : block.divides) {
      if (pc - start != divide.offset || read_register(UC_ARM_REG_R0 + divide.rm) != 0) continue;
      core_.cfsr |= 1u << 25;  // UFSR.DIVBYZERO
      fault(kUsageFault, "UsageFault: divide by zero (CCR.DIV_0_TRP is set)", pc);
    }
    if (stop_ != nullptr) break;
    block_address_ = pc;  // a register access or fault in this step is at pc
    in_run_ = true;
    uc_emu_start(uc_, pc | 1u, kNoUntil, 0, 1);
    in_run_ = false;
    ++retired_;
    handler_costs_[current_exception_].instructions += 1;
  }
  stepping_ = false;
}

// A branch to itself: if some interrupt can still come, the core idles to the run's limit (the
// loop does nothing else); if none can, no progress.
bool ImageChip::spin(uint32_t address) {
  if (!exceptions_.can_be_interrupted(masks(), system_blocks_->systick().ticking())) {
    block_address_ = address;
    raise_fault(ImageStop::Kind::kNoProgress,
                "no progress: the core branches to itself with no interrupt enabled and unmasked that could leave it",
                address);
    return true;
  }
  if (retired_ < run_limit_) {
    handler_costs_[current_exception_].instructions += run_limit_ - retired_;
    retired_ = run_limit_;
  }
  return true;
}

void ImageChip::restore_stopped_block_pc() {
  if (block_stop_pc_ != 0) uc_reg_write(uc_, UC_ARM_REG_PC, &block_stop_pc_);
  block_stop_pc_ = 0;
}

}  // namespace stepdance::sim::image
