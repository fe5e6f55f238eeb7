// Loop-side pumps between a frame's RAM ring and a file: the frame never touches storage.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/file_storage.hpp"
#include "stepdance/core/spsc_queue.hpp"
#include "stepdance/core/status.hpp"

namespace stepdance::recording {

/// Bytes moved between a ring and a file per storage call: one SD sector.
constexpr size_t kStorageChunkBytes = 512;

/// Longest file name the storage takes, plus its NUL.
using FileName = char[FileStorage::kMaxNameLength + 1];

/// Writes "<name><suffix>" into `out`; false (out untouched) for an empty name or one that does
/// not fit the storage's names with the longest suffix, "_len.bin". Context: any.
inline bool recording_file_name(const char* name, const char* suffix, FileName& out) {
  size_t length = 0;
  while (name != nullptr && name[length] != '\0') ++length;
  size_t suffix_length = 0;
  while (suffix[suffix_length] != '\0') ++suffix_length;
  constexpr size_t kLongestSuffix = 8;  // "_len.bin"
  if (length == 0 || length + kLongestSuffix > FileStorage::kMaxNameLength) return false;
  for (size_t i = 0; i < length; ++i) out[i] = name[i];
  for (size_t i = 0; i <= suffix_length; ++i) out[length + i] = suffix[i];
  return true;
}

/// A RAM ring of recording bytes: the frame is one end, the loop the other.
template <size_t Capacity>
using ByteRing = SpscQueue<uint8_t, Capacity>;

/// Writes whole chunks the frame has queued into `handle` (with `flush_all`, the remainder too).
/// Stops at the first storage error and returns it; `written` counts the bytes written.
/// Context: loop (the ring's consumer).
template <size_t Capacity>
Status drain_ring_to_file(ByteRing<Capacity>& ring, FileStorage& storage, int handle, bool flush_all,
                          uint64_t& written) {
  uint8_t chunk[kStorageChunkBytes];
  while (ring.size() >= kStorageChunkBytes || (flush_all && !ring.empty())) {
    size_t length = 0;
    while (length < kStorageChunkBytes && ring.pop(chunk[length]) == Status::kOk) ++length;
    const Status status = storage.write(handle, chunk, length);
    if (status != Status::kOk) return status;
    written += length;
  }
  return Status::kOk;
}

/// Reads chunks from `handle` into the ring while a whole chunk fits; sets end_of_file when a
/// read comes back short. Returns the first storage error. Context: loop (the ring's producer).
template <size_t Capacity>
Status fill_ring_from_file(ByteRing<Capacity>& ring, FileStorage& storage, int handle, bool& end_of_file,
                           uint64_t& read_total) {
  uint8_t chunk[kStorageChunkBytes];
  while (!end_of_file && Capacity - ring.size() >= kStorageChunkBytes) {
    size_t length = 0;
    const Status status = storage.read(handle, chunk, sizeof(chunk), length);
    if (status != Status::kOk) return status;
    for (size_t i = 0; i < length; ++i) ring.push(chunk[i]);
    read_total += length;
    if (length < sizeof(chunk)) end_of_file = true;
  }
  return Status::kOk;
}

}  // namespace stepdance::recording
