// The Arduino backend hooks on the manual backend: delays run frames, serial ports are memory.
#if defined(STEPDANCE_PLATFORM_MANUAL)

#include "arduino_manual.hpp"

#include <array>
#include <deque>

#include "IntervalTimer.h"
#include "hal_manual.hpp"
#include "stepdance/core/units.hpp"

namespace stepdance {
namespace {

// A serial port's far end: bytes for the sketch, bytes from it, and an optional size limit.
// A finite capacity lets a test model a full USB buffer: write_bytes() then accepts only what fits, the
// way a real port's non-blocking write does, so reply queues can be tested for loss.
class MemoryPort final : public ByteStream {
 public:
  size_t bytes_available() override { return incoming.size(); }
  int read_byte() override {
    if (incoming.empty()) return -1;
    const int byte = static_cast<uint8_t>(incoming.front());
    incoming.pop_front();
    return byte;
  }
  size_t write_bytes(const uint8_t* data, size_t length) override {
    const size_t room = write_space();
    const size_t accepted = length < room ? length : room;
    outgoing.append(reinterpret_cast<const char*>(data), accepted);
    return accepted;
  }
  size_t write_space() override { return outgoing.size() < capacity ? capacity - outgoing.size() : 0; }

  std::deque<char> incoming;
  std::string outgoing;
  size_t capacity = static_cast<size_t>(-1);
  bool connected = true;
};

// delayed_us and delay_calls let a test check that a sketch waited (and how long) without real time.
struct ManualArduino {
  std::array<MemoryPort, arduino_backend::kSerialPortCount> ports;
  uint64_t delayed_us = 0;
  uint32_t delay_calls = 0;
};

ManualArduino the_state;

MemoryPort& port_of(arduino_backend::SerialPortId port) { return the_state.ports.at(static_cast<size_t>(port)); }

}  // namespace

namespace arduino_backend {

// A sketch's delay() on the manual backend advances simulated time by running whole frames (and the
// kilohertz tick with them), the order the simulator uses, so a sketch that waits in setup() or loop()
// sees its motion progress as on a board. The remainder below one frame only moves the clock.
void delay_us(uint32_t us) {
  the_state.delayed_us += us;
  ++the_state.delay_calls;
  for (uint32_t frame = 0; frame < us / frame_period_us(); ++frame) {
    hal_manual::run_frames(1);
    arduino::run_interval_timers();  // as the simulator does at each frame tick
  }
  hal_manual::advance_us(us % frame_period_us());
  arduino::run_interval_timers();
}

// A disconnected port returns no stream, as an unplugged USB serial would: Serial reads nothing and
// `if (Serial)` is false.
ByteStream* serial_stream(SerialPortId port) {
  MemoryPort& memory = port_of(port);
  return memory.connected ? &memory : nullptr;
}

}  // namespace arduino_backend

namespace arduino_manual {

// Takes (and clears) what the sketch wrote, so each test step sees only its own replies.
std::string take_serial_output(arduino_backend::SerialPortId port) {
  std::string out;
  out.swap(port_of(port).outgoing);
  return out;
}

void feed_serial(arduino_backend::SerialPortId port, const std::string& bytes) {
  MemoryPort& memory = port_of(port);
  memory.incoming.insert(memory.incoming.end(), bytes.begin(), bytes.end());
}

void set_serial_connected(arduino_backend::SerialPortId port, bool connected) { port_of(port).connected = connected; }

void set_serial_write_space(arduino_backend::SerialPortId port, size_t bytes) { port_of(port).capacity = bytes; }

uint64_t delayed_us() { return the_state.delayed_us; }
uint32_t delay_calls() { return the_state.delay_calls; }

void reset() {
  for (MemoryPort& memory : the_state.ports) memory = MemoryPort{};
  the_state.delayed_us = 0;
  the_state.delay_calls = 0;
}

// One call for a test fixture: HAL board, serial ports and the Arduino layer's globals (timers, pins).
void reset_all(uint32_t start_us) {
  hal_manual::reset(start_us);
  reset();
  arduino::reset_state();
}

}  // namespace arduino_manual
}  // namespace stepdance

#endif  // STEPDANCE_PLATFORM_MANUAL
