// The rig's NVIC, DWT and bus routing, and the register-model entry points the backend calls.
#include "backend_rig.hpp"

#include <Arduino.h>
#include <gtest/gtest.h>

#include <cstring>
#include <map>
#include <vector>

#include "stepdance/hal/hal.hpp"
#include "stepdance/platform/teensy/regs_common.hpp"

namespace backend_rig {
namespace {

using stepdance::sim::image::BusRefusal;

constexpr unsigned kIrqs = 160;
constexpr uint32_t kCoreFirst = 0xE0000000u, kCoreLast = 0xE00FFFFFu;  // ARMv7-M PPB
constexpr uint32_t kCyccnt = 0xE0001004u;                              // DWT_CYCCNT (§C1.8.8)
constexpr uint32_t kIser = 0xE000E100u, kIcer = 0xE000E180u;           // NVIC (§B3.4)
constexpr uint32_t kIspr = 0xE000E200u, kIcpr = 0xE000E280u, kIpr = 0xE000E400u;

struct Nvic {
  void (*vectors[kIrqs])() = {};
  bool enabled[kIrqs] = {};
  bool pending[kIrqs] = {};
  uint8_t priority[kIrqs] = {};
  uint64_t taken[kIrqs] = {};
  std::vector<uint8_t> active;  // priorities of the exceptions running, innermost last
  uint32_t primask = 0;
  uint32_t basepri = 0;
  uint32_t ipsr = 0;
  std::map<uint32_t, uint32_t> core;  // other PPB registers: plain storage
  bool taking = false;
};

std::unique_ptr<World>& world_slot() {
  static std::unique_ptr<World> instance;
  return instance;
}
Nvic& nvic() {
  static Nvic instance;
  return instance;
}

bool is_pending(unsigned irq) { return nvic().pending[irq] || world().chip.level(irq); }

// The priority an interrupt must beat: the running exception's, BASEPRI's; none with PRIMASK.
int threshold() {
  const Nvic& n = nvic();
  if (n.primask) return -1;
  int limit = 256;
  if (n.basepri != 0) limit = static_cast<int>(n.basepri);
  if (!n.active.empty() && n.active.back() < limit) limit = n.active.back();
  return limit;
}

void take_interrupts() {
  Nvic& n = nvic();
  for (;;) {
    const int limit = threshold();
    int best = -1;
    for (unsigned irq = 0; irq < kIrqs; ++irq) {
      if (!n.enabled[irq] || !is_pending(irq) || n.priority[irq] >= limit) continue;
      if (best < 0 || n.priority[irq] < n.priority[best]) best = static_cast<int>(irq);
    }
    if (best < 0) return;
    n.pending[best] = false;
    n.active.push_back(n.priority[best]);
    const uint32_t saved_ipsr = n.ipsr;
    n.ipsr = 16u + static_cast<uint32_t>(best);
    ++n.taken[best];
    if (n.vectors[best] != nullptr) n.vectors[best]();
    n.ipsr = saved_ipsr;
    n.active.pop_back();
  }
}

// One instruction's worth of time passes: events due run, then interrupts are taken.
void tick() {
  World& w = world();
  w.chip.scheduler().run_until(w.chip.now_ns() + kAccessNs);
  take_interrupts();
}

void set_bits(bool* flags, uint32_t address, uint32_t first, uint32_t value, bool to) {
  const unsigned base = 32u * ((address - first) / 4u);
  for (unsigned bit = 0; bit < 32; ++bit) {
    if ((value >> bit) & 1u) flags[base + bit] = to;
  }
}

uint32_t get_bits(bool (*test)(unsigned), uint32_t address, uint32_t first) {
  const unsigned base = 32u * ((address - first) / 4u);
  uint32_t word = 0;
  for (unsigned bit = 0; bit < 32; ++bit) word |= (test(base + bit) ? 1u : 0u) << bit;
  return word;
}

bool in_block(uint32_t address, uint32_t first) { return address >= first && address < first + 0x20u; }

uint32_t core_read(uint32_t address) {
  Nvic& n = nvic();
  if (address == kCyccnt) return static_cast<uint32_t>(world().chip.cycles());
  if (in_block(address, kIser) || in_block(address, kIcer)) {
    return get_bits([](unsigned irq) { return nvic().enabled[irq]; }, address,
                    in_block(address, kIser) ? kIser : kIcer);
  }
  if (in_block(address, kIspr) || in_block(address, kIcpr)) {
    return get_bits(is_pending, address, in_block(address, kIspr) ? kIspr : kIcpr);
  }
  if (address >= kIpr && address < kIpr + kIrqs) return n.priority[address - kIpr];
  return n.core[address];
}

void core_write(uint32_t address, uint32_t value) {
  Nvic& n = nvic();
  if (in_block(address, kIser))
    set_bits(n.enabled, address, kIser, value, true);
  else if (in_block(address, kIcer))
    set_bits(n.enabled, address, kIcer, value, false);
  else if (in_block(address, kIspr))
    set_bits(n.pending, address, kIspr, value, true);
  else if (in_block(address, kIcpr))
    set_bits(n.pending, address, kIcpr, value, false);
  else if (address >= kIpr && address < kIpr + kIrqs)
    n.priority[address - kIpr] = static_cast<uint8_t>(value & 0xF0u);
  else if (address != kCyccnt)
    n.core[address] = value;
}

}  // namespace

World::World() {
  // Teensyduino's clocks at 600 MHz: IPG ÷4, PLL3 locked at 480 MHz (values as in motion_fakes.hpp).
  ccm.registers[0x14] = 0x000A8300u;
  ccm.registers[0x20] = 0x13192F06u;
  ccm.registers[0x28] = 0x0EC102C1u;  // CS1CDR reset value; the backend's power_up() sets its own
  analog.registers[0x10] = 0x80003040u;
  for (auto* block : std::initializer_list<stepdance::sim::image::Peripheral*>{&ccm, &analog, &iomuxc, &gpr, &pit}) {
    bus.add(*block);
  }
  for (auto& port : gpio) bus.add(port);
  blocks = stepdance::sim::image::add_motion_blocks(bus, chip, io, stepdance::sim::image::TeensyModel::kTeensy41);
}

World& world() {
  if (!world_slot()) world_slot() = std::make_unique<World>();
  return *world_slot();
}

World& reset() {
  World& w = world();
  w.io.frames.clear();
  w.pit.registers.clear();  // no channel held, nothing expired
  w.pit.writes.clear();
  return w;
}

void idle_for(SimTime ns) {
  World& w = world();
  const SimTime end = w.chip.now_ns() + ns;
  for (;;) {
    take_interrupts();
    if (w.chip.now_ns() >= end) return;
    SimTime next = w.chip.scheduler().next_time(end);
    if (next > end) next = end;
    w.chip.scheduler().run_until(next);
  }
}

void spin_until(SimTime until_ns) {
  while (world().chip.now_ns() < until_ns) tick();
}

uint64_t taken(unsigned irq) { return nvic().taken[irq]; }

}  // namespace backend_rig

