// Loop-pass benchmark image for QEMU's mps2-an500: runs a workload's loop passes one by one, each
// timed by a CMSDK timer under -icount (bench/measure_target_loop.sh; method in
// docs/benchmarks-target.md), with the workload's unmeasured frames between them. Prints the total,
// the worst pass and where it was. Workloads: EbbCommandWorkload (one EBB command per pass) and
// ArcWorkload (a 1,000-turn helical G2 line fed to the planner).
#include <stdint.h>
#include <stdio.h>

#include STEPDANCE_BENCH_LOOP_HEADER
using LoopWorkload = stepdance::workloads::STEPDANCE_BENCH_LOOP_CLASS;

#ifndef STEPDANCE_BENCH_PASSES
#define STEPDANCE_BENCH_PASSES 1000
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
// Ticks since timer_start(), counting up (wraps after 171 s of virtual time; passes are far shorter).
uint32_t timer_ticks() { return 0xFFFFFFFFu - timer0().value; }

constexpr uint32_t kKnownLoopIterations = 1000000;

// Passes whose workload is not done() run until it is (ArcWorkload); workloads without done()
// (EbbCommandWorkload) run STEPDANCE_BENCH_PASSES passes.
template <class W>
auto finished(W& workload, uint32_t, int) -> decltype(workload.done()) { return workload.done(); }
template <class W>
bool finished(W&, uint32_t pass, long) { return pass >= STEPDANCE_BENCH_PASSES; }

}  // namespace

int main(int, char**) {
  static LoopWorkload workload;  // large: not on the stack
  timer_start();

  uint32_t start = timer_ticks();
  bench_region_begin();
  bench_known_loop(kKnownLoopIterations);
  bench_region_end();
  const uint32_t known_ticks = timer_ticks() - start;

  uint64_t total_ticks = 0;
  uint32_t worst_ticks = 0;
  uint32_t worst_pass = 0;
  uint32_t pass = 0;
  const uint32_t units_before = workload.units();
  for (; !finished(workload, pass, 0) && pass < 100000000u; ++pass) {
    start = timer_ticks();
    workload.loop_pass();
    const uint32_t ticks = timer_ticks() - start;
    total_ticks += ticks;
    if (ticks > worst_ticks) {
      worst_ticks = ticks;
      worst_pass = pass;
    }
    workload.between_passes();
  }

  printf("known_loop iterations=%lu timer_ticks=%lu\n", static_cast<unsigned long>(kKnownLoopIterations),
         static_cast<unsigned long>(known_ticks));
  printf("passes count=%lu units=%lu total_ticks=%llu worst_ticks=%lu worst_pass=%lu\n",
         static_cast<unsigned long>(pass), static_cast<unsigned long>(workload.units() - units_before),
         static_cast<unsigned long long>(total_ticks), static_cast<unsigned long>(worst_ticks),
         static_cast<unsigned long>(worst_pass));
  return workload.failed() ? 1 : 0;
}
