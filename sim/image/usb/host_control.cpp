// The emulated host's control transfers (USB 2.0 §8.5.3, §9.3, §9.4) and the enumeration a PC
// runs: device descriptor at address 0, SET_ADDRESS, descriptors, strings, SET_CONFIGURATION,
// then the CDC requests SET_LINE_CODING and SET_CONTROL_LINE_STATE (PSTN 1.2 §6.3.10, §6.3.12).
#include <algorithm>
#include <cstdio>

#include "image/usb/usb_host.hpp"

namespace stepdance::sim::image::usb {
namespace {

// bmRequestType (USB 2.0 table 9-2) and bRequest codes (table 9-4; PSTN 1.2 table 13).
constexpr uint8_t kDeviceToHost = 0x80, kClassInterface = 0x21;
constexpr uint8_t kGetDescriptor = 6, kSetAddress = 5, kSetConfiguration = 9;
constexpr uint8_t kSetLineCoding = 0x20, kSetControlLineState = 0x22;
constexpr SimTime kDataStageNs = 500 * kMillisecond;      // §9.2.6.4: IN data within 500 ms
constexpr SimTime kOutDataStageNs = 5000 * kMillisecond;  // §9.2.6.4: whole OUT request within 5 s
constexpr SimTime kStatusStageNs = 50 * kMillisecond;     // §9.2.6.4: status within 50 ms
enum Step : int {
  kDevice8,
  kAddress,
  kDevice,
  kConfigHead,
  kConfigAll,
  kLanguages,
  kManufacturer,
  kProduct,
  kSerial,
  kConfigure,
  kLineCoding,
  kLineState,
  kSteps
};

uint16_t request_length(const uint8_t request[8]) { return static_cast<uint16_t>(request[6] | (request[7] << 8)); }
bool device_to_host(const uint8_t request[8]) { return (request[0] & kDeviceToHost) != 0; }

}  // namespace

void UsbHost::queue_request(const char* name, uint8_t type, uint8_t request, uint16_t value, uint16_t index,
                            uint16_t length, const std::vector<uint8_t>& out) {
  control_ = ControlTransfer{};
  control_.name = name;
  const uint8_t bytes[8] = {type,
                            request,
                            static_cast<uint8_t>(value),
                            static_cast<uint8_t>(value >> 8),
                            static_cast<uint8_t>(index),
                            static_cast<uint8_t>(index >> 8),
                            static_cast<uint8_t>(length),
                            static_cast<uint8_t>(length >> 8)};
  for (int i = 0; i < 8; ++i) control_.request[i] = bytes[i];
  control_.data = out;
  control_.deadline_ns = chip_.now_ns() + kStatusStageNs;
  control_active_ = true;
}

void UsbHost::begin_next_request() {
  const DeviceDescriptor& d = record_.device;
  while (step_ < kSteps) {
    const uint16_t string_type = 3 << 8;
    switch (step_) {
      case kDevice8:
        return queue_request("GET_DESCRIPTOR(device) at address 0", kDeviceToHost, kGetDescriptor, 0x0100, 0, 64);
      case kAddress: return queue_request("SET_ADDRESS", 0, kSetAddress, options_.address, 0, 0);
      case kDevice: return queue_request("GET_DESCRIPTOR(device)", kDeviceToHost, kGetDescriptor, 0x0100, 0, 18);
      case kConfigHead:
        return queue_request("GET_DESCRIPTOR(configuration, 9)", kDeviceToHost, kGetDescriptor, 0x0200, 0, 9);
      case kConfigAll:
        return queue_request("GET_DESCRIPTOR(configuration)", kDeviceToHost, kGetDescriptor, 0x0200, 0,
                             record_.cdc.total_length);
      case kLanguages:
        queue_request("GET_DESCRIPTOR(string 0)", kDeviceToHost, kGetDescriptor, string_type, 0, 255);
        control_.tolerate_stall = true;
        return;
      case kManufacturer:
      case kProduct:
      case kSerial: {
        const uint8_t index = step_ == kManufacturer ? d.manufacturer_index
                              : step_ == kProduct    ? d.product_index
                                                     : d.serial_index;
        if (index == 0) break;
        queue_request("GET_DESCRIPTOR(string)", kDeviceToHost, kGetDescriptor, string_type | index, language_, 255);
        control_.tolerate_stall = true;
        return;
      }
      case kConfigure:
        return queue_request("SET_CONFIGURATION", 0, kSetConfiguration, record_.cdc.configuration_value, 0, 0);
      case kLineCoding: {
        const uint32_t baud = options_.baud;  // dwDTERate, bCharFormat 0 (1 stop), bParityType 0, bDataBits 8
        const std::vector<uint8_t> coding = {static_cast<uint8_t>(baud),
                                             static_cast<uint8_t>(baud >> 8),
                                             static_cast<uint8_t>(baud >> 16),
                                             static_cast<uint8_t>(baud >> 24),
                                             0,
                                             0,
                                             8};
        return queue_request("CDC SET_LINE_CODING", kClassInterface, kSetLineCoding, 0, record_.cdc.comm_interface, 7,
                             coding);
      }
      case kLineState:
        line_state_pending_ = false;
        return queue_request("CDC SET_CONTROL_LINE_STATE", kClassInterface, kSetControlLineState, line_state_,
                             record_.cdc.comm_interface, 0);
      default: break;
    }
    ++step_;
  }
  control_active_ = false;
  if (phase_ == Phase::kRunning) return;  // a line-state change after enumeration
  phase_ = Phase::kRunning;
  record_.configured_ns = chip_.now_ns();
}

void UsbHost::set_line_state(bool dtr, bool rts) {
  line_state_ = static_cast<uint16_t>((dtr ? 1u : 0u) | (rts ? 2u : 0u));
  line_state_pending_ = true;
  wake();
}

bool UsbHost::send_line_state() {
  if (!line_state_pending_ || control_active_ || phase_ != Phase::kRunning) return false;
  line_state_pending_ = false;
  step_ = kSteps;  // no enumeration step follows
  queue_request("CDC SET_CONTROL_LINE_STATE", kClassInterface, kSetControlLineState, line_state_,
                record_.cdc.comm_interface, 0);
  return true;
}

bool UsbHost::run_control(int& budget) {
  if (!control_active_) return false;
  while (budget > 0 && control_active_ && (phase_ == Phase::kEnumerating || phase_ == Phase::kRunning) &&
         chip_.now_ns() >= phase_until_ns_) {
    ControlTransfer& t = control_;
    bool moved = false;
    if (t.stage == ControlTransfer::Stage::kSetup) {
      --budget;
      moved = control_setup(t);
    } else if (t.stage == ControlTransfer::Stage::kData) {
      moved = control_data(t, budget);
    } else if (t.stage == ControlTransfer::Stage::kStatus) {
      --budget;
      moved = control_status(t);
    }
    if (phase_ == Phase::kFailed) return true;
    if (t.stage == ControlTransfer::Stage::kDone) {
      control_done(t);
      continue;
    }
    if (!moved) break;
  }
  if (control_active_ && chip_.now_ns() > control_.deadline_ns) {
    const char* stage = control_.stage == ControlTransfer::Stage::kData ? "data" : "status";
    fail(control_.name + ": the device NAKed the " + stage + " stage past the USB 2.0 §9.2.6.4 limit");
  }
  return true;
}

bool UsbHost::control_setup(ControlTransfer& t) {
  const Handshake answer = device_.setup(current_address_, t.request);
  if (answer != Handshake::kAck) {
    const std::string why = device_.detached_reason();
    fail(t.name + ": SETUP got " + handshake_name(answer) + (why.empty() ? "" : " (" + why + ")"));
    return false;
  }
  const bool has_data = request_length(t.request) > 0;
  t.stage = has_data ? ControlTransfer::Stage::kData : ControlTransfer::Stage::kStatus;
  const SimTime limit = !has_data ? kStatusStageNs : device_to_host(t.request) ? kDataStageNs : kOutDataStageNs;
  t.deadline_ns = chip_.now_ns() + limit;
  return true;
}

bool UsbHost::control_data(ControlTransfer& t, int& budget) {
  const size_t wanted = request_length(t.request);
  bool moved = false;
  while (budget > 0 && t.stage == ControlTransfer::Stage::kData) {
    --budget;
    uint8_t packet[64];
    size_t length = 0;
    const bool in = device_to_host(t.request);
    const size_t chunk = in ? 0 : std::min<size_t>(max_packet0_, t.data.size() - t.out_sent);
    const Handshake answer = in ? device_.in(current_address_, 0, packet, max_packet0_, length)
                                : device_.out(current_address_, 0, t.data.data() + t.out_sent, chunk);
    if (answer == Handshake::kNak) return moved;
    if (answer == Handshake::kStall && t.tolerate_stall) {
      t.stalled = true;
      t.stage = ControlTransfer::Stage::kDone;
      return true;
    }
    if (answer != Handshake::kAck) {
      const std::string why = device_.detached_reason();
      fail(t.name + ": data stage got " + handshake_name(answer) + (why.empty() ? "" : " (" + why + ")"));
      return false;
    }
    moved = true;
    if (in) t.data.insert(t.data.end(), packet, packet + length);
    t.out_sent += chunk;
    const bool last = in ? (length < max_packet0_ || t.data.size() >= wanted) : t.out_sent >= t.data.size();
    if (in && t.data.size() > wanted) {
      fail(t.name + ": the device sent more bytes than wLength asked for");
      return false;
    }
    if (last) {
      t.stage = ControlTransfer::Stage::kStatus;
      t.deadline_ns = chip_.now_ns() + kStatusStageNs;
    }
  }
  return moved;
}

bool UsbHost::control_status(ControlTransfer& t) {
  uint8_t packet[64];
  size_t length = 0;
  // The status stage runs opposite to the data (IN after OUT or no data, OUT after IN).
  const Handshake answer = device_to_host(t.request) ? device_.out(current_address_, 0, nullptr, 0)
                                                     : device_.in(current_address_, 0, packet, sizeof packet, length);
  if (answer == Handshake::kNak) return false;
  if (answer == Handshake::kStall && t.tolerate_stall) {
    t.stalled = true;
  } else if (answer != Handshake::kAck) {
    fail(t.name + ": status stage got " + handshake_name(answer));
    return false;
  } else if (length != 0) {
    fail(t.name + ": the status stage carried data");
    return false;
  }
  t.stage = ControlTransfer::Stage::kDone;
  return true;
}

void UsbHost::control_done(ControlTransfer& t) {
  control_active_ = false;
  if (!handle_answer(t)) return;
  ++step_;
  // The host's software sees the transfer complete and submits the next one: not before the
  // next (micro)frame, so the device's interrupt for this one runs first, as on a real bus.
  const SimTime next_frame = next_boundary(period_ns());
  if (phase_until_ns_ < next_frame) phase_until_ns_ = next_frame;
  begin_next_request();
}

}  // namespace stepdance::sim::image::usb
