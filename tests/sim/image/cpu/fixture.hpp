// Test support: a fixture firmware (tests/sim/image/fixtures) on an ImageChip with its own scheduler.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <unicorn/unicorn.h>

#include <cstdio>

#include "image/cpu/image_chip.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image::testing {

/// The path of fixture `name`'s ELF in the build tree.
inline std::string fixture_path(const std::string& name) {
  return std::string(STEPDANCE_BUILD_DIR) + "/tests/sim/image/fixtures/" + name + ".elf";
}

/// A chip with a fixture loaded and powered on at t = 0, and its stop (if any) kept.
struct Fixture {
  Scheduler scheduler;
  std::unique_ptr<ImageChip> chip;
  std::vector<ImageStop> stops;

  /// Loads `name` (a Teensy 4.1 map) and powers on; false (with a test failure) if it cannot.
  bool boot(const std::string& name, std::function<void(ImageChip&)> before_power = nullptr) {
#ifdef STEPDANCE_NO_ARM_GCC
    ADD_FAILURE() << "arm-none-eabi-gcc was not found when the tree was configured: the fixture firmware "
                     "cannot be built (install gcc-arm-none-eabi: scripts/setup.sh)";
    return false;
#endif
    chip = std::make_unique<ImageChip>(scheduler, TeensyModel::kTeensy41);
    std::string error;
    if (!chip->load(fixture_path(name), error)) {
      ADD_FAILURE() << error;
      return false;
    }
    chip->on_stop([this](const ImageStop& stop) { stops.push_back(stop); });
    if (before_power) before_power(*chip);
    chip->power_on(0);
    return true;
  }
  /// Runs the CPU to exactly `time_ns`: an event queued there ends its run, and the scheduler
  /// stops just before handling it (the CPU's next run, which would start a new slice there).
  void run_to(SimTime time_ns);
  /// The address of symbol `name` (fails the test if absent).
  uint32_t address_of(const std::string& name) const {
    uint32_t address = 0;
    EXPECT_TRUE(chip->symbols().find(name, address)) << "no symbol " << name;
    return address;
  }
  /// Word `index` of the array at symbol `name`.
  uint32_t word(const std::string& name, unsigned index = 0) {
    uint32_t value = 0;
    EXPECT_TRUE(chip->read_memory(address_of(name) + 4 * index, &value, 4));
    return value;
  }
};

/// Runs `action` at `time_ns` on `scheduler` (a one-off event the test owns).
class At : public Event {
 public:
  At(Scheduler& scheduler, SimTime time_ns, std::function<void()> action) : Event(&fire), action_(std::move(action)) {
    scheduler.schedule(*this, time_ns);
  }

 private:
  static void fire(Event& event, Scheduler&) { static_cast<At&>(event).action_(); }
  std::function<void()> action_;
};

}  // namespace stepdance::sim::image::testing

namespace stepdance::sim::image::testing {
inline void Fixture::run_to(SimTime time_ns) {
  At end(scheduler, time_ns, [] {});
  scheduler.run_until(time_ns - 1);
  scheduler.cancel(end);
}
}  // namespace stepdance::sim::image::testing
