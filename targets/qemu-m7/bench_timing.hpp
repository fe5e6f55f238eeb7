// What the QEMU benchmark images (bench_frame, bench_planner, bench_loop) share: the two marker
// functions bench/measure_target_*.sh find in QEMU's trace, a loop of known cost, and CMSDK timer 0
// of the mps2 boards, which the images read under -icount (method: docs/benchmarks-target.md).
#pragma once

#include <stdint.h>

extern "C" {

/// bench/measure_target_frame.sh finds these names in QEMU's execution trace: only instructions
/// executed between the two markers are counted. They are never inlined and do nothing else.
void bench_region_begin(void);
void bench_region_end(void);
/// A loop of known cost: `subs` + `bne` per iteration, then `bx lr`, i.e. 2 * iterations + 1
/// instructions. Never inlined.
void bench_known_loop(uint32_t iterations);

}  // extern "C"

namespace stepdance::bench {

// CMSDK APB timer 0 of the mps2 boards (Cortex-M System Design Kit TRM, "APB timer"): a 32-bit
// down-counter at the 25 MHz peripheral clock. Under `-icount shift=0` QEMU's virtual clock moves
// 1 ns per instruction, so one timer tick is 40 executed instructions.
struct CmsdkTimer {
  volatile uint32_t ctrl;    // 0x00, bit 0: enable
  volatile uint32_t value;   // 0x04, current count
  volatile uint32_t reload;  // 0x08, value loaded on reaching zero
};
inline CmsdkTimer& timer0() { return *reinterpret_cast<CmsdkTimer*>(0x40000000u); }

/// Starts timer 0 from its top count. Inline, as the timer reads were in each image before.
inline void timer_start() {
  timer0().ctrl = 0;
  timer0().reload = 0xFFFFFFFFu;
  timer0().value = 0xFFFFFFFFu;
  timer0().ctrl = 1;
}
/// Ticks (40 instructions each under -icount shift=0) since timer_start(), counting up; wraps
/// after 171 s of virtual time.
inline uint32_t timer_ticks() { return 0xFFFFFFFFu - timer0().value; }

/// Iterations of the known loop each image runs first: 2,000,001 instructions, 50,000 ticks.
constexpr uint32_t kKnownLoopIterations = 1000000;

/// Runs the known loop between the markers (the first marked region of every image) and returns
/// its ticks; the measuring scripts check the timer against it. Call after timer_start().
uint32_t measure_known_loop();
/// Prints "known_loop iterations=N timer_ticks=T", the line the measuring scripts read.
void print_known_loop(uint32_t ticks);

}  // namespace stepdance::bench
