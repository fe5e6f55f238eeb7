// Names of the handshakes, for the host's reports.
#include "image/usb/usb_bus.hpp"

namespace stepdance::sim::image::usb {

const char* handshake_name(Handshake handshake) {
  switch (handshake) {
    case Handshake::kAck: return "ACK";
    case Handshake::kNak: return "NAK";
    case Handshake::kStall: return "STALL";
    case Handshake::kNoResponse: return "no response";
  }
  return "?";
}

}  // namespace stepdance::sim::image::usb
