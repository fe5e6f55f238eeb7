// The CI stand-in core's start-up (targets/teensy/stand-in/) booting on the emulated i.MX RT1062:
// ImageChip with the clock, pin, motion and USB blocks wired as an image board wires them, running
// stand_in_boot_sketch.cpp (built by sim/image/CMakeLists.txt with the stand-in's sources).
//
// Expected values are the start-up's targets, not read from its code: the 600 MHz core and 150 MHz
// IPG clock of a Teensy 4 (RM §14 clock tree), SysTick milliseconds (ARMv7-M ARM §B3.3) that
// follow simulated time, delay() and delayMicroseconds() as long as asked, pin 13 driven high.
#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <string>

#include "image/chip/board_io.hpp"
#include "image/cpu/image_chip.hpp"
#include "image/rt1062/clock_and_pin_blocks.hpp"
#include "image/rt1062/motion_blocks.hpp"
#include "image/usb/usb_blocks.hpp"
#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image {
namespace {

/// The world side: remembers driven pin levels, answers nothing else.
class QuietWorld : public BoardIo {
 public:
  void pin_config(SimTime, uint8_t, PinConfig) override {}
  void pin_drive(SimTime, uint8_t pin, bool high) override { driven[pin] = high; }
  bool pin_level(SimTime, uint8_t pin) override { return driven.count(pin) != 0 && driven[pin]; }
  void port_frame(uint8_t, SimTime, const protocol::FrameWords&, SimTime) override {}
  int64_t encoder_counts(SimTime, uint8_t) override { return 0; }
  uint16_t analog_level(SimTime, uint8_t) override { return 0; }
  int i2c_transfer(SimTime, uint8_t, uint32_t, uint8_t, const uint8_t*, size_t, uint8_t*, size_t, SimTime&) override {
    return 3;  // nobody answers
  }
  size_t serial_from_device(SimTime, const uint8_t*, size_t length) override { return length; }
  size_t serial_to_device(SimTime, uint8_t*, size_t) override { return 0; }
  std::map<uint8_t, bool> driven;
};

struct BootedImage {
  Scheduler scheduler;
  QuietWorld world;
  ImageChip chip{scheduler, TeensyModel::kTeensy41};
  std::unique_ptr<rt1062::ClockAndPinBlocks> clocks;
  std::unique_ptr<MotionBlocks> motion;
  std::unique_ptr<usb::UsbBlocks> usb;
  std::string stop;

  bool boot(SimTime run_ns) {
    std::string error;
    if (!chip.load(std::string(STEPDANCE_BUILD_DIR) + "/tests/sim/image/startup/stand_in_boot.elf", error)) {
      ADD_FAILURE() << error;
      return false;
    }
    clocks = rt1062::add_clock_and_pin_blocks(chip.bus(), chip, world, TeensyModel::kTeensy41);
    motion = add_motion_blocks(chip.bus(), chip, world, TeensyModel::kTeensy41);
    usb = usb::add_usb_blocks(chip.bus(), chip, world);
    clocks->apply_boot_rom_clocks();
    clocks->ccm.add_rates_listener([this](const rt1062::ClockRates& rates) {
      if (rates.core_hz != 0) chip.set_core_clock_hz(rates.core_hz);
    });
    chip.on_stop([this](const ImageStop& s) { stop = s.what + " in " + s.symbol; });
    chip.power_on(0);
    scheduler.run_until(run_ns);
    return true;
  }
  uint32_t word(const char* symbol) {
    uint32_t address = 0, value = 0;
    EXPECT_TRUE(chip.symbols().find(symbol, address)) << symbol;
    chip.read_memory(address, &value, 4);
    return value;
  }
};

TEST(StandInBoot, StartUpRunsTheSketchAt600MHzWithSysTickTime) {
#ifdef STEPDANCE_NO_ARM_GCC
  GTEST_SKIP() << "arm-none-eabi-g++ was not found when the tree was configured";
#endif
  BootedImage image;
  ASSERT_TRUE(image.boot(20 * kMillisecond));
  EXPECT_EQ(image.stop, "");
  EXPECT_EQ(image.word("boot_stage"), 2u) << "setup() ran, then loop()";
  EXPECT_EQ(image.chip.core_clock_hz(), 600000000u);
  EXPECT_EQ(image.word("boot_cpu_hz"), 600000000u);
  EXPECT_EQ(image.word("boot_bus_hz"), 150000000u);
  EXPECT_GE(image.word("boot_delay_us"), 5000u);
  EXPECT_LE(image.word("boot_delay_us"), 5002u);
  EXPECT_GE(image.word("boot_delay_microseconds_us"), 250u);
  EXPECT_LE(image.word("boot_delay_microseconds_us"), 251u);
  EXPECT_EQ(image.world.driven[13], true) << "pin 13 driven high";
  EXPECT_EQ(image.word("stand_in_adc_calibration_failed"), 0u);
  // One SysTick per millisecond since it started, and it starts within the first millisecond (the
  // start-up is some 50 000 instructions): 19 or 20 in 20 ms of simulated time.
  const uint64_t ticks = image.chip.handler_cost(15).entries;
  const uint32_t at_setup = image.word("boot_millis_at_setup");
  EXPECT_LE(at_setup, 1u) << "setup() starts right after the start-up";
  EXPECT_GE(ticks, 19u);
  EXPECT_LE(ticks, 20u);
}

}  // namespace
}  // namespace stepdance::sim::image
