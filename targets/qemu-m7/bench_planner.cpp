// Planner-throughput benchmark image for QEMU's mps2-an500: plans N segments with a full
// 128-block look-ahead queue between two markers, timed by a CMSDK timer under -icount
// (bench/measure_target_planner.sh; method in docs/benchmarks-target.md). The workload is the
// planner alone (PlannerWorkload) or G-code lines through the Grbl link into it (GcodeLineWorkload).
#include <stdint.h>
#include <stdio.h>

#include "bench_timing.hpp"
#include "gcode_workload.hpp"
#include "planner_workload.hpp"

#ifndef STEPDANCE_BENCH_PLANNER_WORKLOAD
#define STEPDANCE_BENCH_PLANNER_WORKLOAD PlannerWorkload
#endif

#ifndef STEPDANCE_BENCH_SEGMENTS
#define STEPDANCE_BENCH_SEGMENTS 5000
#endif

using namespace stepdance::bench;

int main(int, char**) {
  static stepdance::workloads::STEPDANCE_BENCH_PLANNER_WORKLOAD workload;  // 128 blocks: too big for the stack
  timer_start();
  const uint32_t known_ticks = measure_known_loop();

  const uint32_t segments = STEPDANCE_BENCH_SEGMENTS;
  uint32_t start = timer_ticks();
  bench_region_begin();
  for (uint32_t i = 0; i < segments; ++i) workload.step();
  bench_region_end();
  const uint32_t segment_ticks = timer_ticks() - start;

  print_known_loop(known_ticks);
  printf("segments count=%lu timer_ticks=%lu checksum=%ld\n", static_cast<unsigned long>(segments),
         static_cast<unsigned long>(segment_ticks), static_cast<long>(workload.checksum()));
  return workload.checksum() > 0 ? 0 : 1;
}
