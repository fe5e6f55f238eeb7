// USB1's cable side: attach, bus reset and the host's transactions (RM ch. 42, "Device
// operational model": bus reset, setup handling, and the endpoint response matrix — a primed
// endpoint ACKs, an unprimed one NAKs, a stalled one STALLs).
#include "image/usb/usb_controller.hpp"

#include "kernel/scheduler/scheduler.hpp"

namespace stepdance::sim::image::usb {

bool UsbController::attached() const { return detached_reason().empty(); }

std::string UsbController::detached_reason() const {
  if ((mode_ & kModeCmMask) != kModeCmDevice) return "USB1_USBMODE.CM is not 2 (device mode)";
  if (!(command_ & kCmdRunStop)) return "USB1_USBCMD.RS is 0 (no pull-up)";
  if (!phy_.ready()) return phy_.not_ready_reason();
  if (!queues_.error().empty()) return queues_.error();
  return "";
}

void UsbController::bus_reset_begin() {
  in_reset_ = true;
  port_enabled_ = high_speed_ = false;
  // A bus reset returns the device to the default address (USB 2.0 §9.1.1.3).
  address_ = 0;
  address_pending_ = false;
  device_address_register_ = 0;
  chip_.scheduler().cancel(sof_);
  raise(kStsUri);
}

BusSpeed UsbController::bus_reset_end() {
  in_reset_ = false;
  port_enabled_ = true;
  // The chirp handshake reaches high speed unless PORTSC1.PFSC forces full speed.
  high_speed_ = !(port_writable_ & kPortPfsc);
  port_up_ns_ = chip_.now_ns();
  raise(kStsPci);  // device mode: port change at the end of reset, HSP now valid
  schedule_sof();
  return high_speed_ ? BusSpeed::kHigh : BusSpeed::kFull;
}

bool UsbController::answers(uint8_t address) const { return attached() && port_enabled_ && address == address_; }

Handshake UsbController::endpoint_gate(unsigned endpoint, bool in) const {
  if (endpoint >= kEndpoints) return Handshake::kNoResponse;
  const uint32_t control = endpoint_control_[endpoint];
  if (!(control & (in ? kCtrlTxEnable : kCtrlRxEnable))) return Handshake::kNoResponse;
  if (control & (in ? kCtrlTxStall : kCtrlRxStall)) return Handshake::kStall;
  return Handshake::kAck;
}

Handshake UsbController::setup(uint8_t address, const uint8_t request[8]) {
  if (!answers(address)) return Handshake::kNoResponse;
  if (!queues_.store_setup(request)) {
    raise(kStsSei);
    return Handshake::kNoResponse;
  }
  setup_status_ |= 1u;
  command_ &= ~kCmdSetupTripwire;  // tells software a new setup replaced the one it was reading
  // A setup token clears a protocol stall of endpoint 0 (USB 2.0 §8.5.3.4).
  endpoint_control_[0] &= ~(kCtrlRxStall | kCtrlTxStall);
  if (queues_.interrupt_on_setup(0)) raise(kStsUi);
  return Handshake::kAck;
}

Handshake UsbController::out(uint8_t address, uint8_t endpoint, const uint8_t* data, size_t length) {
  if (!answers(address)) return Handshake::kNoResponse;
  const Handshake gate = endpoint_gate(endpoint, false);
  if (gate != Handshake::kAck) return gate;
  const unsigned queue = queue_index(endpoint, false);
  if (!(endpoint_status_ & queue_bit(queue))) return Handshake::kNak;  // no dTD: the bytes wait
  PacketResult result;
  if (!queues_.out_packet(queue, data, length, result)) {
    raise(kStsSei);
    return Handshake::kNoResponse;
  }
  finish_packet(queue, result);
  return Handshake::kAck;
}

Handshake UsbController::in(uint8_t address, uint8_t endpoint, uint8_t* data, size_t capacity, size_t& length) {
  length = 0;
  if (!answers(address)) return Handshake::kNoResponse;
  const Handshake gate = endpoint_gate(endpoint, true);
  if (gate != Handshake::kAck) return gate;
  const unsigned queue = queue_index(endpoint, true);
  if (!(endpoint_status_ & queue_bit(queue))) return Handshake::kNak;
  PacketResult result;
  if (!queues_.in_packet(queue, data, capacity, result)) {
    raise(kStsSei);
    return Handshake::kNoResponse;
  }
  length = result.bytes;
  finish_packet(queue, result);
  // USBADRA: the new address takes effect once this IN on endpoint 0 (the SET_ADDRESS status
  // stage) has completed.
  if (endpoint == 0 && result.retired && address_pending_) {
    address_ = static_cast<uint8_t>(device_address_register_ >> kDeviceAddrShift);
    address_pending_ = false;
  }
  return Handshake::kAck;
}

void UsbController::finish_packet(unsigned queue, const PacketResult& result) {
  if (!result.retired) return;
  const uint32_t bit = queue_bit(queue);
  // ENDPTCOMPLETE marks every retired dTD; USBINT only those with IOC (RM USB_nENDPTCOMPLETE).
  endpoint_complete_ |= bit;
  if (!result.next_primed) endpoint_status_ &= ~bit;
  if (result.interrupt) {
    raise(kStsUi);
  } else {
    update_irq();
  }
}

}  // namespace stepdance::sim::image::usb
