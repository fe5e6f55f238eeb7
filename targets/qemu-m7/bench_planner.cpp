// Planner-throughput benchmark image for QEMU's mps2-an500: plans N segments with a full
// 128-block look-ahead queue between two markers, timed by a CMSDK timer under -icount
// (bench/measure_target_planner.sh; method in docs/benchmarks-target.md). The workload is the
// planner alone (PlannerWorkload) or G-code lines through the Grbl link into it (GcodeLineWorkload).
#include <stdint.h>
#include <stdio.h>

#include "gcode_workload.hpp"
#include "planner_workload.hpp"

#ifndef STEPDANCE_BENCH_PLANNER_WORKLOAD
#define STEPDANCE_BENCH_PLANNER_WORKLOAD PlannerWorkload
#endif

#ifndef STEPDANCE_BENCH_SEGMENTS
#define STEPDANCE_BENCH_SEGMENTS 5000
#endif

extern "C" {

__attribute__((noinline)) void bench_region_begin(void) { __asm__ volatile("" ::: "memory"); }
__attribute__((noinline)) void bench_region_end(void) { __asm__ volatile("" ::: "memory"); }

// A loop of known cost: `subs` + `bne` per iteration, then `bx lr`, i.e. 2 * iterations + 1.
__attribute__((noinline, naked)) void bench_known_loop(uint32_t) {
  __asm__ volatile(
      "1: subs r0, r0, #1\n\t"
      "bne 1b\n\t"
      "bx lr");
}

}  // extern "C"

namespace {

// CMSDK APB timer 0 of the mps2 boards (Cortex-M System Design Kit TRM, "APB timer"): a 32-bit
// down-counter at the 25 MHz peripheral clock. Under `-icount shift=0` QEMU's virtual clock moves
// 1 ns per instruction, so one timer tick is 40 executed instructions.
struct CmsdkTimer {
  volatile uint32_t ctrl;    // 0x00, bit 0: enable
  volatile uint32_t value;   // 0x04, current count
  volatile uint32_t reload;  // 0x08, value loaded on reaching zero
};
CmsdkTimer& timer0() { return *reinterpret_cast<CmsdkTimer*>(0x40000000u); }

void timer_start() {
  timer0().ctrl = 0;
  timer0().reload = 0xFFFFFFFFu;
  timer0().value = 0xFFFFFFFFu;
  timer0().ctrl = 1;
}
// Ticks since timer_start(), counting up.
uint32_t timer_ticks() { return 0xFFFFFFFFu - timer0().value; }

constexpr uint32_t kKnownLoopIterations = 1000000;

}  // namespace

int main(int, char**) {
  static stepdance::workloads::STEPDANCE_BENCH_PLANNER_WORKLOAD workload;  // 128 blocks: too big for the stack
  timer_start();

  uint32_t start = timer_ticks();
  bench_region_begin();
  bench_known_loop(kKnownLoopIterations);
  bench_region_end();
  const uint32_t known_ticks = timer_ticks() - start;

  const uint32_t segments = STEPDANCE_BENCH_SEGMENTS;
  start = timer_ticks();
  bench_region_begin();
  for (uint32_t i = 0; i < segments; ++i) workload.step();
  bench_region_end();
  const uint32_t segment_ticks = timer_ticks() - start;

  printf("known_loop iterations=%lu timer_ticks=%lu\n", static_cast<unsigned long>(kKnownLoopIterations),
         static_cast<unsigned long>(known_ticks));
  printf("segments count=%lu timer_ticks=%lu checksum=%ld\n", static_cast<unsigned long>(segments),
         static_cast<unsigned long>(segment_ticks), static_cast<long>(workload.checksum()));
  return workload.checksum() > 0 ? 0 : 1;
}
