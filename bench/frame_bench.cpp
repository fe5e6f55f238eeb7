// Google Benchmark: host nanoseconds for one frame of the Step-A-Sketch-sized graph.
#include <benchmark/benchmark.h>

#include "step_a_sketch_graph.hpp"

namespace {

void BM_StepASketchFrame(benchmark::State& state) {
  stepdance::workloads::StepASketchGraph graph;
  uint32_t frame = 0;
  for (auto _ : state) graph.run_busy_frame(frame++);
  state.counters["frames"] = frame;
}
BENCHMARK(BM_StepASketchFrame);

}  // namespace

BENCHMARK_MAIN();
