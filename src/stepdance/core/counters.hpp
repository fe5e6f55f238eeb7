// Named counters: how a block reports its statistics without anyone knowing its class.
#pragma once

#include <stdint.h>

namespace stepdance {

/// Receives the counters of one block, one call per counter. Names are static strings in
/// snake_case ("unreachable", "sent_x_forward"). Context: loop.
class CounterSink {
 public:
  virtual void counter(const char* name, uint64_t value) = 0;

 protected:
  ~CounterSink() = default;
};

}  // namespace stepdance
