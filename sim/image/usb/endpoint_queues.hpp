// The device controller's view of the endpoint queue heads and transfer descriptors in memory.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "image/chip/chip_context.hpp"
#include "image/usb/usb_registers.hpp"

namespace stepdance::sim::image::usb {

/// Queue head index of endpoint `endpoint` in direction `in` (dQH list order: OUT, IN, OUT, …).
constexpr unsigned queue_index(unsigned endpoint, bool in) { return endpoint * 2 + (in ? 1 : 0); }
/// The ENDPTPRIME/ENDPTSTAT/ENDPTCOMPLETE bit of a queue head (receive 15:0, transmit 31:16).
constexpr uint32_t queue_bit(unsigned queue) { return 1u << ((queue / 2) + ((queue & 1) ? 16 : 0)); }

/// What a packet did to the active transfer descriptor.
struct PacketResult {
  size_t bytes = 0;          ///< bytes moved
  bool retired = false;      ///< the dTD is done (written back to memory)
  bool interrupt = false;    ///< it was retired with IOC set
  bool next_primed = false;  ///< the dTD's successor was loaded: the endpoint stays primed
};

/// Reads and writes dQHs and dTDs through ChipContext::read_memory/write_memory exactly as the
/// RM lays them out (usb_registers.hpp), and keeps the controller's per-endpoint progress. All
/// calls run on the simulator's thread. A memory access outside RAM sets error() and fails.
class EndpointQueues {
 public:
  static constexpr unsigned kQueues = kEndpoints * 2;

  explicit EndpointQueues(ChipContext& chip) : chip_(chip) {}

  /// ENDPTLISTADDR: the dQH array's address (2 KB aligned).
  void set_list_address(uint32_t address) { list_ = address; }
  uint32_t list_address() const { return list_; }
  /// Forgets every endpoint's progress (controller reset, flush of all).
  void clear();

  /// Prime: loads the dTD the dQH's next pointer names into the overlay. False if the pointer
  /// terminates, the dTD is not active, or memory failed.
  bool prime(unsigned queue);
  /// Flush: drops the endpoint's progress (ENDPTFLUSH).
  void flush(unsigned queue) { progress_[queue] = {}; }

  /// The dQH's max packet length (bytes) and whether it interrupts on setup.
  uint32_t max_packet(unsigned queue);
  bool interrupt_on_setup(unsigned queue);

  /// Receives one OUT packet into the active dTD's buffer.
  bool out_packet(unsigned queue, const uint8_t* data, size_t length, PacketResult& result);
  /// Sends one IN packet (≤ max packet, ≤ capacity) from the active dTD's buffer.
  bool in_packet(unsigned queue, uint8_t* data, size_t capacity, PacketResult& result);
  /// Stores a setup packet in dQH 0's setup buffer.
  bool store_setup(const uint8_t request[8]);

  /// The first memory failure, in one line ("" if none).
  const std::string& error() const { return error_; }

 private:
  struct Progress {
    uint32_t done_bytes = 0;  ///< bytes moved by the active dTD so far
    bool zero_length_owed = false;
  };

  uint32_t head(unsigned queue) const { return list_ + queue * kDqhStrideBytes; }
  bool read_word(uint32_t address, uint32_t& value);
  bool write_word(uint32_t address, uint32_t value);
  bool buffer_address(unsigned queue, uint32_t position, uint32_t& address);
  bool copy_buffer(unsigned queue, uint8_t* data, size_t length, bool to_memory);
  bool retire(unsigned queue, uint32_t token, PacketResult& result);

  ChipContext& chip_;
  uint32_t list_ = 0;
  std::array<Progress, kQueues> progress_{};
  std::string error_;
};

}  // namespace stepdance::sim::image::usb
