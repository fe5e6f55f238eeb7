// The register model's memory, log and hooks, and the few Teensyduino services the backend calls
// (micros, the clock rates, attachInterruptVector), all driven by the model time.
#include "register_model.hpp"

#include <Arduino.h>

#include <cstring>
#include <map>

#include "stepdance/platform/teensy/regs_common.hpp"

namespace teensy_model {
namespace {

constexpr uint32_t kCycleCounter = 0xE0001004u;  // DWT_CYCCNT

struct State {
  std::map<uint32_t, uint32_t> words;  // 4-byte aligned address → word
  std::vector<Access> log;
  std::map<uint32_t, WriteHook> write_hooks;
  std::map<uint32_t, ReadHook> read_hooks;
  void (*vectors[256])() = {};
  uint64_t cycles = 0;
  uint32_t primask = 0;
  uint32_t basepri = 0;
  uint32_t ipsr = 0;
};

State& state() {
  static State instance;
  return instance;
}

uint32_t lane_mask(unsigned bytes) { return bytes == 4 ? 0xFFFFFFFFu : (1u << (8u * bytes)) - 1u; }

void record(Access::Kind kind, uint32_t address, uint32_t value, const char* special) {
  State& s = state();
  s.log.push_back(Access{kind, address, value, special, s.primask, s.basepri, s.cycles});
}

}  // namespace

void reset() {
  State& s = state();
  s.words.clear();
  s.log.clear();
  s.write_hooks.clear();
  s.read_hooks.clear();
  std::memset(s.vectors, 0, sizeof(s.vectors));
  s.cycles = 0;
  s.primask = s.basepri = s.ipsr = 0;
}

uint32_t peek(uint32_t address, unsigned bytes) {
  const uint32_t word = state().words[address & ~3u];
  return (word >> (8u * (address & 3u))) & lane_mask(bytes);
}

void poke(uint32_t address, uint32_t value, unsigned bytes) {
  uint32_t& word = state().words[address & ~3u];
  const unsigned shift = 8u * (address & 3u);
  word = (word & ~(lane_mask(bytes) << shift)) | ((value & lane_mask(bytes)) << shift);
}

const std::vector<Access>& log() { return state().log; }
void on_write(uint32_t address, WriteHook hook) { state().write_hooks[address] = std::move(hook); }
void on_read(uint32_t address, ReadHook hook) { state().read_hooks[address] = std::move(hook); }
void write_one_to_clear(uint32_t address) {
  on_write(address, [](uint32_t stored, uint32_t written) { return stored & ~written; });
}
uint64_t now_cycles() { return state().cycles; }
void advance_cycles(uint64_t cycles) { state().cycles += cycles; }
void (*vector(unsigned irq))() { return state().vectors[irq]; }
uint32_t primask() { return state().primask; }
uint32_t basepri() { return state().basepri; }

void run_isr(unsigned irq) {
  State& s = state();
  const uint32_t saved = s.ipsr;
  s.ipsr = 16u + irq;
  if (s.vectors[irq] != nullptr) s.vectors[irq]();
  s.ipsr = saved;
}

}  // namespace teensy_model

// ---- The backend's side: what regs_common.hpp and regs_core.hpp call under the model switch ----
namespace stepdance::platform::teensy::register_model {

uint32_t read(uint32_t address, unsigned bytes) {
  auto& s = teensy_model::state();
  if (address == teensy_model::kCycleCounter) s.cycles += 10;
  uint32_t value = teensy_model::peek(address, bytes);
  const auto hook = s.read_hooks.find(address);
  if (hook != s.read_hooks.end()) value = hook->second(value);
  if (address == teensy_model::kCycleCounter) value = static_cast<uint32_t>(s.cycles);
  teensy_model::record(teensy_model::Access::kRead, address, value, nullptr);
  return value;
}

void write(uint32_t address, unsigned bytes, uint32_t value) {
  auto& s = teensy_model::state();
  teensy_model::record(teensy_model::Access::kWrite, address, value, nullptr);
  uint32_t stored = value;
  const auto hook = s.write_hooks.find(address);
  if (hook != s.write_hooks.end()) stored = hook->second(teensy_model::peek(address, bytes), value);
  teensy_model::poke(address, stored, bytes);
}

void barrier() {}

uint32_t read_special(const char* name) {
  auto& s = teensy_model::state();
  if (std::strcmp(name, "primask") == 0) return s.primask;
  if (std::strcmp(name, "basepri") == 0) return s.basepri;
  return s.ipsr;
}

void write_special(const char* name, uint32_t value) {
  auto& s = teensy_model::state();
  if (std::strcmp(name, "primask") == 0) s.primask = value & 1u;
  if (std::strcmp(name, "basepri") == 0) s.basepri = value & 0xF0u;
  teensy_model::record(teensy_model::Access::kSpecialWrite, 0, value, name);
}

}  // namespace stepdance::platform::teensy::register_model

// ---- Teensyduino services, as the stand-in declares them, on the model time ---------------------
// Left out where the stand-in core's own definitions are under test (stand_in_test.cpp).
#if !defined(TEENSY_MODEL_WITHOUT_SERVICES)
uint32_t micros() {
  teensy_model::advance_cycles(10);
  return static_cast<uint32_t>(teensy_model::now_cycles() / (teensy_model::kCoreHz / 1000000u));
}
volatile uint32_t F_CPU_ACTUAL = teensy_model::kCoreHz;
volatile uint32_t F_BUS_ACTUAL = teensy_model::kBusHz;
void attachInterruptVector(IRQ_NUMBER_t irq, void (*handler)()) {
  teensy_model::state().vectors[static_cast<unsigned>(irq)] = handler;
}
#endif
