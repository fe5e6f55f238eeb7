// The manual host backend of the HAL facade: deterministic, single-threaded, driven by tests.
#if defined(STEPDANCE_PLATFORM_MANUAL)

#include "hal_manual.hpp"

#include <array>
#include <cstring>
#include <deque>
#include <map>
#include <vector>

#include "stepdance/core/byte_stream.hpp"
#include "stepdance/core/units.hpp"
#include "stepdance/hal/console.hpp"
#include "stepdance/hal/nonvolatile.hpp"
#include "stepdance/hal/storage.hpp"

namespace stepdance {
namespace {

constexpr uint8_t kPorts = 4;
constexpr uint8_t kEncoders = 2;

struct InputPortState {
  bool begun = false;
  protocol::DirSampleEdge edge = protocol::DirSampleEdge::kFalling;
  hal::PulseSink sink = nullptr;
  void* context = nullptr;
};

struct PinState {
  hal::PinMode mode = hal::PinMode::kInput;
  bool level = false;
  bool configured = false;
  uint16_t adc = 0;
  uint32_t adc_samples = 0;
  bool adc_begun = false;
};

// The console never fills (1 MiB of space), so log messages are never dropped in a test.
class ConsoleStream final : public ByteStream {
 public:
  size_t bytes_available() override { return input.size(); }
  int read_byte() override {
    if (input.empty()) return -1;
    const int byte = static_cast<uint8_t>(input.front());
    input.pop_front();
    return byte;
  }
  size_t write_bytes(const uint8_t* data, size_t length) override {
    output.append(reinterpret_cast<const char*>(data), length);
    return length;
  }
  size_t write_space() override { return 1u << 20; }
  std::deque<char> input;
  std::string output;
};

// An in-memory SD card. Reading a missing file is an I/O error and an absent card kUnsupported, the
// two cases the recorder and player report differently (no file versus a board without a slot).
// Handles are never reused, so a stale handle stays invalid after close.
class MemoryStorage final : public FileStorage {
 public:
  Status open(const char* name, FileMode mode, int& handle) override {
    if (!present) return Status::kUnsupported;
    if (name == nullptr || std::strlen(name) > kMaxNameLength) return Status::kBadArgument;
    if (mode == FileMode::kRead && !files.count(name)) return Status::kIoError;
    auto& file = files[name];
    if (mode == FileMode::kWriteTruncate) file.clear();
    handles.push_back({name, mode == FileMode::kRead ? 0 : file.size(), true});
    handle = static_cast<int>(handles.size() - 1);
    return Status::kOk;
  }
  Status read(int handle, uint8_t* data, size_t length, size_t& read) override {
    if (!valid(handle)) return Status::kBadArgument;
    auto& open_file = handles[handle];
    const auto& file = files[open_file.name];
    read = std::min(length, file.size() - open_file.offset);
    std::memcpy(data, file.data() + open_file.offset, read);
    open_file.offset += read;
    return Status::kOk;
  }
  Status write(int handle, const uint8_t* data, size_t length) override {
    if (!valid(handle)) return Status::kBadArgument;
    auto& file = files[handles[handle].name];
    file.insert(file.end(), data, data + length);
    return Status::kOk;
  }
  Status close(int handle) override {
    if (!valid(handle)) return Status::kBadArgument;
    handles[handle].open = false;
    return Status::kOk;
  }
  struct OpenFile {
    std::string name;
    size_t offset;
    bool open;
  };
  bool valid(int handle) const {
    return handle >= 0 && static_cast<size_t>(handle) < handles.size() && handles[handle].open;
  }
  std::map<std::string, std::vector<uint8_t>> files;
  std::vector<OpenFile> handles;
  bool present = true;  // false: a board without a card slot (a Teensy 4.0)
};

/// EEPROM emulation: a Teensy 4.0's 1080 bytes, erased (0xFF) at reset(), kept by reboot().
class MemoryEeprom final : public NonvolatileStore {
 public:
  size_t size_bytes() override { return bytes.size(); }
  Status read(size_t offset, uint8_t* data, size_t length) override {
    if (!fits(offset, length)) return Status::kBadArgument;
    std::memcpy(data, bytes.data() + offset, length);
    return Status::kOk;
  }
  Status write(size_t offset, const uint8_t* data, size_t length) override {
    if (!fits(offset, length)) return Status::kBadArgument;
    std::memcpy(bytes.data() + offset, data, length);
    ++writes;
    return Status::kOk;
  }
  bool fits(size_t offset, size_t length) const { return offset <= bytes.size() && length <= bytes.size() - offset; }
  std::array<uint8_t, hal_manual::kEepromBytes> bytes = filled();
  uint32_t writes = 0;

