// The HAL conformance suite on the simulator backend (src/stepdance/platform/sim), outside a
// board's shared object: its sources are linked into this test, and a fake host behind the board
// ABI (abi/board_abi.h, StepdanceHostV1) plays the simulator's side.
//
// The fake host does what the ABI's comments say the simulator does, and nothing more: time is
// what the last entry brought, a frame handed over is played from the next frame tick, a port
// plays nothing in a tick it was given nothing for (and nothing at all while the frame timer is
// stopped), timers fire at their periods, pins, counts, conversions, console bytes and files are
// kept as given. What the suite checks is the board half: that the backend turns every hal::
// call into the ABI's calls and back without changing a value, an order or a unit.
#include <cmath>
#include <deque>
#include <map>

#include "hal_contract.hpp"
#include "stepdance/platform/sim/host_link.hpp"
#include "stepdance/platform/sim/sim_hal.hpp"

namespace hal_conformance {
namespace {

namespace sim_runtime = ::stepdance::sim_runtime;

constexpr int kOk = 0;
constexpr int kBadArgument = static_cast<int>(Status::kBadArgument);
constexpr int kBusy = static_cast<int>(Status::kBusy);
constexpr int kIoError = static_cast<int>(Status::kIoError);

// ---- The fake simulator ----------------------------------------------------------------------
struct FakeSimulator {
  int64_t now_ns = 0;
  uint32_t frame_period_us = 0;  // 0: not running
  uint32_t khz_period_us = 0;
  int64_t next_khz_ns = 0;
  uint8_t claimed = 0;
  FrameWords given[4] = {};    // handed over since the last tick
  FrameWords playing[4] = {};  // launched at the last tick
  int32_t counts[2] = {};
  std::map<uint8_t, uint16_t> adc;
  std::map<uint8_t, uint32_t> adc_samples;
  std::map<uint8_t, int> modes;
  std::map<uint8_t, bool> driven;   // by the board (outputs)
  std::map<uint8_t, bool> outside;  // by the world (inputs)
  bool safe = false;
  std::deque<uint8_t> console_in;
  std::string console_out;
  std::map<std::string, std::string> files;
  struct Open {
    std::string name;
    size_t offset;
    bool open;
  };
  std::vector<Open> handles;
};
FakeSimulator sim;

int timer_start(void*, int timer, uint32_t period_us) {
  if (period_us == 0) return kBadArgument;
  if (timer == STEPDANCE_TIMER_FRAME) {
    sim.frame_period_us = period_us;
  } else {
    sim.khz_period_us = period_us;
    sim.next_khz_ns = sim.now_ns + int64_t{period_us} * 1000;
  }
  return kOk;
}
void timers_stop(void*) { sim.frame_period_us = sim.khz_period_us = 0; }
int64_t delay_ns(void*, int64_t duration) { return sim.now_ns += duration; }
int port_out_begin(void*, uint8_t port) {
  if (sim.claimed & (1u << port)) return kBusy;
  sim.claimed = static_cast<uint8_t>(sim.claimed | (1u << port));
  return kOk;
}
void port_out_frame(void*, uint8_t port, uint32_t step, uint32_t dir) { sim.given[port] = {step, dir}; }
int port_in_begin(void*, uint8_t, int) { return kOk; }
int quadrature_begin(void*, uint8_t) { return kOk; }
int32_t quadrature_read(void*, uint8_t index) { return sim.counts[index]; }
void quadrature_write(void*, uint8_t index, int32_t count) { sim.counts[index] = count; }
int adc_begin(void*, uint8_t) { return kOk; }
uint16_t adc_read(void*, uint8_t pin) { return sim.adc[pin]; }
uint32_t adc_sample_count(void*, uint8_t pin) { return sim.adc_samples[pin]; }
int gpio_mode(void*, uint8_t pin, int mode) {
  sim.modes[pin] = mode;
  return kOk;
}
int gpio_read(void*, uint8_t pin) {
  const bool output = sim.modes[pin] == static_cast<int>(stepdance::hal::PinMode::kOutput);
  return (output ? sim.driven[pin] : sim.outside[pin]) ? 1 : 0;
}
void gpio_write(void*, uint8_t pin, int high) { sim.driven[pin] = high != 0; }
void enter_safe_state(void*) { sim.safe = true; }
void log_fault(void*, const char*, const char*) {}
size_t console_write(void*, const uint8_t* data, size_t length) {
  sim.console_out.append(reinterpret_cast<const char*>(data), length);
  return length;
}
size_t console_available(void*) { return sim.console_in.size(); }
int console_read(void*) {
  if (sim.console_in.empty()) return -1;
  const int byte = sim.console_in.front();
  sim.console_in.pop_front();
  return byte;
}
int file_open(void*, const char* name, int mode, int* handle) {
  if (mode == STEPDANCE_FILE_READ && sim.files.count(name) == 0) return kIoError;
  if (mode == STEPDANCE_FILE_WRITE) sim.files[name].clear();
  const size_t offset = mode == STEPDANCE_FILE_READ ? 0 : sim.files[name].size();
  sim.handles.push_back({name, offset, true});
  *handle = static_cast<int>(sim.handles.size() - 1);
  return kOk;
}
bool valid(int handle) {
  return handle >= 0 && static_cast<size_t>(handle) < sim.handles.size() && sim.handles[handle].open;
}
int file_read(void*, int handle, uint8_t* data, size_t length, size_t* read) {
  *read = 0;
  if (!valid(handle)) return kBadArgument;
  FakeSimulator::Open& file = sim.handles[handle];
  const std::string& bytes = sim.files[file.name];
  *read = std::min(length, bytes.size() - file.offset);
  bytes.copy(reinterpret_cast<char*>(data), *read, file.offset);
  file.offset += *read;
  return kOk;
}
int file_write(void*, int handle, const uint8_t* data, size_t length) {
  if (!valid(handle)) return kBadArgument;
  sim.files[sim.handles[handle].name].append(reinterpret_cast<const char*>(data), length);
  return kOk;
}
int file_close(void*, int handle) {
  if (!valid(handle)) return kBadArgument;
  sim.handles[handle].open = false;
  return kOk;
}
int i2c_begin(void*, uint8_t, uint32_t) { return static_cast<int>(Status::kUnsupported); }
int i2c_transfer(void*, uint8_t, uint8_t, const uint8_t*, size_t, uint8_t*, size_t, int64_t* wire_ns) {
  *wire_ns = 0;
  return 3;  // address NACK: no devices on the fake's buses
}
void sketch_ended(void*, int, int) {}

StepdanceHostV1 make_table() {
  StepdanceHostV1 table{};
  table.abi_version = STEPDANCE_BOARD_ABI_VERSION;
  table.timer_start = &timer_start;
  table.timers_stop = &timers_stop;
  table.delay_ns = &delay_ns;
  table.port_out_begin = &port_out_begin;
  table.port_out_frame = &port_out_frame;
  table.port_in_begin = &port_in_begin;
  table.quadrature_begin = &quadrature_begin;
  table.quadrature_read = &quadrature_read;
  table.quadrature_write = &quadrature_write;
  table.adc_begin = &adc_begin;
  table.adc_read = &adc_read;
  table.adc_sample_count = &adc_sample_count;
  table.gpio_mode = &gpio_mode;
  table.gpio_read = &gpio_read;
  table.gpio_write = &gpio_write;
  table.enter_safe_state = &enter_safe_state;
  table.log_fault = &log_fault;
  table.console_write = &console_write;
  table.console_available = &console_available;
  table.console_read = &console_read;
  table.file_open = &file_open;
  table.file_read = &file_read;
  table.file_write = &file_write;
  table.file_close = &file_close;
  table.i2c_begin = &i2c_begin;
  table.i2c_transfer = &i2c_transfer;
  table.sketch_ended = &sketch_ended;
  return table;
}
const StepdanceHostV1 kTable = make_table();

// ---- The adapter -----------------------------------------------------------------------------
struct SimAdapter {
  // The simulator backend's skip list: empty; every clause runs.
  static const char* skip_reason(Clause) { return nullptr; }

