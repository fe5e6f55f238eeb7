// Exception entry and return, done here rather than by the emulator (unicorn has no NVIC: it
// hands every exception to a hook). DDI 0403E B1.5.6 "exception entry behavior", B1.5.7
// "stack alignment on exception entry", B1.5.8 "exception return behavior".
//
// FPU: a frame is extended (S0-S15, FPSCR) when CONTROL.FPCA is set, as with FPCCR.ASPEN (reset
// value). The registers are saved at entry rather than lazily (the memory the firmware sees is
// the same once the handler touches the FPU; time is in instructions, so no cycle difference).
#include <unicorn/unicorn.h>

#include <array>
#include <cstdio>

#include "image/cpu/image_chip.hpp"

namespace stepdance::sim::image {
namespace {

constexpr uint32_t kControlSpsel = 1u << 1, kControlFpca = 1u << 2;
constexpr uint32_t kXpsrAlign = 1u << 9;  // stacked xPSR bit 9: the frame was realigned
constexpr uint32_t kThumb = 1u << 24;
constexpr size_t kBasicWords = 8, kExtendedWords = 26;

// EXC_RETURN (B1.5.8 table B1-8): bit 4 = 0 means an extended (FP) frame.
constexpr uint32_t kReturnHandler = 0xFFFFFFF1, kReturnThreadMsp = 0xFFFFFFF9, kReturnThreadPsp = 0xFFFFFFFD;
constexpr uint32_t kReturnNoFp = 1u << 4;

constexpr int kFrameRegisters[] = {UC_ARM_REG_R0, UC_ARM_REG_R1,  UC_ARM_REG_R2,
                                   UC_ARM_REG_R3, UC_ARM_REG_R12, UC_ARM_REG_LR};

}  // namespace

// Writes IPSR (and the T bit, IT cleared) and makes the emulator re-read its mode flags, so a
// branch to an EXC_RETURN value in handler mode ends the exception.
void ImageChip::write_ipsr(unsigned number) {
  uint32_t xpsr = read_register(UC_ARM_REG_XPSR);
  xpsr = (xpsr & 0xF80F0000u) | kThumb | (number & 0x1FF);
  uc_reg_write(uc_, UC_ARM_REG_XPSR_NZCVQG, &xpsr);
  uint32_t flags = read_register(UC_ARM_REG_APSR_NZCV);
  uc_reg_write(uc_, UC_ARM_REG_APSR_NZCV, &flags);  // rebuilds the cached mode flags (hflags)
}

bool ImageChip::take_pending_exception() {
  if (!exceptions_.any_pending()) {
    check_masks_ = false;
    return false;
  }
  const unsigned number = exceptions_.next_to_take(masks());
  if (number == 0) {
    // Held off: by the masks (re-check them at every block until it is taken) or by priority
    // (an exception return re-checks).
    check_masks_ = exceptions_.next_to_take(Masks{}) != 0;
    return false;
  }
  check_masks_ = false;
  enter_exception(number, read_register(UC_ARM_REG_PC));
  return true;
}

void ImageChip::enter_exception(unsigned number, uint32_t return_pc) {
  uint32_t control = read_register(UC_ARM_REG_CONTROL);
  const bool thread = current_exception_ == 0;
  const bool on_psp = thread && (control & kControlSpsel) != 0;
  const bool fp_frame = (control & kControlFpca) != 0 && (core_.fpccr & (1u << 31)) != 0;
  uint32_t sp = read_register(on_psp ? UC_ARM_REG_PSP : UC_ARM_REG_MSP);
  const size_t words = fp_frame ? kExtendedWords : kBasicWords;
  uint32_t xpsr = read_register(UC_ARM_REG_XPSR);
  if ((sp - 4 * words) & 4)
    xpsr |= kXpsrAlign;
  else
    xpsr &= ~kXpsrAlign;
  const uint32_t frame = (sp - 4 * words) & ~7u;
  std::array<uint32_t, kExtendedWords> words_out{};
  for (size_t i = 0; i < 6; ++i) words_out[i] = read_register(kFrameRegisters[i]);
  words_out[6] = return_pc & ~1u;
  words_out[7] = xpsr;
  if (fp_frame) {
    for (int s = 0; s < 16; ++s) words_out[8 + s] = read_register(UC_ARM_REG_S0 + s);
    words_out[24] = read_register(UC_ARM_REG_FPSCR);
  }
  if ((!on_psp && stack_overflows(frame)) || !write_memory(frame, words_out.data(), 4 * words)) {
    stack_fault(frame, return_pc);
    return;
  }
  if (on_psp) {
    uc_reg_write(uc_, UC_ARM_REG_PSP, &frame);
    control &= ~kControlSpsel;  // handlers run on MSP (written in thread mode: the emulator swaps SPs)
  } else {
    uc_reg_write(uc_, UC_ARM_REG_MSP, &frame);
  }
  control &= ~kControlFpca;
  uc_reg_write(uc_, UC_ARM_REG_CONTROL, &control);
  uint32_t lr = !thread ? kReturnHandler : on_psp ? kReturnThreadPsp : kReturnThreadMsp;
  if (fp_frame) lr &= ~kReturnNoFp;
  uc_reg_write(uc_, UC_ARM_REG_LR, &lr);
  activate(number);
}

// Fetches the handler's address and switches to it (the frame is already stacked).
void ImageChip::activate(unsigned number) {
  uint32_t handler = 0;
  if (!read_memory(core_.vtor + 4 * number, &handler, 4) || (handler & ~1u) == 0) {
    core_.hfsr |= 1u << 1;  // HFSR.VECTTBL
    char what[120];
    std::snprintf(what, sizeof what, "HardFault: no handler for exception %u in the vector table at 0x%08X", number,
                  core_.vtor);
    raise_fault(ImageStop::Kind::kHardFault, what, read_register(UC_ARM_REG_PC));
    return;
  }
  exceptions_.activate(number);
  current_exception_ = number;
  if (handler_costs_[number].entries++ == 0) handler_costs_[number].first_entry_ns = time_of_cycle(retired_);
  write_ipsr(number);
  handler |= 1u;
  uc_reg_write(uc_, UC_ARM_REG_PC, &handler);
}

void ImageChip::return_from_exception(uint32_t exc_return) {
  const unsigned number = current_exception_;
  const uint32_t kind = exc_return | kReturnNoFp;
  if ((kind != kReturnHandler && kind != kReturnThreadMsp && kind != kReturnThreadPsp) || number == 0) {
    core_.cfsr |= 1u << 18;  // UFSR.INVPC
    raise_fault(ImageStop::Kind::kUsageFault, "UsageFault: exception return with a bad EXC_RETURN value",
                read_register(UC_ARM_REG_LR));
    return;
  }
  const bool fp_frame = (exc_return & kReturnNoFp) == 0;
  const bool to_psp = kind == kReturnThreadPsp;
  const uint32_t frame = read_register(to_psp ? UC_ARM_REG_PSP : UC_ARM_REG_MSP);
  std::array<uint32_t, kExtendedWords> words{};
  const size_t count = fp_frame ? kExtendedWords : kBasicWords;
  if (!read_memory(frame, words.data(), 4 * count)) {
    stack_fault(frame, read_register(UC_ARM_REG_PC));
    return;
  }
  exceptions_.deactivate(number);
  unstack(words, fp_frame, frame + 4 * static_cast<uint32_t>(count), to_psp);
  recheck_ = true;  // a pending exception may be takeable now
}

// Restores the stacked registers and mode (the frame has been read into `words`).
void ImageChip::unstack(const std::array<uint32_t, 26>& words, bool fp_frame, uint32_t sp_after, bool to_psp) {
  for (size_t i = 0; i < 6; ++i) uc_reg_write(uc_, kFrameRegisters[i], &words[i]);
  if (fp_frame) {
    for (int s = 0; s < 16; ++s) uc_reg_write(uc_, UC_ARM_REG_S0 + s, &words[8 + s]);
    uc_reg_write(uc_, UC_ARM_REG_FPSCR, &words[24]);
  }
  const uint32_t xpsr = words[7];
  if (xpsr & kXpsrAlign) sp_after += 4;
  current_exception_ = xpsr & 0x1FF;
  write_ipsr(current_exception_);
  uint32_t restored = xpsr | kThumb;
  uc_reg_write(uc_, UC_ARM_REG_XPSR_NZCVQG, &restored);
  uint32_t control = read_register(UC_ARM_REG_CONTROL);
  control = fp_frame ? control | kControlFpca : control & ~kControlFpca;
  if (to_psp) control |= kControlSpsel;  // back in thread mode: the emulator swaps to PSP
  uc_reg_write(uc_, UC_ARM_REG_CONTROL, &control);
  uc_reg_write(uc_, to_psp ? UC_ARM_REG_PSP : UC_ARM_REG_MSP, &sp_after);
  const uint32_t pc = words[6] | 1u;
  uc_reg_write(uc_, UC_ARM_REG_PC, &pc);
  uint32_t flags = read_register(UC_ARM_REG_APSR_NZCV);
  uc_reg_write(uc_, UC_ARM_REG_APSR_NZCV, &flags);
}

}  // namespace stepdance::sim::image
