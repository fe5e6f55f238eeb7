// C trampolines from the board ABI into SimBoard.
#include "board/host/board_callbacks.hpp"

#include <cstdio>
#include <cstdlib>

#include "board/host/sim_board.hpp"

namespace stepdance::sim {
namespace {

// Every callback starts here, so a stop requested while the sketch runs (a hang, Ctrl-C) takes
// effect at the sketch's next call into the simulator, before the simulator's state is touched.
SimBoard& of(void* context) {
  EntryMonitor::escape_if_requested();
  return *static_cast<SimBoard*>(context);
}
int ok() { return static_cast<int>(Status::kOk); }
int no_such_pin() { return static_cast<int>(Status::kNoSuchPin); }
/// The process's status when a sketch ends the program where it cannot be stopped: the
/// command line's "a sketch failed" (cli/exit_codes.hpp).
constexpr int kExitSketchOutsideEntry = 5;

}  // namespace

StepdanceHostV1 BoardCallbacks::table() {
  StepdanceHostV1 host{};
  host.abi_version = STEPDANCE_BOARD_ABI_VERSION;
  add_timer_callbacks(host);
  add_port_callbacks(host);
  add_input_callbacks(host);
  add_console_callbacks(host);
  add_i2c_callbacks(host);
  add_end_callback(host);
  return host;
}

void BoardCallbacks::add_timer_callbacks(StepdanceHostV1& host) {
  host.timer_start = [](void* c, int timer, uint32_t period_us) { return of(c).start_timer(timer, period_us); };
  host.timers_stop = [](void* c) { of(c).stop_timers(); };
  host.delay_ns = [](void* c, int64_t duration_ns) {
    SimBoard& board = of(c);
    board.delay(duration_ns);
    if (board.run_is_over()) EntryMonitor::escape(EscapeCause::kRunOver);
    return board.scheduler_.now();
  };
}

void BoardCallbacks::add_port_callbacks(StepdanceHostV1& host) {
  host.port_out_begin = [](void* c, uint8_t port) {
    if (port >= SimBoard::kPorts) return no_such_pin();
    return of(c).ports_.claim_output(port) ? ok() : static_cast<int>(Status::kBusy);
  };
  host.port_out_frame = [](void* c, uint8_t port, uint32_t step_bits, uint32_t dir_bits) {
    if (port >= SimBoard::kPorts) return;
    of(c).ports_.queue_frame(port, protocol::FrameWords{step_bits, dir_bits});
  };
  host.port_in_begin = [](void* c, uint8_t port, int edge) {
    if (port >= SimBoard::kPorts) return no_such_pin();
    of(c).ports_.begin_input(
        port, edge == STEPDANCE_DIR_AT_RISING ? protocol::DirSampleEdge::kRising : protocol::DirSampleEdge::kFalling);
    return ok();
  };
}

void BoardCallbacks::add_input_callbacks(StepdanceHostV1& host) {
  host.quadrature_begin = [](void*, uint8_t index) { return index < 2 ? ok() : no_such_pin(); };
  host.quadrature_read = [](void* c, uint8_t index) { return of(c).read_quadrature(index); };
  host.quadrature_write = [](void* c, uint8_t index, int32_t count) { of(c).write_quadrature(index, count); };
  host.adc_begin = [](void* c, uint8_t pin) {
    if (pin >= SimBoard::kPins) return no_such_pin();
    auto& adc = of(c).adcs_[pin];
    if (!adc.begun) adc.begun_at = of(c).scheduler_.now();
    adc.begun = true;
    return ok();
  };
  host.adc_read = [](void* c, uint8_t pin) -> uint16_t { return of(c).analog_level(pin); };
  host.adc_sample_count = [](void* c, uint8_t pin) { return pin < SimBoard::kPins ? of(c).adc_samples(pin) : 0u; };
  host.gpio_mode = [](void* c, uint8_t pin, int mode) { return of(c).set_pin_mode(pin, mode); };
  host.gpio_read = [](void* c, uint8_t pin) { return pin < SimBoard::kPins && of(c).pin_level(pin) ? 1 : 0; };
  host.gpio_write = [](void* c, uint8_t pin, int high) { of(c).write_pin(pin, high != 0); };
}

void BoardCallbacks::add_console_callbacks(StepdanceHostV1& host) {
  host.enter_safe_state = [](void* c) { of(c).enter_safe_state(); };
  host.log_fault = [](void* c, const char* reason, const char* detail) {
    SimBoard& board = of(c);
    if (board.faults_.size() < SimBoard::kFaultLogEntries) {
      board.faults_.push_back({board.scheduler_.now(), std::string(reason) + ": " + detail});
    } else {
      ++board.faults_not_logged_;
    }
  };
  host.console_write = [](void* c, const uint8_t* data, size_t length) { return of(c).write_console(data, length); };
  host.console_available = [](void* c) -> size_t { return of(c).console_.available(); };
  host.console_read = [](void* c) { return of(c).console_.read(); };

  host.file_open = [](void* c, const char* name, int mode, int* handle) {
    if (of(c).storage_refused_in_isr()) return static_cast<int>(Status::kIoError);
    return static_cast<int>(of(c).storage_.open(name, mode, *handle));
  };
  host.file_read = [](void* c, int handle, uint8_t* data, size_t length, size_t* read) {
    return of(c).storage_read(handle, data, length, read);
  };
  host.file_write = [](void* c, int handle, const uint8_t* data, size_t length) {
    return of(c).storage_write(handle, data, length);
  };
  host.file_close = [](void* c, int handle) {
    if (of(c).storage_refused_in_isr()) return static_cast<int>(Status::kIoError);
    return static_cast<int>(of(c).storage_.close(handle));
  };
}

void BoardCallbacks::add_end_callback(StepdanceHostV1& host) {
  host.sketch_ended = [](void* c, int how, int status) {
    EntryMonitor::record_sketch_end(how, status);
    EntryMonitor::escape(EscapeCause::kEnded);
    // Outside every entry point (a global destructor, say) nothing can be left: end here.
    std::fprintf(stderr, "board '%s': the sketch ended the program outside setup() and loop()\n", of(c).name().c_str());
    std::_Exit(kExitSketchOutsideEntry);
  };
}

void BoardCallbacks::add_i2c_callbacks(StepdanceHostV1& host) {
  host.i2c_begin = [](void* c, uint8_t bus, uint32_t clock_hz) {
    return of(c).i2c_.begin(bus, clock_hz) ? ok() : no_such_pin();
  };
  host.i2c_transfer = [](void* c, uint8_t bus, uint8_t address, const uint8_t* write, size_t write_length,
                         uint8_t* read, size_t read_length, int64_t* wire_ns) {
    return of(c).i2c_transfer(bus, address, write, write_length, read, read_length, wire_ns);
  };
}

}  // namespace stepdance::sim
