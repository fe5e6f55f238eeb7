// Frame-cost benchmark image for QEMU's mps2-an500: runs N frames of a benchmark graph (the
// Step-A-Sketch-sized one by default; STEPDANCE_BENCH_GRAPH_HEADER and _CLASS name another) on
// the manual backend between two marker calls, timed by a CMSDK timer (docs/benchmarks-target.md).
#include <stdint.h>
#include <stdio.h>

#ifndef STEPDANCE_BENCH_GRAPH_HEADER
#define STEPDANCE_BENCH_GRAPH_HEADER "step_a_sketch_graph.hpp"
#define STEPDANCE_BENCH_GRAPH_CLASS StepASketchGraph
#endif
#include STEPDANCE_BENCH_GRAPH_HEADER
#include "stepdance/core/frame_period.hpp"
using BenchGraph = stepdance::workloads::STEPDANCE_BENCH_GRAPH_CLASS;

#ifndef STEPDANCE_BENCH_FRAMES
#define STEPDANCE_BENCH_FRAMES 20000
#endif

extern "C" {

// bench/measure_target_frame.sh finds these names in QEMU's execution trace: only instructions
// executed between the two markers are counted. They are never inlined and do nothing else.
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
#if defined(STEPDANCE_BENCH_FRAME_PERIOD_US)
  stepdance::set_frame_period_us(STEPDANCE_BENCH_FRAME_PERIOD_US);  // before the graph starts the engine
#endif
  BenchGraph graph;
  timer_start();

  uint32_t start = timer_ticks();
  bench_region_begin();
  bench_known_loop(kKnownLoopIterations);
  bench_region_end();
  const uint32_t known_ticks = timer_ticks() - start;

  const uint32_t frames = STEPDANCE_BENCH_FRAMES;
  start = timer_ticks();
  bench_region_begin();
  for (uint32_t frame = 0; frame < frames; ++frame) graph.run_busy_frame(frame);
  bench_region_end();
  const uint32_t frame_ticks = timer_ticks() - start;

  const uint32_t pulses = graph.output_a.pulses_sent(stepdance::SIGNAL_E, stepdance::DIRECTION_FORWARD) +
                          graph.output_a.pulses_sent(stepdance::SIGNAL_E, stepdance::DIRECTION_REVERSE);
  printf("known_loop iterations=%lu timer_ticks=%lu\n", static_cast<unsigned long>(kKnownLoopIterations),
         static_cast<unsigned long>(known_ticks));
  printf("frames count=%lu timer_ticks=%lu pulses_a=%lu\n", static_cast<unsigned long>(frames),
         static_cast<unsigned long>(frame_ticks), static_cast<unsigned long>(pulses));
  return pulses > 0 ? 0 : 1;
}
