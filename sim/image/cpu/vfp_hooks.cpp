// Double-precision FPU instructions on an emulator without a double-precision unit.
//
// Debian's unicorn 2.0.1 models the Cortex-M7's FPU as single precision only: a double-precision
// data-processing instruction is undefined to it. The first time one is reached (the emulator
// reports an invalid instruction with the PC on it), it is executed here (vfp_double.cpp),
// ITSTATE is advanced if it sits in an IT block (written through CPSR, which the emulator
// honours), and the PC moves past it; that ends the run (an emulator restart, ~30 µs). Before
// the next run the site becomes NOP.W in the emulator's memory with a code hook of its own that
// executes the double-precision operation: from then on the block runs straight through
// (~0.3 µs per operation, docs/simulator.md).
//
// Counting: the first time, the undefined instruction ends its translation block and the block
// hook counted it with the block; afterwards it is a NOP.W inside its block. Each run of the
// instruction is counted once.
//
// IT blocks: the emulator skips a conditional instruction whose condition fails before calling
// its code hook or reaching the undefined instruction, so reaching either means the condition
// passed; the NOP.W then advances ITSTATE as any instruction does.
//
// With any code hook installed, unicorn no longer puts the PC back at the start of a block the
// block hook stopped the run before (restore_stopped_block_pc() does).
#include <unicorn/unicorn.h>

#include "image/cpu/image_chip.hpp"
#include "image/cpu/vfp_double.hpp"

