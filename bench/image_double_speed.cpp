// Double-precision benchmark: the cost of one double-precision instruction run in software
// (sim/image/cpu/vfp_hooks.cpp) against the same loop in single precision (which the emulator
// runs itself). Not a test: it reports numbers and asserts nothing.
//
//   stepdance_image_double_speed
// The firmware is the build tree's tests/sim/image/fixtures/bench_double_f64.elf and _f32.elf:
// 200,000 iterations of five operations and a branch, 1,000,000 operations in all.
#include <chrono>
#include <cstdio>
#include <ctime>
#include <string>

#include "image/cpu/image_chip.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace {

namespace image = stepdance::sim::image;

struct Figures {
  double wall_s = 0;
  double cpu_s = 0;
  uint64_t instructions = 0;
  uint64_t double_ops = 0;
};

double cpu_now_s() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// Runs `name` until it stops at its final `b .` (no progress).
bool run(const char* name, Figures& figures) {
  const std::string elf = std::string(STEPDANCE_BUILD_DIR "/tests/sim/image/fixtures/") + name + ".elf";
  stepdance::sim::Scheduler scheduler;
  image::ImageChip chip(scheduler, image::TeensyModel::kTeensy41);
  std::string error;
  if (!chip.load(elf, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return false;
  }
  chip.power_on(0);
  const auto wall_start = std::chrono::steady_clock::now();
  const double cpu_start = cpu_now_s();
  scheduler.run_until(stepdance::sim::kSecond);
  figures.cpu_s = cpu_now_s() - cpu_start;
  figures.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  figures.instructions = chip.instructions();
  figures.double_ops = chip.double_ops().executed;
  return chip.stopped();
}

}  // namespace

int main() {
  Figures f64, f32;
  if (!run("bench_double_f64", f64) || !run("bench_double_f32", f32)) return 1;
  std::printf("loop of 1,000,000 operations      CPU s     wall s   instructions  double ops\n");
  std::printf("double precision (software)     %7.3f    %7.3f   %12llu  %10llu\n", f64.cpu_s, f64.wall_s,
              static_cast<unsigned long long>(f64.instructions), static_cast<unsigned long long>(f64.double_ops));
  std::printf("single precision (emulator)     %7.3f    %7.3f   %12llu  %10llu\n", f32.cpu_s, f32.wall_s,
              static_cast<unsigned long long>(f32.instructions), static_cast<unsigned long long>(f32.double_ops));
  const double ns = (f64.cpu_s - f32.cpu_s) * 1e9 / static_cast<double>(f64.double_ops ? f64.double_ops : 1);
  std::printf("software double operation: %.0f ns of CPU each, beyond the single-precision one\n", ns);
  return 0;
}