 private:
  static std::array<uint8_t, hal_manual::kEepromBytes> filled() {
    std::array<uint8_t, hal_manual::kEepromBytes> erased;
    erased.fill(0xFF);
    return erased;
  }
};

struct ManualBoard {
  uint32_t micros = 0;
  uint32_t cycles = 0;
  uint32_t cycles_per_read = 0;
  uint32_t frames_since_tick = 0;
  hal::Isr frame_isr = nullptr;
  hal::Isr khz_isr = nullptr;
  std::array<protocol::FrameWords, kPorts> last_frames{};
  std::array<uint32_t, kPorts> frame_counts{};
  std::array<bool, kPorts> outputs_claimed{};
  std::array<InputPortState, kPorts> inputs{};
  std::array<int32_t, kEncoders> quadrature{};
  std::array<bool, kEncoders> quadrature_begun{};
  std::array<PinState, hal_manual::kMaxPin + 1> pins{};
  bool safe_state = false;
  std::string fault_log;
  ConsoleStream console;
  MemoryStorage storage;
  MemoryEeprom eeprom;
};

// A plain global (not a function-local static) so each access costs no initialisation guard:
// the benchmarks measure frames on this backend. Nothing touches the HAL during static init.
ManualBoard the_board;
ManualBoard& board() { return the_board; }

bool valid_pin(uint8_t pin) { return pin <= hal_manual::kMaxPin; }

}  // namespace

// ---- HAL facade -------------------------------------------------------------------------------
namespace hal {

uint32_t micros_now() { return board().micros; }
// Each read advances the counter by cycles_per_read, so a test can give a frame a known cost and check
// the engine's overrun and load arithmetic against it. 600 MHz is the Teensy 4.x core clock.
uint32_t cycles_now() {
  const uint32_t now = board().cycles;
  board().cycles += board().cycles_per_read;
  return now;
}
uint32_t cycles_per_second() { return 600000000u; }

// The timers only store their ISR: time moves when a test calls run_frames(), never by itself, which
// makes every test deterministic.
Status frame_timer_start(uint32_t, Isr on_frame) {
  board().frame_isr = on_frame;
  return Status::kOk;
}
Status khz_timer_start(uint32_t, Isr on_tick) {
  board().khz_isr = on_tick;
  return Status::kOk;
}
void timers_stop() {
  board().frame_isr = nullptr;
  board().khz_isr = nullptr;
}

// Single-threaded: no interrupt can preempt the test, so critical sections are empty.
uint32_t irq_save() { return 0; }
void irq_restore(uint32_t) {}

// A port can be claimed once (kBusy after), as on the board where one timer channel drives it; the
// OutputPort above is responsible for releasing a previous owner.
Status port_out_begin(uint8_t port) {
  if (port >= kPorts) return Status::kNoSuchPin;
  if (board().outputs_claimed[port]) return Status::kBusy;
  board().outputs_claimed[port] = true;
  return Status::kOk;
}
void port_out_frame(uint8_t port, const protocol::FrameWords& words) {
  if (port >= kPorts) return;
  board().last_frames[port] = words;
  ++board().frame_counts[port];
}

Status port_in_begin(uint8_t port, protocol::DirSampleEdge edge, PulseSink sink, void* context) {
  if (port >= kPorts) return Status::kNoSuchPin;
  board().inputs[port] = {true, edge, sink, context};
  return Status::kOk;
}
// The Teensy 4.x capture clock at its usual 150 MHz bus clock (150 ticks per µs) into a 16-bit
// counter, so pulse-width tests wrap where the hardware's counter does.
protocol::CaptureClock port_in_clock(uint8_t) { return protocol::CaptureClock{150, 0xFFFFu}; }

// Two encoder inputs, as on the boards; a count changes only when a test calls set_quadrature().
Status quadrature_begin(uint8_t index) {
  if (index >= kEncoders) return Status::kNoSuchPin;
  board().quadrature_begun[index] = true;
  return Status::kOk;
}
int32_t quadrature_read(uint8_t index) { return index < kEncoders ? board().quadrature[index] : 0; }
void quadrature_write(uint8_t index, int32_t count) {
  if (index < kEncoders) board().quadrature[index] = count;
}

Status adc_begin(uint8_t pin) {
  if (!valid_pin(pin)) return Status::kNoSuchPin;
  board().pins[pin].adc_begun = true;
  return Status::kOk;
}
uint16_t adc_read(uint8_t pin) { return valid_pin(pin) ? board().pins[pin].adc : 0; }
uint32_t adc_sample_count(uint8_t pin) { return valid_pin(pin) ? board().pins[pin].adc_samples : 0; }

// An unconnected pin with a pull resistor reads the pull's level; a test overrides it with set_pin().
Status gpio_mode(uint8_t pin, PinMode mode) {
  if (!valid_pin(pin)) return Status::kNoSuchPin;
  PinState& state = board().pins[pin];
  state.mode = mode;
  state.configured = true;
  if (mode == PinMode::kInputPullup) state.level = true;
  if (mode == PinMode::kInputPulldown) state.level = false;
  return Status::kOk;
}
bool gpio_read(uint8_t pin) { return valid_pin(pin) && board().pins[pin].level; }
void gpio_write(uint8_t pin, bool high) {
  if (valid_pin(pin)) board().pins[pin].level = high;
}

// A fatal fault stops the timers as the firmware does; in_safe_state() lets a test check it happened.
void enter_safe_state() {
  board().safe_state = true;
  timers_stop();
}
void log_fault(const char* reason, const char* detail) { board().fault_log = std::string(reason) + ": " + detail; }
void log_message(const char* text) {
  board().console.output += text;
  board().console.output += "\r\n";
}

ByteStream& console() { return board().console; }
FileStorage& storage() { return board().storage; }
NonvolatileStore& nonvolatile_store() { return board().eeprom; }

}  // namespace hal

// ---- Test controls ----------------------------------------------------------------------------
namespace hal_manual {

void reset(uint32_t start_us) {
  board() = ManualBoard{};
  board().micros = start_us;
}

// A power cycle: everything resets except the EEPROM, so settings persistence can be tested.
void reboot(uint32_t start_us) {
  const MemoryEeprom kept = board().eeprom;
  reset(start_us);
  board().eeprom = kept;
}

uint8_t* eeprom_bytes() { return board().eeprom.bytes.data(); }
uint32_t eeprom_writes() { return board().eeprom.writes; }
void set_storage_present(bool present) { board().storage.present = present; }

// Advances time one frame at a time and fires the kilohertz ISR every frames_per_kilohertz_tick()
// frames, after the frame ISR of the same instant, so tick-stage blocks see that frame's results.
void run_frames(uint32_t n) {
  for (uint32_t i = 0; i < n; ++i) {
    board().micros += frame_period_us();
    if (board().frame_isr != nullptr) board().frame_isr();
    if (++board().frames_since_tick >= frames_per_kilohertz_tick()) {
      board().frames_since_tick = 0;
      if (board().khz_isr != nullptr) board().khz_isr();
    }
  }
}

// Moves the clock without running frames: for loop-side code that reads micros() (retries, pacing).
void advance_us(uint32_t us) { board().micros += us; }
void set_cycles_per_read(uint32_t cycles) { board().cycles_per_read = cycles; }
bool frame_timer_running() { return board().frame_isr != nullptr; }
bool khz_timer_running() { return board().khz_isr != nullptr; }

protocol::FrameWords last_frame(uint8_t port) { return board().last_frames.at(port); }
uint32_t frames_written(uint8_t port) { return board().frame_counts.at(port); }
bool output_claimed(uint8_t port) { return board().outputs_claimed.at(port); }

bool inject_pulse(uint8_t port, const protocol::CapturedPulse& pulse) {
  const InputPortState& input = board().inputs.at(port);
  if (!input.begun || input.sink == nullptr) return false;
  input.sink(input.context, pulse);
  return true;
}
protocol::DirSampleEdge input_edge(uint8_t port) { return board().inputs.at(port).edge; }

void set_quadrature(uint8_t index, int32_t count) { board().quadrature.at(index) = count; }
// Each value counts as a new conversion, so inputs that act on new samples (AnalogInput's callback,
// its pending deadband centre) see one.
void set_adc(uint8_t pin, uint16_t value) {
  board().pins.at(pin).adc = value;
  ++board().pins.at(pin).adc_samples;
}
void set_pin(uint8_t pin, bool high) { board().pins.at(pin).level = high; }
bool pin_level(uint8_t pin) { return board().pins.at(pin).level; }
hal::PinMode pin_mode(uint8_t pin) { return board().pins.at(pin).mode; }

bool in_safe_state() { return board().safe_state; }
const std::string& last_fault_log() { return board().fault_log; }

std::string take_console_output() {
  std::string out;
  out.swap(board().console.output);
  return out;
}
void feed_console(const std::string& bytes) {
  board().console.input.insert(board().console.input.end(), bytes.begin(), bytes.end());
}

}  // namespace hal_manual
}  // namespace stepdance

#endif  // STEPDANCE_PLATFORM_MANUAL
