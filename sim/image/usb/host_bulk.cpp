// The emulated host's serial traffic once enumerated: bulk IN polling hands the device's bytes
// to the world, bulk OUT carries the world's bytes to the device. A NAK (no dTD primed) leaves
// the bytes with the host; nothing is dropped. When the world does not take every IN byte the
// host keeps the rest and stops polling IN until they are taken (as a PC's full tty buffer).
#include <algorithm>

#include "image/usb/usb_host.hpp"

namespace stepdance::sim::image::usb {
namespace {

constexpr size_t kMaxPacket = 512;

}  // namespace

bool UsbHost::run_bulk(int& budget) {
  bool moved = false;
  if (!in_held_.empty()) {
    const size_t taken = world_.serial_from_device(chip_.now_ns(), in_held_.data(), in_held_.size());
    in_held_.erase(in_held_.begin(), in_held_.begin() + static_cast<std::ptrdiff_t>(taken));
    moved = taken > 0;
  }
  if (in_held_.empty()) moved = bulk_in(budget) || moved;
  moved = bulk_out(budget) || moved;
  return moved;
}

bool UsbHost::bulk_in(int& budget) {
  const CdcFunction& cdc = record_.cdc;
  const size_t packet_size = std::min<size_t>(cdc.bulk_in_max_packet, kMaxPacket);
  bool moved = false;
  while (budget > 0 && phase_ == Phase::kRunning) {
    --budget;
    uint8_t packet[kMaxPacket];
    size_t length = 0;
    const Handshake answer = device_.in(current_address_, cdc.bulk_in & 0x0Fu, packet, packet_size, length);
    if (answer == Handshake::kNak) break;
    if (answer != Handshake::kAck) {
      const std::string why = device_.detached_reason();
      fail(std::string("bulk IN endpoint got ") + handshake_name(answer) + (why.empty() ? "" : " (" + why + ")"));
      break;
    }
    moved = true;
    const size_t taken = length == 0 ? 0 : world_.serial_from_device(chip_.now_ns(), packet, length);
    if (taken < length) {
      in_held_.assign(packet + taken, packet + length);
      break;
    }
    if (length < packet_size) break;  // a short packet ends the transfer: poll again next frame
  }
  return moved;
}

bool UsbHost::bulk_out(int& budget) {
  const CdcFunction& cdc = record_.cdc;
  while (out_.size() < options_.out_buffer_bytes) {
    uint8_t chunk[kMaxPacket];
    const size_t room = std::min(sizeof chunk, options_.out_buffer_bytes - out_.size());
    const size_t got = world_.serial_to_device(chip_.now_ns(), chunk, room);
    if (got == 0) break;
    out_.insert(out_.end(), chunk, chunk + got);
  }
  const size_t packet_size = std::min<size_t>(cdc.bulk_out_max_packet, kMaxPacket);
  bool moved = false;
  while (budget > 0 && !out_.empty() && phase_ == Phase::kRunning) {
    --budget;
    uint8_t packet[kMaxPacket];
    const size_t length = std::min(packet_size, out_.size());
    std::copy(out_.begin(), out_.begin() + static_cast<std::ptrdiff_t>(length), packet);
    const Handshake answer = device_.out(current_address_, cdc.bulk_out & 0x0Fu, packet, length);
    if (answer == Handshake::kNak) break;  // no dTD primed: the bytes wait here
    if (answer != Handshake::kAck) {
      const std::string why = device_.detached_reason();
      fail(std::string("bulk OUT endpoint got ") + handshake_name(answer) + (why.empty() ? "" : " (" + why + ")"));
      break;
    }
    out_.erase(out_.begin(), out_.begin() + static_cast<std::ptrdiff_t>(length));
    moved = true;
  }
  return moved;
}

}  // namespace stepdance::sim::image::usb
