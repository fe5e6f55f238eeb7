// The QEMU benchmark images' shared markers, known loop and its report (bench_timing.hpp).
#include "bench_timing.hpp"

#include <stdio.h>

extern "C" {

__attribute__((noinline)) void bench_region_begin(void) { __asm__ volatile("" ::: "memory"); }
__attribute__((noinline)) void bench_region_end(void) { __asm__ volatile("" ::: "memory"); }

// Naked: no prologue or epilogue, so its instruction count is exactly the loop's.
__attribute__((noinline, naked)) void bench_known_loop(uint32_t) {
  __asm__ volatile(
      "1: subs r0, r0, #1\n\t"
      "bne 1b\n\t"
      "bx lr");
}

}  // extern "C"

namespace stepdance::bench {

uint32_t measure_known_loop() {
  const uint32_t start = timer_ticks();
  bench_region_begin();
  bench_known_loop(kKnownLoopIterations);
  bench_region_end();
  return timer_ticks() - start;
}

void print_known_loop(uint32_t ticks) {
  printf("known_loop iterations=%lu timer_ticks=%lu\n", static_cast<unsigned long>(kKnownLoopIterations),
         static_cast<unsigned long>(ticks));
}

}  // namespace stepdance::bench
