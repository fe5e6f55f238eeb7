// libFuzzer target: arbitrary bytes from a host through the Grbl link into a scripted machine.
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <math.h>

#include "stepdance/interfaces/gcode/grbl_protocol.hpp"
#include "stepdance/interfaces/gcode/grbl_settings_store.hpp"

namespace {

using namespace stepdance;
using namespace stepdance::gcode;

/// Delivers the input in chunks; the host reads replies slowly now and then.
struct FuzzStream final : ByteStream {
  const uint8_t* data = nullptr;
  size_t size = 0;
  size_t offset = 0;
  size_t chunk_end = 0;
  size_t written = 0;
  size_t write_room = 64;
  size_t bytes_available() override { return chunk_end - offset; }
  int read_byte() override { return offset < chunk_end ? data[offset++] : -1; }
  size_t write_bytes(const uint8_t*, size_t length) override {
    const size_t n = length < write_room ? length : write_room;
    written += n;
    write_room -= n;
    return n;
  }
  size_t write_space() override { return write_room; }
};

/// A machine with a small queue that drains one motion per poll.
struct FuzzMachine final : GrblMachine {
  int queued = 0;
  MotionState state = MotionState::kIdle;
  void on_motion(const Motion& motion) override {
    for (int axis = 0; axis < kAxisCount; ++axis) {
      if (!isfinite(motion.end_mm[axis])) abort();
    }
    if (++queued > 16) abort();  // the protocol must wait for ready_for_line()
    state = MotionState::kRun;
  }
  void on_dwell(double) override {}
  MotionState motion_state() override { return state; }
  bool hold_complete() override { return true; }
  void position_mm(double (&out)[kAxisCount]) override {
    for (double& value : out) value = 0.0;
  }
  double feed_now_mm_per_min() override { return 0.0; }
  uint16_t queue_slots_free() override { return static_cast<uint16_t>(16 - queued); }
  uint16_t queue_slots_total() override { return 16; }
  bool ready_for_line() override { return queued <= 14; }
  void feed_hold() override { state = MotionState::kHolding; }
  void cycle_start() override { state = queued > 0 ? MotionState::kRun : MotionState::kIdle; }
  bool soft_reset() override {
    const bool moving = queued > 0;
    queued = 0;
    state = MotionState::kIdle;
    return moving;
  }
  void jog(const Motion&) override { state = MotionState::kJog; }
  void jog_cancel() override { state = MotionState::kIdle; }
  void set_overrides(uint8_t feed, uint8_t) override {
    if (feed < 10 || feed > 200) abort();
  }
  double steps_per_mm(int) override { return 80.0; }
  void drain() {
    if (queued > 0 && state == MotionState::kRun) --queued;
    if (queued == 0 && state != MotionState::kHolding) state = MotionState::kIdle;
  }
};

/// EEPROM emulation: 1080 erased bytes, like a Teensy 4.0's.
struct FuzzStore final : NonvolatileStore {
  uint8_t bytes[1080];
  FuzzStore() {
    for (uint8_t& byte : bytes) byte = 0xFF;
  }
  size_t size_bytes() override { return sizeof(bytes); }
  Status read(size_t offset, uint8_t* data, size_t length) override {
    if (offset > sizeof(bytes) || length > sizeof(bytes) - offset) abort();  // we never ask beyond it
    for (size_t i = 0; i < length; ++i) data[i] = bytes[offset + i];
    return Status::kOk;
  }
  Status write(size_t offset, const uint8_t* data, size_t length) override {
    if (offset > sizeof(bytes) || length > sizeof(bytes) - offset) abort();
    for (size_t i = 0; i < length; ++i) bytes[offset + i] = data[i];
    return Status::kOk;
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  FuzzStream stream;
  stream.data = data;
  stream.size = size;
  FuzzMachine machine;
  FuzzStore store;
  GrblProtocol protocol;
  protocol.begin(stream, machine, &store);
  for (int pass = 0; pass < 4096 && (stream.offset < size || machine.queued > 0); ++pass) {
    stream.chunk_end = stream.offset + 37 < size ? stream.offset + 37 : size;
    protocol.poll();
    machine.drain();
    stream.write_room = (pass % 3 == 0) ? 4096 : 0;
  }
  if (protocol.replies_dropped() != 0) abort();
  // Whatever the host did, what was stored reads back whole after a reboot.
  GrblSettings rebooted;
  uint8_t version = 0;
  const SettingsLoad load = load_settings(store, rebooted, version);
  if (load != SettingsLoad::kLoaded && load != SettingsLoad::kBlank) abort();
  for (int i = 0; i < GrblSettings::kCount; ++i) {
    if (rebooted.at(i).host_set && rebooted.at(i).value != protocol.settings().at(i).value) abort();
  }
  return 0;
}
