// The emulated host's state in one line, for run reports.
#include <cstdio>

#include "image/usb/usb_host.hpp"

namespace stepdance::sim::image::usb {

std::string UsbHost::describe() const {
  char text[256];
  const char* speed = record_.speed == BusSpeed::kHigh ? "high speed" : "full speed";
  switch (phase_) {
    case Phase::kFailed: return failure_;
    case Phase::kDetached: return "usb host: no device attached (" + device_.detached_reason() + ")";
    case Phase::kDebounce:
    case Phase::kReset:
    case Phase::kRecovery: return "usb host: device attached, bus reset in progress";
    case Phase::kEnumerating: {
      const char* stage = control_.stage == ControlTransfer::Stage::kSetup  ? "setup"
                          : control_.stage == ControlTransfer::Stage::kData ? "data"
                                                                            : "status";
      std::snprintf(text, sizeof text, "usb host: enumerating at %s, waiting on %s (%s stage)", speed,
                    control_active_ ? control_.name.c_str() : "the next request", stage);
      return text;
    }
    case Phase::kRunning:
      std::snprintf(text, sizeof text,
                    "usb host: configured at %.6f s, %s, %04X:%04X \"%s\" \"%s\", CDC bulk IN 0x%02X OUT 0x%02X",
                    to_seconds(record_.configured_ns), speed, record_.device.vendor_id, record_.device.product_id,
                    record_.manufacturer.c_str(), record_.product.c_str(), record_.cdc.bulk_in, record_.cdc.bulk_out);
      return text;
  }
  return "usb host";
}

}  // namespace stepdance::sim::image::usb
