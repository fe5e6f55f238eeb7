// libFuzzer target: arbitrary bytes from plotter software into the EBB emulation, frames running
// in between, on the manual board. Any crash, sanitizer report or broken invariant fails it.
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <math.h>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/engine.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/interfaces/ebb/eibotboard.hpp"

namespace {

using namespace stepdance;

/// The input arrives in chunks; between chunks some frames run. The host reads slowly at times.
struct FuzzStream final : ByteStream {
  const uint8_t* data = nullptr;
  size_t offset = 0;
  size_t chunk_end = 0;
  size_t write_room = 256;
  size_t bytes_available() override { return chunk_end - offset; }
  int read_byte() override { return offset < chunk_end ? data[offset++] : -1; }
  size_t write_bytes(const uint8_t*, size_t length) override {
    const size_t n = length < write_room ? length : write_room;
    write_room -= n;
    return n;
  }
  size_t write_space() override { return write_room; }
};

constexpr uint32_t kFrameBudget = 5000;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hal_manual::reset();
  engine().clear();
  clear_fault();
  FuzzStream stream;
  stream.data = data;
  {
    Eibotboard ebb;
    if (ebb.begin(&stream) != Status::kOk) abort();
    if (dance_start() != Status::kOk) abort();
    size_t position = 0;
    uint32_t long_frames = 0;
    while (position < size) {
      // A chunk: its first byte says how long it is and how many frames follow it.
      const uint8_t control = data[position++];
      const size_t length = 1 + (control & 0x3F);
      stream.chunk_end = position + length < size ? position + length : size;
      stream.offset = position;
      dance_loop();
      position = stream.offset;  // what the board did not read yet stays for the next round
      if (position < stream.chunk_end && (control & 0x40) == 0) position = stream.chunk_end;  // host gave up
      // Three frames, or up to 2500 (100 ms) that stop early once the machine is idle: frames
      // with nothing to do change nothing and were most of the run time. One input runs at most
      // kFrameBudget frames in long chunks (200 ms of machine time: queued moves complete, the
      // FIFO fills and drains), so the frames, not the parser, no longer take most of the run.
      if ((control & 0x80) && long_frames < kFrameBudget) {
        for (uint32_t frame = 0; frame < 2500 && !ebb.is_idle(); ++frame, ++long_frames) hal_manual::run_frames(1);
      } else {
        hal_manual::run_frames(3);
      }
      stream.write_room = 256;
      if (!isfinite(ebb.output_x.read_absolute()) || !isfinite(ebb.output_y.read_absolute()) ||
          !isfinite(ebb.output_z.read_absolute())) {
        abort();
      }
      if (ebb.replies_dropped() != 0) abort();  // replies must wait, never be dropped
    }
  }
  engine().clear();
  return 0;
}
