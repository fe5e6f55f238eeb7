// A fixed-capacity list of values in registration order; no heap, overflow is reported.
#pragma once

#include <stddef.h>

#include "stepdance/core/status.hpp"

namespace stepdance {

/// An ordered list holding at most Capacity elements in inline storage.
/// Appending to a full list returns Status::kFull and leaves the list unchanged.
/// Context: mutate from the loop only; iterating is safe from any context while no one mutates.
template <typename T, size_t Capacity>
class FixedList {
 public:
  static_assert(Capacity > 0, "a FixedList needs room for at least one element");

  /// Appends value at the end. Returns kFull when there is no room.
  Status push_back(const T& value) {
    if (size_ == Capacity) return Status::kFull;
    items_[size_] = value;
    ++size_;
    return Status::kOk;
  }

  /// Removes the first element equal to value, keeping the order of the rest.
  /// Returns true if an element was removed.
  bool remove(const T& value) {
    for (size_t i = 0; i < size_; ++i) {
      if (items_[i] == value) {
        for (size_t j = i + 1; j < size_; ++j) items_[j - 1] = items_[j];
        --size_;
        return true;
      }
    }
    return false;
  }

  /// True if an element equal to value is in the list.
  bool contains(const T& value) const {
    for (size_t i = 0; i < size_; ++i) {
      if (items_[i] == value) return true;
    }
    return false;
  }

  void clear() { size_ = 0; }
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  bool full() const { return size_ == Capacity; }
  static constexpr size_t capacity() { return Capacity; }

  T& operator[](size_t index) { return items_[index]; }
  const T& operator[](size_t index) const { return items_[index]; }
  T* begin() { return items_; }
  T* end() { return items_ + size_; }
  const T* begin() const { return items_; }
  const T* end() const { return items_ + size_; }

 private:
  T items_[Capacity] = {};
  size_t size_ = 0;
};

}  // namespace stepdance
