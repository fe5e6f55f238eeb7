// How to count instructions with unicorn (the choice sim/image/cpu made): a block hook adding a
// cached per-block count, against unicorn's per-instruction ways (a code hook; uc_emu_start's
// `count`). A Thumb loop of 10 register instructions, 20 million instructions each way.
// Not a test: it reports numbers and asserts nothing.   Usage: stepdance_unicorn_counting
#include <unicorn/unicorn.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <ctime>

namespace {

constexpr uint64_t kInstructions = 20000000;
constexpr uint32_t kLoopInstructions = 10;

struct Counter {
  uint64_t instructions = 0;
};

// Every block of the loop is the whole loop: 10 instructions (the block hook's cached count).
void on_block(uc_engine* uc, uint64_t, uint32_t, void* user) {
  auto& counter = *static_cast<Counter*>(user);
  counter.instructions += kLoopInstructions;
  if (counter.instructions >= kInstructions) uc_emu_stop(uc);
}

void on_instruction(uc_engine* uc, uint64_t, uint32_t, void* user) {
  auto& counter = *static_cast<Counter*>(user);
  if (++counter.instructions >= kInstructions) uc_emu_stop(uc);
}

uc_engine* open_loop() {
  uc_engine* uc = nullptr;
  uc_open(UC_ARCH_ARM, UC_MODE_THUMB, &uc);  // as ImageChip opens it (no MCLASS: see image_chip.cpp)
  uc_ctl_set_cpu_model(uc, UC_CPU_ARM_CORTEX_M7);
  uc_mem_map(uc, 0, 0x10000, UC_PROT_ALL);
  // 0x100: adds r1,#1 (×9); b 0x100
  uint16_t code[kLoopInstructions];
  for (uint32_t i = 0; i + 1 < kLoopInstructions; ++i) code[i] = 0x3101;
  code[kLoopInstructions - 1] = 0xE7F5;  // b: PC + 4 - 22 = 0x100
  uc_mem_write(uc, 0x100, code, sizeof code);
  return uc;
}

void report(const char* way, std::clock_t start) {
  const double cpu_s = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
  std::printf("%-36s %8.1f million instructions per CPU second\n", way,
              static_cast<double>(kInstructions) / cpu_s / 1e6);
}

}  // namespace

int main() {
  for (int way = 0; way < 3; ++way) {
    uc_engine* uc = open_loop();
    Counter counter;
    uc_hook hook;
    if (way == 0) uc_hook_add(uc, &hook, UC_HOOK_BLOCK, reinterpret_cast<void*>(&on_block), &counter, 1, 0);
    if (way == 1) uc_hook_add(uc, &hook, UC_HOOK_CODE, reinterpret_cast<void*>(&on_instruction), &counter, 1, 0);
    const std::clock_t start = std::clock();
    uc_emu_start(uc, 0x101, 0xFFFFFFFE, 0, way == 2 ? kInstructions : 0);
    report(way == 0   ? "block hook, cached count"
           : way == 1 ? "code hook (every instruction)"
                      : "uc_emu_start count",
           start);
    uc_close(uc);
  }
  return 0;
}
