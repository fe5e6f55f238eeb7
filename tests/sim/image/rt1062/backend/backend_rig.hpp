// A host "CPU" for the Teensy backend's own code against the RT1062 motion-block models.
//
// The backend is compiled with STEPDANCE_TEENSY_REGISTER_MODEL, so each of its register accesses,
// DSBs and PRIMASK/BASEPRI/IPSR accesses calls this rig. The rig sends peripheral accesses
// through a PeripheralBus holding the models under test (FLEXIO3, …) and plain storage for the
// blocks other parts model (CCM, IOMUXC, GPIO); it keeps a small NVIC (enables, pending,
// priorities, PRIMASK/BASEPRI masking, preemption) and the DWT cycle counter. Every access costs
// kAccessNs of simulated time, after which due scheduler events run and pending interrupts are
// taken, as between two instructions. A refused access fails the running test, naming it.
#pragma once

#include <cstdint>
#include <memory>

#include "image/rt1062/motion_blocks.hpp"
#include "motion_fakes.hpp"

namespace backend_rig {

using stepdance::sim::SimTime;

/// Simulated time one register access (or micros() call) takes.
constexpr SimTime kAccessNs = 10;

/// The world: chip, board I/O, bus, storage blocks and the models. One per test (reset()).
struct World {
  World();
  stepdance::sim::image::testing::FakeChip chip;
  stepdance::sim::image::testing::FakeIo io;
  stepdance::sim::image::testing::FakeClockBlock ccm{"CCM", 0x400FC000u};
  stepdance::sim::image::testing::FakeClockBlock analog{"CCM_ANALOG", 0x400D8000u};
  stepdance::sim::image::testing::FakeClockBlock iomuxc{"IOMUXC", 0x401F8000u};
  stepdance::sim::image::testing::FakeClockBlock gpr{"IOMUXC_GPR", 0x400AC000u};
  stepdance::sim::image::testing::FakePit pit;
  stepdance::sim::image::testing::FakeClockBlock gpio[4] = {
      {"GPIO6", 0x42000000u}, {"GPIO7", 0x42004000u}, {"GPIO8", 0x42008000u}, {"GPIO9", 0x4200C000u}};
  stepdance::sim::image::PeripheralBus bus;
  std::unique_ptr<stepdance::sim::image::MotionBlocks> blocks;
};

/// A fresh world and NVIC (vectors, enables, pending, masks cleared). Call first in each test.
World& reset();
/// The current world.
World& world();
/// Lets simulated time pass with the CPU idle in thread mode (the sketch's loop waiting): runs
/// events and takes interrupts as they come, until `ns` from now.
void idle_for(SimTime ns);
/// Spins (as a busy loop would) until simulated time reaches `until_ns`, taking interrupts.
void spin_until(SimTime until_ns);
/// Interrupts taken so far, per IRQ number.
uint64_t taken(unsigned irq);

}  // namespace backend_rig
