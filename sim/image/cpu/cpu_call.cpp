// A debugger's call into the image (ImageChip::call_function): the function runs on the core as
// it stands, between two runs, with simulated time stopped, nothing counted and no exception
// taken; afterwards every register is as it was. Its return and its callouts are fetches from
// addresses where no memory is, which the fetch hook recognises (kCallReturnAddress,
// kCalloutAddress: 0x80000000–0x9FFFFFFF is executable in the default memory map, DDI 0403E
// B3.1 table B3-1, and nothing is mapped there on the RT1062 model).
#include <unicorn/unicorn.h>

#include <array>
#include <cstdio>

#include "image/cpu/block_cache.hpp"
#include "image/cpu/image_chip.hpp"

namespace stepdance::sim::image {
namespace {

constexpr uint64_t kNoUntil = 0xFFFFFFFE;
/// Room left below the interrupted code's stack pointer (bytes, 8-byte aligned as AAPCS wants).
constexpr uint32_t kStackGapBytes = 64;

/// The core registers a call may change, saved and put back.
constexpr int kSavedRegisters[] = {
    UC_ARM_REG_R0,  UC_ARM_REG_R1,  UC_ARM_REG_R2,   UC_ARM_REG_R3,    UC_ARM_REG_R4,  UC_ARM_REG_R5,  UC_ARM_REG_R6,
    UC_ARM_REG_R7,  UC_ARM_REG_R8,  UC_ARM_REG_R9,   UC_ARM_REG_R10,   UC_ARM_REG_R11, UC_ARM_REG_R12, UC_ARM_REG_SP,
    UC_ARM_REG_LR,  UC_ARM_REG_PC,  UC_ARM_REG_XPSR, UC_ARM_REG_FPSCR, UC_ARM_REG_D0,  UC_ARM_REG_D1,  UC_ARM_REG_D2,
    UC_ARM_REG_D3,  UC_ARM_REG_D4,  UC_ARM_REG_D5,   UC_ARM_REG_D6,    UC_ARM_REG_D7,  UC_ARM_REG_D8,  UC_ARM_REG_D9,
    UC_ARM_REG_D10, UC_ARM_REG_D11, UC_ARM_REG_D12,  UC_ARM_REG_D13,   UC_ARM_REG_D14, UC_ARM_REG_D15};

class SavedRegisters {
 public:
  explicit SavedRegisters(uc_struct* uc) : uc_(uc) {
    for (size_t i = 0; i < std::size(kSavedRegisters); ++i) uc_reg_read(uc_, kSavedRegisters[i], &values_[i]);
  }
  ~SavedRegisters() {
    for (size_t i = 0; i < std::size(kSavedRegisters); ++i) uc_reg_write(uc_, kSavedRegisters[i], &values_[i]);
  }
  SavedRegisters(const SavedRegisters&) = delete;
  SavedRegisters& operator=(const SavedRegisters&) = delete;

 private:
  uc_struct* uc_;
  std::array<uint64_t, std::size(kSavedRegisters)> values_{};  // D registers are 64-bit
};

void write_register(uc_struct* uc, int reg, uint32_t value) { uc_reg_write(uc, reg, &value); }

}  // namespace

bool ImageChip::call_function(uint32_t function, const std::array<uint32_t, 4>& args,
                              const std::function<void()>& on_callout, std::string& error) {
  if (in_run_ || calling_ || stopped_ || !powered_) {
    error = "the image cannot be called now (running, stopped or not powered)";
    return false;
  }
  const SavedRegisters saved(uc_);
  const uint64_t retired = retired_;
  const auto costs = handler_costs_;
  calling_ = true;
  call_instructions_ = 0;
  for (size_t i = 0; i < args.size(); ++i) write_register(uc_, UC_ARM_REG_R0 + static_cast<int>(i), args[i]);
  write_register(uc_, UC_ARM_REG_SP, (read_register(UC_ARM_REG_SP) - kStackGapBytes) & ~7u);
  write_register(uc_, UC_ARM_REG_LR, kCallReturnAddress | 1u);
  const bool returned = run_call(function | 1u, on_callout, error);
  calling_ = false;
  retired_ = retired;
  handler_costs_ = costs;
  block_ = nullptr;
  return returned;
}

// Runs until the call returns: each callout runs `on_callout` and returns to the code that made
// it. False with `error` on anything else (a fault, a register access, too many instructions).
bool ImageChip::run_call(uint32_t pc, const std::function<void()>& on_callout, std::string& error) {
  for (;;) {
    call_reached_ = 0;
    call_problem_.clear();
    uc_emu_start(uc_, pc, kNoUntil, 0, 0);
    if (!call_problem_.empty()) {
      error = call_problem_;
      return false;
    }
    if (call_reached_ == kCallReturnAddress) return true;
    if (call_reached_ != kCalloutAddress) {
      error = "the called function stopped at " + symbols().describe(read_register(UC_ARM_REG_PC));
      return false;
    }
    on_callout();
    pc = read_register(UC_ARM_REG_LR) | 1u;
  }
}

// Inside a call: where the emulator stopped, or why it must. True if the hook handled it.
bool ImageChip::call_fetch(uint32_t address) {
  if (address == kCallReturnAddress || address == kCalloutAddress) {
    call_reached_ = address;
  } else {
    char where[16];
    std::snprintf(where, sizeof where, "0x%08X", address);
    call_problem_ = std::string("the called function fetched from ") + where + ", where no memory is";
  }
  uc_emu_stop(uc_);
  return false;
}

void ImageChip::call_went_wrong(const std::string& what) {
  if (call_problem_.empty()) call_problem_ = "the called function " + what;
  uc_emu_stop(uc_);
}

}  // namespace stepdance::sim::image
