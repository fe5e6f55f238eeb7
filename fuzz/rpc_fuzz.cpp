// libFuzzer target: arbitrary lines into the RPC block (JSON parsing, argument checks, calls,
// the chunked index and __describe__, subscriptions and their events), on the manual board with a few enrolled names of
// every kind.
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "hal_manual.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/engine.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/interfaces/rpc/rpc.hpp"
#include "stepdance/motion/time_based_interpolator.hpp"

namespace {

using namespace stepdance;

struct FuzzStream final : ByteStream {
  const uint8_t* data = nullptr;
  size_t size = 0;
  size_t offset = 0;
  size_t write_room = 300;
  size_t bytes_available() override { return size - offset; }
  int read_byte() override { return offset < size ? data[offset++] : -1; }
  size_t write_bytes(const uint8_t*, size_t length) override {
    const size_t n = length < write_room ? length : write_room;
    write_room -= n;
    return n;
  }
  size_t write_space() override { return write_room; }
};

double scale(double value, double factor) { return value * factor; }
int8_t narrow(int8_t value) { return value; }
const char* label(const char* text) { return text; }
void nothing() {}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  hal_manual::reset();
  engine().clear();
  clear_fault();
  clear_fault_subscribers();
  FuzzStream stream;
  stream.data = data;
  stream.size = size;
  {
    RPC rpc;
    TimeBasedInterpolator tbi;
    static double level = 0;
    static bool armed = false;
    if (rpc.begin(&stream) != Status::kOk || tbi.begin() != Status::kOk) abort();
    rpc.enroll("scale", scale);
    rpc.enroll("narrow", narrow);
    rpc.enroll("label", label);
    rpc.enroll("nothing", nothing);
    rpc.enroll("level", level);
    rpc.enroll("armed", armed);
    rpc.enroll("tbi", tbi);
    if (dance_start() != Status::kOk) abort();
    for (int pass = 0; pass < 64 && (stream.offset < size || stream.write_room == 0); ++pass) {
      dance_loop();
      hal_manual::run_frames(2);
      if (pass % 8 == 7) {
        report_fault(FaultLevel::kWarning, FaultReason::kRefused, "fuzz", "now and then");
        hal_manual::advance_us(RPC::kMinEventIntervalUs);
      }
      level += 1;               // a subscribed value changes
      stream.write_room = 300;  // the host reads
    }
  }
  engine().clear();
  return 0;
}
