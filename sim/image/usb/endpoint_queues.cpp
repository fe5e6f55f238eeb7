// dQH/dTD handling of the device controller (RM ch. 42, device data structures and "Executing a
// transfer descriptor"): prime loads a dTD into the dQH overlay, packets move bytes through its
// five buffer pages and count its total bytes down, retiring writes the token back to the dTD
// and follows its next pointer.
#include "image/usb/endpoint_queues.hpp"

#include <algorithm>
#include <cstdio>

namespace stepdance::sim::image::usb {
namespace {

constexpr uint32_t kPointerMask = ~0x1Fu;  // dTDs are 32-byte aligned: pointer bits 31:5
constexpr uint32_t kPageMask = ~0xFFFu;
constexpr uint32_t kDtdWords = kDtdBytes / 4;

uint32_t token_total(uint32_t token) { return (token >> kTokenTotalShift) & kTokenTotalMask; }
uint32_t with_total(uint32_t token, uint32_t total) {
  return (token & ~(kTokenTotalMask << kTokenTotalShift)) | (total << kTokenTotalShift);
}

}  // namespace

void EndpointQueues::clear() { progress_.fill({}); }

bool EndpointQueues::read_word(uint32_t address, uint32_t& value) {
  if (chip_.read_memory(address, &value, 4)) return true;
  if (error_.empty()) {
    char text[96];
    std::snprintf(text, sizeof text, "USB1 DMA read at 0x%08X is outside RAM", address);
    error_ = text;
  }
  return false;
}

bool EndpointQueues::write_word(uint32_t address, uint32_t value) {
  if (chip_.write_memory(address, &value, 4)) return true;
  if (error_.empty()) {
    char text[96];
    std::snprintf(text, sizeof text, "USB1 DMA write at 0x%08X is outside RAM", address);
    error_ = text;
  }
  return false;
}

uint32_t EndpointQueues::max_packet(unsigned queue) {
  uint32_t capabilities = 0;
  if (!read_word(head(queue) + kDqhCapabilities, capabilities)) return 0;
  return (capabilities >> kCapMaxPacketShift) & kCapMaxPacketMask;
}

bool EndpointQueues::interrupt_on_setup(unsigned queue) {
  uint32_t capabilities = 0;
  return read_word(head(queue) + kDqhCapabilities, capabilities) && (capabilities & kCapIos) != 0;
}

bool EndpointQueues::prime(unsigned queue) {
  uint32_t next = 0;
  if (!read_word(head(queue) + kDqhOverlay + kDtdNext, next) || (next & kDtdTerminate)) return false;
  uint32_t words[kDtdWords];
  const uint32_t dtd = next & kPointerMask;
  for (uint32_t i = 0; i < kDtdWords; ++i) {
    if (!read_word(dtd + 4 * i, words[i])) return false;
  }
  if (!(words[1] & kTokenActive)) return false;
  if (!write_word(head(queue) + kDqhCurrentDtd, dtd)) return false;
  for (uint32_t i = 0; i < kDtdWords; ++i) {
    if (!write_word(head(queue) + kDqhOverlay + 4 * i, words[i])) return false;
  }
  progress_[queue] = {};
  return true;
}

bool EndpointQueues::buffer_address(unsigned queue, uint32_t position, uint32_t& address) {
  uint32_t page0 = 0;
  if (!read_word(head(queue) + kDqhOverlay + kDtdPages, page0)) return false;
  const uint32_t offset = (page0 & 0xFFFu) + position;
  const uint32_t page = offset >> 12;
  if (page > 4) {
    if (error_.empty()) error_ = "USB1 transfer runs past its dTD's fifth buffer page";
    return false;
  }
  uint32_t base = page0 & kPageMask;
  if (page > 0 && !read_word(head(queue) + kDqhOverlay + kDtdPages + 4 * page, base)) return false;
  address = (base & kPageMask) + (offset & 0xFFFu);
  return true;
}

bool EndpointQueues::copy_buffer(unsigned queue, uint8_t* data, size_t length, bool to_memory) {
  size_t copied = 0;
  while (copied < length) {
    uint32_t address = 0;
    if (!buffer_address(queue, progress_[queue].done_bytes + static_cast<uint32_t>(copied), address)) return false;
    const size_t chunk = std::min<size_t>(length - copied, 0x1000u - (address & 0xFFFu));
    const bool ok = to_memory ? chip_.write_memory(address, data + copied, chunk)
                              : chip_.read_memory(address, data + copied, chunk);
    if (!ok) {
      if (error_.empty()) {
        char text[96];
        std::snprintf(text, sizeof text, "USB1 DMA of %zu bytes at 0x%08X is outside RAM", chunk, address);
        error_ = text;
      }
      return false;
    }
    copied += chunk;
  }
  progress_[queue].done_bytes += static_cast<uint32_t>(length);
  return true;
}

bool EndpointQueues::retire(unsigned queue, uint32_t token, PacketResult& result) {
  token &= ~kTokenActive;
  uint32_t current = 0, next = 0;
  if (!read_word(head(queue) + kDqhCurrentDtd, current)) return false;
  if (!write_word(head(queue) + kDqhOverlay + kDtdToken, token)) return false;
  if (!write_word((current & kPointerMask) + kDtdToken, token)) return false;
  result.retired = true;
  result.interrupt = (token & kTokenIoc) != 0;
  progress_[queue] = {};
  // The successor is read from the retired dTD in memory: software may have linked it while
  // this one was active (the ATDTW protocol exists for exactly that).
  if (!read_word((current & kPointerMask) + kDtdNext, next)) return false;
  if (!write_word(head(queue) + kDqhOverlay + kDtdNext, next)) return false;
  if (!(next & kDtdTerminate)) result.next_primed = prime(queue);
  return true;
}

bool EndpointQueues::out_packet(unsigned queue, const uint8_t* data, size_t length, PacketResult& result) {
  uint32_t token = 0;
  if (!read_word(head(queue) + kDqhOverlay + kDtdToken, token)) return false;
  const uint32_t total = token_total(token);
  const uint32_t packet = max_packet(queue);
  // More bytes than the dTD has room for: the room is filled and the dTD halts with a data
  // buffer error (the transfer overflowed).
  const size_t taken = std::min<size_t>(length, total);
  if (!copy_buffer(queue, const_cast<uint8_t*>(data), taken, true)) return false;
  token = with_total(token, total - static_cast<uint32_t>(taken));
  if (taken < length) token |= kTokenHalted | kTokenBufferError;
  result.bytes = taken;
  if (token_total(token) == 0 || length < packet || taken < length) return retire(queue, token, result);
  return write_word(head(queue) + kDqhOverlay + kDtdToken, token);
}

bool EndpointQueues::in_packet(unsigned queue, uint8_t* data, size_t capacity, PacketResult& result) {
  uint32_t token = 0, capabilities = 0;
  if (!read_word(head(queue) + kDqhOverlay + kDtdToken, token)) return false;
  if (!read_word(head(queue) + kDqhCapabilities, capabilities)) return false;
  if (progress_[queue].zero_length_owed) return retire(queue, token, result);
  const uint32_t total = token_total(token);
  const uint32_t packet = (capabilities >> kCapMaxPacketShift) & kCapMaxPacketMask;
  const size_t length = std::min<size_t>({total, packet, capacity});
  if (!copy_buffer(queue, data, length, false)) return false;
  token = with_total(token, total - static_cast<uint32_t>(length));
  result.bytes = length;
  if (token_total(token) == 0) {
    // A transfer that ends on a full packet is closed by a zero-length packet unless the dQH's
    // ZLT bit turns that off (RM: dQH "ZLT").
    const bool owe_zero = length == packet && length > 0 && !(capabilities & kCapZltDisabled);
    if (!owe_zero) return retire(queue, token, result);
    progress_[queue].zero_length_owed = true;
  }
  return write_word(head(queue) + kDqhOverlay + kDtdToken, token);
}

bool EndpointQueues::store_setup(const uint8_t request[8]) {
  if (chip_.write_memory(head(0) + kDqhSetupBuffer, request, 8)) return true;
  if (error_.empty()) error_ = "USB1 setup buffer write is outside RAM";
  return false;
}

}  // namespace stepdance::sim::image::usb