// ---- What regs_common.hpp and regs_core.hpp call under the register-model switch ----------------
namespace stepdance::platform::teensy::register_model {

uint32_t read(uint32_t address, unsigned bytes) {
  uint32_t value = 0;
  if (address >= backend_rig::kCoreFirst && address <= backend_rig::kCoreLast) {
    value = backend_rig::core_read(address);
  } else {
    stepdance::sim::image::BusRefusal refusal;
    if (!backend_rig::world().bus.read(address, static_cast<uint8_t>(bytes), value, refusal)) {
      ADD_FAILURE() << "backend access refused: " << refusal.describe();
    }
  }
  backend_rig::tick();
  return value;
}

void write(uint32_t address, unsigned bytes, uint32_t value) {
  if (address >= backend_rig::kCoreFirst && address <= backend_rig::kCoreLast) {
    backend_rig::core_write(address, value);
  } else {
    stepdance::sim::image::BusRefusal refusal;
    if (!backend_rig::world().bus.write(address, static_cast<uint8_t>(bytes), value, refusal)) {
      ADD_FAILURE() << "backend access refused: " << refusal.describe();
    }
  }
  backend_rig::tick();
}

void barrier() {}

uint32_t read_special(const char* name) {
  const auto& n = backend_rig::nvic();
  if (std::strcmp(name, "primask") == 0) return n.primask;
  if (std::strcmp(name, "basepri") == 0) return n.basepri;
  return n.ipsr;
}

void write_special(const char* name, uint32_t value) {
  auto& n = backend_rig::nvic();
  if (std::strcmp(name, "primask") == 0) n.primask = value & 1u;
  if (std::strcmp(name, "basepri") == 0) n.basepri = value & 0xF0u;
  backend_rig::tick();  // unmasking lets a pending interrupt in at once
}

}  // namespace stepdance::platform::teensy::register_model

// ---- Teensyduino services, as the stand-in declares them, on simulated time --------------------
uint32_t micros() {
  backend_rig::tick();
  return static_cast<uint32_t>(backend_rig::world().chip.now_ns() / 1000);
}
volatile uint32_t F_CPU_ACTUAL = 600000000u;
volatile uint32_t F_BUS_ACTUAL = 150000000u;
void attachInterruptVector(IRQ_NUMBER_t irq, void (*handler)()) {
  backend_rig::nvic().vectors[static_cast<unsigned>(irq)] = handler;
}

namespace stepdance::hal {
void log_message(const char*) {}
void log_fault(const char*, const char*) {}
// The backend's safe state (safe_state.cpp) drives pads these tests do not model; a fault the core
// reports here fails the test instead.
void enter_safe_state() { ADD_FAILURE() << "the core entered the safe state"; }
}  // namespace stepdance::hal
