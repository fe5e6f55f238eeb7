// Inside a board's shared object: the console stream and file storage, forwarded to the simulator.
#if defined(STEPDANCE_PLATFORM_SIM)

#include "stepdance/core/byte_stream.hpp"
#include "stepdance/hal/console.hpp"
#include "stepdance/hal/storage.hpp"
#include "stepdance/platform/sim/host_link.hpp"

namespace stepdance {
namespace {

using sim_runtime::host;
using sim_runtime::host_context;

/// The board's USB serial: bytes go to the simulator's console log, input comes from the
/// scenario's `serial` actions. Writing never refuses (the host buffers everything).
// The large write space models a host that always reads; a slow reader is modelled by the manual
// backend's MemoryPort instead.
class SimulatedConsole final : public ByteStream {
 public:
  size_t bytes_available() override { return host().console_available(host_context()); }
  int read_byte() override { return host().console_read(host_context()); }
  size_t write_bytes(const uint8_t* data, size_t length) override {
    return host().console_write(host_context(), data, length);
  }
  size_t write_space() override { return 1u << 16; }
};

/// The board's SD card: a folder of the simulation's output directory.
class SimulatedStorage final : public FileStorage {
 public:
  Status open(const char* name, FileMode mode, int& handle) override {
    return static_cast<Status>(host().file_open(host_context(), name, static_cast<int>(mode), &handle));
  }
  Status read(int handle, uint8_t* data, size_t length, size_t& read) override {
    return static_cast<Status>(host().file_read(host_context(), handle, data, length, &read));
  }
  Status write(int handle, const uint8_t* data, size_t length) override {
    return static_cast<Status>(host().file_write(host_context(), handle, data, length));
  }
  Status close(int handle) override { return static_cast<Status>(host().file_close(host_context(), handle)); }
};

SimulatedConsole the_console;
SimulatedStorage the_storage;

}  // namespace

namespace hal {
ByteStream& console() { return the_console; }
FileStorage& storage() { return the_storage; }
}  // namespace hal

}  // namespace stepdance

#endif  // STEPDANCE_PLATFORM_SIM
