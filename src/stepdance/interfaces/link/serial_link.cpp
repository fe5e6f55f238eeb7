// The console end of the serial link.
#include "stepdance/interfaces/link/serial_link.hpp"

#include "stepdance/core/file_storage.hpp"  // hal::console()

namespace stepdance::link {

ByteStream* SerialLink::attach_console() {
  stream_ = &hal::console();
  return stream_;
}

}  // namespace stepdance::link