  static void reset() {
    stepdance::hal::timers_stop();
    sim = FakeSimulator{};
    sim_runtime::attach_host(&kTable, &sim);
    sim_runtime::set_now_ns(0);
  }
  static void settle() {}
  static void advance_us(uint32_t us) { sim_runtime::set_now_ns(sim.now_ns += int64_t{us} * 1000); }

  // One frame tick as the simulator's scheduler runs it: the handed-over frames start on the
  // wire, then the frame ISR, then (when its period is up) the kilohertz ISR.
  static void tick() {
    sim_runtime::set_now_ns(sim.now_ns += int64_t{kFramePeriodUs} * 1000);
    for (uint8_t port = 0; port < 4; ++port) {  // no frame timer, no frame ticks: nothing shifts
      sim.playing[port] = sim.frame_period_us != 0 ? sim.given[port] : FrameWords{0, 0};
      sim.given[port] = {0, 0};
    }
    if (sim.frame_period_us != 0) sim_runtime::run_frame_isr();
    if (sim.khz_period_us != 0 && sim.now_ns >= sim.next_khz_ns) {
      sim.next_khz_ns += int64_t{sim.khz_period_us} * 1000;
      sim_runtime::run_khz_isr();
    }
  }
  static FrameWords launched(uint8_t port) { return sim.playing[port]; }

  static void inject_pulse(uint8_t port, const stepdance::protocol::CapturedPulse& pulse) {
    const StepdanceCapturedPulseV1 abi{pulse.rise_ticks, pulse.fall_ticks, static_cast<uint8_t>(pulse.dir_high),
                                       pulse.extra_periods};
    sim_runtime::deliver_captured_pulse(port, abi);
  }
  static void set_quadrature(uint8_t index, int32_t count) { sim.counts[index] = count; }
  static void set_adc_fraction(uint8_t pin, double fraction) {
    sim.adc[pin] = static_cast<uint16_t>(std::lround(fraction * kAdcFullScale));
    ++sim.adc_samples[pin];
  }
  static void drive_pin(uint8_t pin, bool high) { sim.outside[pin] = high; }
  static void feed_console(const std::string& bytes) {
    sim.console_in.insert(sim.console_in.end(), bytes.begin(), bytes.end());
  }
  static std::string take_console_output() {
    std::string out;
    out.swap(sim.console_out);
    return out;
  }
  static bool drivers_disabled() { return sim.safe; }
};

}  // namespace

INSTANTIATE_TYPED_TEST_SUITE_P(Sim, HalContract, SimAdapter);

}  // namespace hal_conformance
