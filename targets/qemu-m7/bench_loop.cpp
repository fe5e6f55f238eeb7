// Loop-pass benchmark image for QEMU's mps2-an500: runs a workload's loop passes one by one, each
// timed by a CMSDK timer under -icount (bench/measure_target_loop.sh; method in
// docs/benchmarks-target.md), with the workload's unmeasured frames between them. Prints the total,
// the worst pass and where it was. Workloads: EbbCommandWorkload (one EBB command per pass) and
// ArcWorkload (a 1,000-turn helical G2 line fed to the planner).
#include <stdint.h>
#include <stdio.h>

#include "bench_timing.hpp"

#include STEPDANCE_BENCH_LOOP_HEADER
using LoopWorkload = stepdance::workloads::STEPDANCE_BENCH_LOOP_CLASS;

#ifndef STEPDANCE_BENCH_PASSES
#define STEPDANCE_BENCH_PASSES 1000
#endif

using namespace stepdance::bench;

namespace {

// Passes whose workload is not done() run until it is (ArcWorkload); workloads without done()
// (EbbCommandWorkload) run STEPDANCE_BENCH_PASSES passes.
template <class W>
auto finished(W& workload, uint32_t, int) -> decltype(workload.done()) {
  return workload.done();
}
template <class W>
bool finished(W&, uint32_t pass, long) {
  return pass >= STEPDANCE_BENCH_PASSES;
}

}  // namespace

int main(int, char**) {
  static LoopWorkload workload;  // large: not on the stack
  timer_start();
  const uint32_t known_ticks = measure_known_loop();

  uint64_t total_ticks = 0;
  uint32_t worst_ticks = 0;
  uint32_t worst_pass = 0;
  uint32_t pass = 0;
  const uint32_t units_before = workload.units();
  for (; !finished(workload, pass, 0) && pass < 100000000u; ++pass) {
    const uint32_t start = timer_ticks();
    workload.loop_pass();
    const uint32_t ticks = timer_ticks() - start;
    total_ticks += ticks;
    if (ticks > worst_ticks) {
      worst_ticks = ticks;
      worst_pass = pass;
    }
    workload.between_passes();
  }

  print_known_loop(known_ticks);
  printf("passes count=%lu units=%lu total_ticks=%llu worst_ticks=%lu worst_pass=%lu\n",
         static_cast<unsigned long>(pass), static_cast<unsigned long>(workload.units() - units_before),
         static_cast<unsigned long long>(total_ticks), static_cast<unsigned long>(worst_ticks),
         static_cast<unsigned long>(worst_pass));
  return workload.failed() ? 1 : 0;
}
