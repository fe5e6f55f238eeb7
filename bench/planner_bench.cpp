// Google Benchmark: host time to plan one segment with a full 128-block look-ahead queue.
#include <benchmark/benchmark.h>

#include "planner_workload.hpp"

namespace {

void BM_PlanOneSegmentFullQueue(benchmark::State& state) {
  stepdance::workloads::PlannerWorkload workload;
  for (auto _ : state) workload.step();
  benchmark::DoNotOptimize(workload.checksum());
  state.SetItemsProcessed(state.iterations());  // items/s = planned segments per second
}
BENCHMARK(BM_PlanOneSegmentFullQueue);

}  // namespace
