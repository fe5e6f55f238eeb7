// Image CPU benchmark: emulated instructions per wall second for a firmware image on the emulated
// Cortex-M7 (sim/image/cpu), with SysTick at 1 kHz and a 25 kHz interrupt, at a 600 MHz core
// clock: once with a thread loop of register instructions, once with a RAM load and store every
// 8 instructions. Not a test: it reports numbers and asserts nothing.
//
//   stepdance_image_cpu_speed [simulated_seconds]
// The firmware is the build tree's tests/sim/image/fixtures/bench_loop.elf.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>

#include "image/cpu/image_chip.hpp"
#include "kernel/scheduler/periodic_timer.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace {

using stepdance::sim::SimTime;
namespace image = stepdance::sim::image;

constexpr unsigned kFrameIrq = 3;
constexpr SimTime kFramePeriodNs = 40 * stepdance::sim::kMicrosecond;  // 25 kHz

// Raises and lowers the frame interrupt's line: the rising edge pends it.
void frame_tick(void* context, SimTime) {
  auto& chip = *static_cast<image::ImageChip*>(context);
  chip.set_irq_level(kFrameIrq, true);
  chip.set_irq_level(kFrameIrq, false);
}

// Runs `simulated_s` of the firmware with its thread loop `loop_kind`; prints the figures.
int run(double simulated_s, uint32_t loop_kind) {
  const std::string elf = STEPDANCE_BUILD_DIR "/tests/sim/image/fixtures/bench_loop.elf";
  stepdance::sim::Scheduler scheduler;
  image::ImageChip chip(scheduler, image::TeensyModel::kTeensy41);
  std::string error;
  if (!chip.load(elf, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 2;
  }
  chip.on_stop([](const image::ImageStop& stop) { std::fprintf(stderr, "stopped: %s\n", stop.what.c_str()); });
  uint32_t kind_address = 0;
  if (!chip.symbols().find("loop_kind", kind_address) || !chip.write_memory(kind_address, &loop_kind, 4)) return 2;
  chip.set_core_clock_hz(600000000);
  chip.power_on(0);
  stepdance::sim::PeriodicTimer frames(scheduler, &frame_tick, &chip);
  frames.start(kFramePeriodNs, kFramePeriodNs);
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  scheduler.run_until(stepdance::sim::from_seconds(simulated_s));
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  // Process CPU time as well: on a shared machine it moves less than wall time.
  const double cpu_s = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const image::ImageChip::HandlerCost irq = chip.handler_cost(16 + kFrameIrq);
  const image::ImageChip::HandlerCost tick = chip.handler_cost(15);
  std::printf("%s thread loop: simulated %.3f s at 600 MHz in %.3f s of wall time\n",
              loop_kind == 0 ? "register" : "load/store", simulated_s, wall_s);
  std::printf("emulated instructions: %llu (%.1f million per wall second, %.1f million per CPU second)\n",
              static_cast<unsigned long long>(chip.instructions()),
              static_cast<double>(chip.instructions()) / wall_s / 1e6,
              static_cast<double>(chip.instructions()) / cpu_s / 1e6);
  std::printf("simulated seconds per wall second: %.3f\n", simulated_s / wall_s);
  std::printf("25 kHz interrupt: %llu entries, %.1f instructions each; SysTick: %llu entries\n",
              static_cast<unsigned long long>(irq.entries),
              irq.entries ? static_cast<double>(irq.instructions) / static_cast<double>(irq.entries) : 0.0,
              static_cast<unsigned long long>(tick.entries));
  return chip.stopped() ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  const double simulated_s = argc > 1 ? std::atof(argv[1]) : 1.0;
  const int registers = run(simulated_s, 0);
  const int memory = run(simulated_s, 1);
  return registers != 0 ? registers : memory;
}
