// The board-side link to the simulator: the current callback table and the detached stand-ins.
#if defined(STEPDANCE_PLATFORM_SIM)

#include "stepdance/platform/sim/host_link.hpp"

#include <unistd.h>

namespace stepdance::sim_runtime {
namespace {

constexpr int kUnsupported = 7;  // stepdance::Status::kUnsupported

// The detached table: what a board's shared object answers before the simulator attaches (global
// constructors of the sketch run at load time) or after it detaches. Everything refuses or reads as
// idle instead of crashing on a null table.
int refuse_timer(void*, int, uint32_t) { return kUnsupported; }
void ignore(void*) {}
int64_t ignore_delay(void*, int64_t) { return 0; }
int refuse_port(void*, uint8_t) { return kUnsupported; }
void ignore_frame(void*, uint8_t, uint32_t, uint32_t) {}
int refuse_input(void*, uint8_t, int) { return kUnsupported; }
int32_t zero_count(void*, uint8_t) { return 0; }
void ignore_count(void*, uint8_t, int32_t) {}
uint16_t zero_adc(void*, uint8_t) { return 0; }
uint32_t zero_samples(void*, uint8_t) { return 0; }
int refuse_mode(void*, uint8_t, int) { return kUnsupported; }
int low_pin(void*, uint8_t) { return 0; }
void ignore_write(void*, uint8_t, int) {}
void ignore_fault(void*, const char*, const char*) {}
size_t swallow(void*, const uint8_t*, size_t length) { return length; }
size_t nothing_available(void*) { return 0; }
int no_byte(void*) { return -1; }
int refuse_open(void*, const char*, int, int*) { return kUnsupported; }
int refuse_read(void*, int, uint8_t*, size_t, size_t* read) {
  *read = 0;
  return kUnsupported;
}
int refuse_write(void*, int, const uint8_t*, size_t) { return kUnsupported; }
int refuse_close(void*, int) { return kUnsupported; }
int refuse_i2c_begin(void*, uint8_t, uint32_t) { return kUnsupported; }
int no_i2c_device(void*, uint8_t, uint8_t, const uint8_t*, size_t, uint8_t*, size_t, int64_t* wire_ns) {
  *wire_ns = 0;
  return 3;  // stepdance::hal::I2cResult::kAddressNack
}
// exit() or abort() from a global constructor: no simulator to tell yet, so say it here.
void ended_while_loading(void*, int, int) {
  static const char kMessage[] = "stepdance: a sketch ended the program (exit() or abort()) while loading\n";
  (void)!write(2, kMessage, sizeof kMessage - 1);
}

const StepdanceHostV1 kDetached = {
    STEPDANCE_BOARD_ABI_VERSION,
    &refuse_timer,
    &ignore,
    &ignore_delay,
    &refuse_port,
    &ignore_frame,
    &refuse_input,
    &refuse_port,
    &zero_count,
    &ignore_count,
    &refuse_port,
    &zero_adc,
    &zero_samples,
    &refuse_mode,
    &low_pin,
    &ignore_write,
    &ignore,
    &ignore_fault,
    &swallow,
    &nothing_available,
    &no_byte,
    &refuse_open,
    &refuse_read,
    &refuse_write,
    &refuse_close,
    &refuse_i2c_begin,
    &no_i2c_device,
    &ended_while_loading,
};

const StepdanceHostV1* current = &kDetached;
void* current_context = nullptr;
int64_t current_ns = 0;

}  // namespace

const StepdanceHostV1& host() { return *current; }
void* host_context() { return current_context; }

int64_t now_ns() { return current_ns; }
void set_now_ns(int64_t now) { current_ns = now; }

// The table's abi_version has been checked by the board's entry point (board_entry.cpp) before it
// gets here, so a board and a simulator of other versions never call through mismatched entries.
void attach_host(const StepdanceHostV1* table, void* context) {
  current = table;
  current_context = context;
}

}  // namespace stepdance::sim_runtime

#endif  // STEPDANCE_PLATFORM_SIM
