// Google Benchmark: host time for one G-code line through the Grbl link (receive, parse, validate,
// execute, `ok`) and the look-ahead planner with a full 128-block queue.
#include <benchmark/benchmark.h>

#include "gcode_workload.hpp"

namespace {

void BM_ParseAndPlanOneGcodeLine(benchmark::State& state) {
  static stepdance::workloads::GcodeLineWorkload workload;  // 128 blocks and the link: large
  for (auto _ : state) workload.step();
  benchmark::DoNotOptimize(workload.checksum());
  state.SetItemsProcessed(state.iterations());  // items/s = G-code lines per second
}
BENCHMARK(BM_ParseAndPlanOneGcodeLine);

}  // namespace
