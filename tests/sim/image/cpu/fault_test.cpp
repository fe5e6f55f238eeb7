// Faults and stalls stop the image with the fault, the faulting PC, its function and a
// backtrace; exit status 5, or 6 for no progress (docs/simulator.md). One fixture per kind
// (tests/sim/image/fixtures/fault_*.c).
#include "fixture.hpp"
#include "test_device.hpp"

namespace stepdance::sim::image::testing {
namespace {

// Boots `name`, runs 10 ms of simulated time, and returns its one stop.
ImageStop run_to_stop(Fixture& fixture, const std::string& name) {
  if (!fixture.boot(name)) return {};
  fixture.scheduler.run_until(10 * kMillisecond);
  EXPECT_EQ(fixture.stops.size(), 1u) << name << " did not stop once";
  return fixture.stops.empty() ? ImageStop{} : fixture.stops[0];
}

// The stop's PC lies inside function `function` (by the ELF's symbol table), and the report
// names it and its caller.
void expect_in(const Fixture& fixture, const ImageStop& stop, const std::string& function) {
  EXPECT_EQ(stop.symbol, function) << stop.what;
  const uint32_t start = fixture.address_of(function);
  EXPECT_GE(stop.pc, start);
  EXPECT_LT(stop.pc, start + 64);
  ASSERT_FALSE(stop.backtrace.empty());
  char pc_text[16];
  std::snprintf(pc_text, sizeof pc_text, "0x%08X", stop.pc);
  EXPECT_EQ(stop.backtrace[0].rfind(std::string(pc_text) + " " + function + "+0x", 0), 0u) << stop.backtrace[0];
}

bool mentions(const std::vector<std::string>& frames, const std::string& function) {
  for (const std::string& frame : frames) {
    if (frame.find(" " + function + "+") != std::string::npos) return true;
  }
  return false;
}

TEST(ImageChipFault, AnUndefinedInstructionIsAUsageFault) {
  Fixture f;
  const ImageStop stop = run_to_stop(f, "fault_undefined");
  EXPECT_EQ(stop.kind, ImageStop::Kind::kUsageFault);
  EXPECT_NE(stop.what.find("undefined instruction"), std::string::npos) << stop.what;
  expect_in(f, stop, "undefined_here");
  EXPECT_TRUE(mentions(stop.backtrace, "main"));
  EXPECT_EQ(stop.exit_code, 5);
  uint16_t instruction = 0;
  ASSERT_TRUE(f.chip->read_memory(stop.pc, &instruction, 2));
  EXPECT_EQ(instruction, 0xDE07);                                   // the UDF #7 itself
  EXPECT_EQ(f.chip->core_registers().cfsr & (1u << 16), 1u << 16);  // UFSR.UNDEFINSTR
}

TEST(ImageChipFault, AFaultWhoseHandlerIsDisabledEscalatesToHardFault) {
  Fixture f;
  const ImageStop stop = run_to_stop(f, "fault_escalated");
  EXPECT_EQ(stop.kind, ImageStop::Kind::kHardFault);
  EXPECT_NE(stop.what.find("escalated"), std::string::npos) << stop.what;
  EXPECT_NE(stop.what.find("undefined instruction"), std::string::npos) << stop.what;
  expect_in(f, stop, "undefined_here");
  EXPECT_EQ(f.chip->core_registers().hfsr & (1u << 30), 1u << 30);  // HFSR.FORCED
}

TEST(ImageChipFault, ADivideByZeroWithDiv0TrpIsAUsageFault) {
  Fixture f;
  const ImageStop stop = run_to_stop(f, "fault_divide");
  EXPECT_EQ(stop.kind, ImageStop::Kind::kUsageFault);
  EXPECT_NE(stop.what.find("divide by zero"), std::string::npos) << stop.what;
  expect_in(f, stop, "divide_here");
  uint16_t instruction = 0;
  ASSERT_TRUE(f.chip->read_memory(stop.pc, &instruction, 2));
  EXPECT_EQ(instruction & 0xFFF0, 0xFB90);                          // SDIV
  EXPECT_EQ(f.chip->core_registers().cfsr & (1u << 25), 1u << 25);  // UFSR.DIVBYZERO
}

TEST(ImageChipFault, AReadWhereNoMemoryIsIsABusFault) {
  Fixture f;
  const ImageStop stop = run_to_stop(f, "fault_bus");
  EXPECT_EQ(stop.kind, ImageStop::Kind::kBusFault);
  EXPECT_NE(stop.what.find("read of 4 bytes at 0x30000000"), std::string::npos) << stop.what;
  expect_in(f, stop, "read_unmapped");
  EXPECT_EQ(f.chip->core_registers().bfar, 0x30000000u);
}

TEST(ImageChipFault, ABlockAnsweringWithABusErrorIsABusFault) {
  Fixture f;
  std::unique_ptr<TestDevice> device;
  ASSERT_TRUE(f.boot("fault_device", [&device](ImageChip& chip) {
    device = std::make_unique<TestDevice>(chip);
    chip.bus().add(*device);
  }));
  f.scheduler.run_until(1 * kMillisecond);
  ASSERT_EQ(f.stops.size(), 1u);
  const ImageStop& stop = f.stops[0];
  EXPECT_EQ(stop.kind, ImageStop::Kind::kBusFault);
  EXPECT_NE(stop.what.find("0x40100014 (TESTDEV+0x14): the block answers with a bus error"), std::string::npos)
      << stop.what;
  expect_in(f, stop, "read_device");
  EXPECT_EQ(f.chip->core_registers().bfar, 0x40100014u);
}

TEST(ImageChipFault, AnAccessTheMpuForbidsIsAMemManageFault) {
  Fixture f;
  const ImageStop stop = run_to_stop(f, "fault_memmanage");
  EXPECT_EQ(stop.kind, ImageStop::Kind::kMemManage);
  EXPECT_NE(stop.what.find("0x20200010"), std::string::npos) << stop.what;
  expect_in(f, stop, "touch_guarded");
  EXPECT_EQ(f.chip->core_registers().mmfar, 0x20200010u);
}

TEST(ImageChipFault, EndlessRecursionOverflowsTheStack) {
  Fixture f;
  const ImageStop stop = run_to_stop(f, "fault_stack");
  EXPECT_EQ(stop.kind, ImageStop::Kind::kStackOverflow) << stop.what;
  EXPECT_EQ(stop.symbol, "recurse") << stop.what;
  EXPECT_EQ(stop.exit_code, 5);
  EXPECT_TRUE(mentions(stop.backtrace, "recurse"));
  // The stack's bottom is _ebss; SP went below it by at most one frame.
  const uint32_t sp = f.chip->read_register(UC_ARM_REG_SP);
  EXPECT_LT(sp, f.address_of("_ebss"));
  EXPECT_GT(sp + 128, f.address_of("_ebss"));
}

TEST(ImageChipFault, TheStackGuardRegionIsTheStacksBottom) {
  Fixture f;
  const ImageStop stop = run_to_stop(f, "fault_stack_guard");
  EXPECT_EQ(stop.kind, ImageStop::Kind::kStackOverflow) << stop.what;
  EXPECT_EQ(stop.symbol, "recurse");
  char bottom[16];
  std::snprintf(bottom, sizeof bottom, "0x%08X", f.address_of("_ebss") + 32);  // the guard's top
  EXPECT_NE(stop.what.find(std::string("bottom ") + bottom), std::string::npos) << stop.what;
}

TEST(ImageChipFault, ASpinWithInterruptsMaskedIsNoProgress) {
  Fixture f;
  const ImageStop stop = run_to_stop(f, "fault_stall");
  EXPECT_EQ(stop.kind, ImageStop::Kind::kNoProgress);
  expect_in(f, stop, "stall");
  EXPECT_EQ(stop.exit_code, 6);
  EXPECT_LT(stop.time_ns, 1 * kMillisecond);  // found at once, not at the end of the run
}

TEST(ImageChipFault, SleepingWithNothingToWakeTheCoreIsNoProgress) {
  Fixture f;
  const ImageStop stop = run_to_stop(f, "fault_sleep");
  EXPECT_EQ(stop.kind, ImageStop::Kind::kNoProgress);
  EXPECT_NE(stop.what.find("WFI"), std::string::npos) << stop.what;
  EXPECT_EQ(stop.symbol, "sleep_forever");
  EXPECT_EQ(stop.exit_code, 6);
}

TEST(ImageChipFault, AnUnmodelledRegisterStopsTheRunNamingIt) {
  Fixture f;
  const ImageStop stop = run_to_stop(f, "fault_unmodelled");
  EXPECT_EQ(stop.kind, ImageStop::Kind::kUnmodelledAccess);
  EXPECT_NE(stop.what.find("read of 4 bytes at 0x400AC044"), std::string::npos) << stop.what;
  expect_in(f, stop, "read_gpr17");
  EXPECT_EQ(stop.exit_code, 5);
}

}  // namespace
}  // namespace stepdance::sim::image::testing
