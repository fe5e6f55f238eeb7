// Frame-cost benchmark image for QEMU's mps2-an500: runs N frames of a benchmark graph (the
// Step-A-Sketch-sized one by default; STEPDANCE_BENCH_GRAPH_HEADER and _CLASS name another) on
// the manual backend between two marker calls, timed by a CMSDK timer (docs/benchmarks-target.md).
#include <stdint.h>
#include <stdio.h>

#include "bench_timing.hpp"

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

using namespace stepdance::bench;

int main(int, char**) {
#if defined(STEPDANCE_BENCH_FRAME_PERIOD_US)
  stepdance::set_frame_period_us(STEPDANCE_BENCH_FRAME_PERIOD_US);  // before the graph starts the engine
#endif
  BenchGraph graph;
  timer_start();
  const uint32_t known_ticks = measure_known_loop();

  const uint32_t frames = STEPDANCE_BENCH_FRAMES;
  uint32_t start = timer_ticks();
  bench_region_begin();
  for (uint32_t frame = 0; frame < frames; ++frame) graph.run_busy_frame(frame);
  bench_region_end();
  const uint32_t frame_ticks = timer_ticks() - start;

  const uint32_t pulses = graph.output_a.pulses_sent(stepdance::SIGNAL_E, stepdance::DIRECTION_FORWARD) +
                          graph.output_a.pulses_sent(stepdance::SIGNAL_E, stepdance::DIRECTION_REVERSE);
  print_known_loop(known_ticks);
  printf("frames count=%lu timer_ticks=%lu pulses_a=%lu\n", static_cast<unsigned long>(frames),
         static_cast<unsigned long>(frame_ticks), static_cast<unsigned long>(pulses));
  return pulses > 0 ? 0 : 1;
}