namespace stepdance::sim::image {
namespace {

constexpr uint32_t kControlNpriv = 1u << 0, kControlFpca = 1u << 2;
/// Whether sites get code hooks after their first run (fast) or take the invalid-instruction
/// path every time (about 30 µs each). The fault the hooks once caused in Step-A-Sketch's image
/// (a block of micros() restarted after its push) was the stale PC restore_stopped_block_pc()
/// fixes.
constexpr bool kHookDoubleSites = true;
constexpr uint32_t kFpccrAspen = 1u << 31;
/// ITSTATE in xPSR/CPSR: IT[1:0] at bits 26:25, IT[7:2] at bits 15:10 (ARMv7-M ARM B1.4.2).
constexpr uint32_t kItMask = (3u << 25) | (0x3Fu << 10);

uint32_t it_state(uint32_t psr) { return ((psr >> 8) & 0xFC) | ((psr >> 25) & 3); }
uint32_t with_it_state(uint32_t psr, uint32_t it) { return (psr & ~kItMask) | ((it & 0xFC) << 8) | ((it & 3) << 25); }

}  // namespace

bool ImageChip::emulate_double_at_fault(uint32_t pc) {
  uint16_t halves[2];
  if (!read_memory(pc & ~1u, halves, sizeof halves)) return false;
  const uint32_t instruction = uint32_t{halves[0]} << 16 | halves[1];
  if (!is_vfp_double_data_op(instruction)) return false;
  const VfpOperands operands = vfp_operands(instruction);
  const DoubleSite site{this, pc & ~1u, instruction, operands.reads, operands.writes, vfp_reads_apsr(instruction)};
  if (!execute_double(site)) return true;  // a NOCP fault: the run stops on it
  ++double_ops_.slow;
  if ((read_register(UC_ARM_REG_XPSR) & kItMask) != 0) advance_it_state();
  if (kHookDoubleSites) new_double_sites_.push_back(site);
  uint32_t next = (site.address + 4) | 1u;
  uc_reg_write(uc_, UC_ARM_REG_PC, &next);
  return true;
}

// ITAdvance (ARMv7-M ARM A7.3.2): the last instruction of the block clears ITSTATE, any other
// shifts IT[4:0] left.
void ImageChip::advance_it_state() {
  uint32_t cpsr = read_register(UC_ARM_REG_CPSR);
  const uint32_t it = it_state(cpsr);
  const uint32_t next = (it & 7) == 0 ? 0 : (it & 0xE0) | ((it << 1) & 0x1F);
  cpsr = with_it_state(cpsr, next);
  uc_reg_write(uc_, UC_ARM_REG_CPSR, &cpsr);
}

// The site's instruction becomes NOP.W (ARMv7-M A7.7.88, T2: 0xF3AF 0x8000) in the emulator's
// memory and its code hook executes the double-precision operation just before it: the block
// runs on without leaving the emulator, and the CPU advances the PC and ITSTATE itself, inside
// an IT block too. (A hook that writes PC = address + 4 instead ends the block at every site and
// sends the emulator round its loop; the restarted block once blamed on it was the stale PC that
// restore_stopped_block_pc() fixes.)
void ImageChip::hook_double_site(const DoubleSite& site) {
  double_sites_.push_back(site);
  uc_hook hook;
  uc_hook_add(uc_, &hook, UC_HOOK_CODE, reinterpret_cast<void*>(&on_double_site), &double_sites_.back(),
              site.address, site.address);
  const uint16_t nop_w[2] = {0xF3AF, 0x8000};
  uc_mem_write(uc_, site.address, nop_w, sizeof nop_w);
  uc_ctl_remove_cache(uc_, site.address, site.address + 4);
  ++double_ops_.sites;
}

void ImageChip::install_double_sites() {
  for (const DoubleSite& site : new_double_sites_) {
    bool known = false;
    for (const DoubleSite& hooked : double_sites_) known = known || hooked.address == site.address;
    if (!known) hook_double_site(site);
  }
  new_double_sites_.clear();
}

void ImageChip::on_double_site(uc_struct* uc, uint64_t, uint32_t, void* user) {
  const DoubleSite& site = *static_cast<const DoubleSite*>(user);
  if (!site.chip->execute_double(site)) {
    site.chip->we_stopped_ = true;
    uc_emu_stop(uc);
  }
}

// Once any code hook exists, unicorn no longer puts the PC back to the start of a block that the
// block hook stopped before (qemu/accel/tcg/cpu-exec.c syncs it only without UC_HOOK_CODE): the
// PC would be wherever it was last synchronised (a hooked instruction, a register access), and
// the next run would repeat instructions already done. Put it there, as the run loop expects.
void ImageChip::restore_stopped_block_pc() {
  // Also after uc_emu_start with a count (step_through_block), which adds a code hook of its own.
  if (block_stop_pc_ != 0) uc_reg_write(uc_, UC_ARM_REG_PC, &block_stop_pc_);
  block_stop_pc_ = 0;
}

// Moves the instruction's D registers, FPSCR (and APSR for VSEL) out of the emulator, executes,
// and writes back what changed. Executing a floating-point instruction sets CONTROL.FPCA (with
// FPCCR.ASPEN) as the hardware does, so a following exception stacks the FP context. False
// after a NOCP UsageFault (CPACR denies CP10).
bool ImageChip::execute_double(const DoubleSite& site) {
  const uint32_t cp10 = (core_.cpacr >> 20) & 3;
  uint32_t control = read_register(UC_ARM_REG_CONTROL);
  const bool unprivileged = current_exception_ == 0 && (control & kControlNpriv) != 0;
  if (cp10 == 0 || (cp10 == 1 && unprivileged)) {
    core_.cfsr |= 1u << 19;  // UFSR.NOCP
    fault(kUsageFault, "UsageFault: a coprocessor (FPU) instruction with the coprocessor disabled", site.address);
    return false;
  }
  VfpRegisters regs;
  int ids[19];
  void* values[19];
  int count = 0;
  ids[count] = UC_ARM_REG_FPSCR, values[count++] = &regs.fpscr;
  if (site.apsr) ids[count] = UC_ARM_REG_APSR, values[count++] = &regs.apsr;
  const int first_d = count;
  for (int n = 0; n < 16; ++n) {
    if (((site.reads | site.writes) >> n) & 1) ids[count] = UC_ARM_REG_D0 + n, values[count++] = &regs.d[static_cast<size_t>(n)];
  }
  uc_reg_read_batch(uc_, ids, values, count);
  const uint32_t fpscr_before = regs.fpscr;
  execute_vfp_double(site.instruction, regs);
  int written = 0;
  for (int i = first_d; i < count; ++i) {
    if ((site.writes >> (ids[i] - UC_ARM_REG_D0)) & 1) ids[written] = ids[i], values[written++] = values[i];
  }
  if (regs.fpscr != fpscr_before) ids[written] = UC_ARM_REG_FPSCR, values[written++] = &regs.fpscr;
  if (written > 0) uc_reg_write_batch(uc_, ids, values, written);
  if ((control & kControlFpca) == 0 && (core_.fpccr & kFpccrAspen) != 0) {
    control |= kControlFpca;
    uc_reg_write(uc_, UC_ARM_REG_CONTROL, &control);
  }
  ++double_ops_.executed;
  return true;
}

}  // namespace stepdance::sim::image
