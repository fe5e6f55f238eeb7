// The emulator behaviour ImageChip::run_slice() works around (cpu_run.cpp), shown on unicorn
// itself: a run stopped from the block hook, before a block entered by a chained jump, leaves the
// PC at the block's start only while no UC_HOOK_CODE exists. With one registered anywhere (even on
// an address never run) unicorn 2.0.1's cpu_tb_exec skips its "restore the PC to the TB's start"
// and the PC is the last one synced: here the start of the previous block, after its push ran.
// If a later unicorn restores the PC itself, the second test fails and the workaround is moot.
#include <gtest/gtest.h>

#include <unicorn/unicorn.h>

#include <cstdint>

namespace stepdance::sim::image::testing {
namespace {

constexpr uint32_t kCode = 0x100, kPopBlock = 0x108, kStack = 0x20001000;

struct Engine {
  uc_engine* uc = nullptr;
  uint64_t stop_at = 0;
  Engine() {
    uc_open(UC_ARCH_ARM, static_cast<uc_mode>(UC_MODE_THUMB | UC_MODE_MCLASS), &uc);
    uc_ctl_set_cpu_model(uc, UC_CPU_ARM_CORTEX_M7);
    uc_mem_map(uc, 0, 0x10000, UC_PROT_ALL);
    uc_mem_map(uc, 0x20000000, 0x10000, UC_PROT_ALL);
    // 0x100: push {r4,r5}; movs r5,#7; cmp r0,r0; bne 0x100 (not taken: falls through to 0x108)
    // 0x108: pop {r4,r5}; bx lr
    const uint8_t code[] = {0x30, 0xB4, 0x07, 0x25, 0x80, 0x42, 0xFB, 0xD1, 0x30, 0xBC, 0x70, 0x47};
    uc_mem_write(uc, kCode, code, sizeof code);
    uc_hook hook;
    uc_hook_add(uc, &hook, UC_HOOK_BLOCK, reinterpret_cast<void*>(&on_block), this, 1, 0);
  }
  ~Engine() { uc_close(uc); }
  static void on_block(uc_engine* engine, uint64_t address, uint32_t, void* user) {
    if (address == static_cast<Engine*>(user)->stop_at) uc_emu_stop(engine);
  }
  static void on_code(uc_engine*, uint64_t, uint32_t, void*) {}
  uint32_t reg(int id) {
    uint32_t value = 0;
    uc_reg_read(uc, id, &value);
    return value;
  }
  /// Calls the code at 0x100 (returning to 0x200, the run's end); stops before `stop_at`.
  void call(uint64_t stop_block) {
    uint32_t sp = kStack, lr = 0x201;
    uc_reg_write(uc, UC_ARM_REG_SP, &sp);
    uc_reg_write(uc, UC_ARM_REG_LR, &lr);
    stop_at = stop_block;
    uc_emu_start(uc, kCode | 1u, 0x200, 0, 0);
  }
};

TEST(UnicornStop, WithoutACodeHookTheStoppedBlockIsWhereThePcIs) {
  Engine e;
  e.call(0);          // translates both blocks and chains 0x100 -> 0x108
  e.call(kPopBlock);  // stops before the chained block
  EXPECT_EQ(e.reg(UC_ARM_REG_PC), kPopBlock);
  EXPECT_EQ(e.reg(UC_ARM_REG_SP), kStack - 8);  // the push ran
}

TEST(UnicornStop, WithACodeHookAnywhereThePcIsAnEarlierBlocksStart) {
  Engine e;
  uc_hook hook;
  uc_hook_add(e.uc, &hook, UC_HOOK_CODE, reinterpret_cast<void*>(&Engine::on_code), nullptr, 0x8000, 0x8000);
  e.call(0);
  e.call(kPopBlock);
  EXPECT_EQ(e.reg(UC_ARM_REG_PC), kCode);  // resumed here, the push would run twice
  EXPECT_EQ(e.reg(UC_ARM_REG_SP), kStack - 8);
}

}  // namespace
}  // namespace stepdance::sim::image::testing
