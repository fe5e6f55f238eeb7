// The console end of the serial link.
#include "stepdance/interfaces/link/serial_link.hpp"

#include "stepdance/hal/console.hpp"

namespace stepdance::link {

// The board's USB serial (hal::console()): the default link of every host protocol.
ByteStream* SerialLink::attach_console() {
  stream_ = &hal::console();
  return stream_;
}

}  // namespace stepdance::link
