// console(): the core's ByteStream over Teensyduino's USB Serial, never blocking.
#if defined(__IMXRT1062__)

#include "stepdance/platform/teensy/console.hpp"

#include "stepdance/core/byte_stream.hpp"
#include "stepdance/hal/console.hpp"
#include "stepdance/platform/teensy/teensyduino_services.hpp"

namespace stepdance::platform::teensy {
namespace {

class UsbSerialStream final : public ByteStream {
 public:
  size_t bytes_available() override {
    flush_pending_fault();
    const int available = services::serial_available();
    return available > 0 ? static_cast<size_t>(available) : 0;
  }
  int read_byte() override { return services::serial_read(); }
  size_t write_bytes(const uint8_t* data, size_t length) override {
    flush_pending_fault();
    const size_t room = write_space();
    const size_t count = length < room ? length : room;
    return count == 0 ? 0 : services::serial_write(data, count);
  }
  size_t write_space() override {
    const int space = services::serial_write_space();
    return space > 0 ? static_cast<size_t>(space) : 0;
  }
};

UsbSerialStream usb_console;

}  // namespace
}  // namespace stepdance::platform::teensy

namespace stepdance::hal {
ByteStream& console() { return platform::teensy::usb_console; }
}  // namespace stepdance::hal

#endif  // __IMXRT1062__
