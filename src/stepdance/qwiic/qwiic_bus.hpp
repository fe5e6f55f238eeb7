// QwiicBus: the queue of I2C transfers on one QWIIC connector, served from the loop.
#pragma once

#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/hal/i2c.hpp"

namespace stepdance {

/// QWIIC connector numbers (the silkscreen's QWIIC0 and QWIIC1).
constexpr uint8_t QWIIC_0 = 0;
constexpr uint8_t QWIIC_1 = 1;

/// One queued transfer and its outcome, owned by the driver that submits it (the queue keeps
/// only a pointer). `done` runs in the loop when the transfer ends.
struct I2cRequest {
  using Done = void (*)(void* context, hal::I2cResult result);
  hal::I2cTransfer transfer;
  Done done = nullptr;
  void* context = nullptr;
  /// kPending from submit() until the transfer ends, then its result.
  hal::I2cResult result = hal::I2cResult::kIdle;
  bool in_flight() const { return result == hal::I2cResult::kPending; }
};

/// Serves the drivers sharing one bus: requests run one at a time, in submission order, and
/// across all buses at most one transfer starts per loop pass. With transfers of at most
/// hal::kI2cMaxTransferBytes a pass spends at most one transfer's wire time on I2C (0.9 ms at
/// 400 kHz), however many drivers queue work. Counters: one per result, refusals, high water.
class QwiicBus : public Block {
 public:
  const char* type_name() const override { return "QwiicBus"; }
  /// Bus `index`: QWIIC_0 or QWIIC_1. Context: any (constructors of globals).
  explicit QwiicBus(uint8_t index) : index_(index) {}

  /// Claims the bus at `clock_hz` and registers in the loop stage; calling it again is
  /// harmless. Errors come from the HAL (kNoSuchPin for a board without the bus). Context: loop.
  Status begin(uint32_t clock_hz = hal::kI2cFastModeHz);
  bool begun() const { return begun_; }
  uint8_t index() const { return index_; }

  /// Queues `request`. kNotStarted before begin(), kBusy if it is already queued or on the
  /// wire, kBadArgument for an oversized part, kFull when kCapacity requests wait (counted).
  /// Context: loop.
  Status submit(I2cRequest& request);
  /// Drops every waiting request and forgets the pass budget (tests, simulator resets). Context: loop.
  void clear();
  /// Requests waiting or on the wire. Context: loop.
  uint8_t queued() const { return static_cast<uint8_t>(count_ + (active_ != nullptr ? 1 : 0)); }

  /// Finishes the transfer on the wire (calling its `done`) and starts the next one if no bus
  /// started one in this loop pass. Called by the engine. Context: loop.
  void loop() override { service(); }
  void report_counters(CounterSink& sink) const override;

  /// Most requests that can wait at once.
  static constexpr uint8_t kCapacity = 8;

 private:
  void service();
  bool finish_active();
  void start_next();
  void count(hal::I2cResult result);

  uint8_t index_;
  bool begun_ = false;
  I2cRequest* waiting_[kCapacity] = {};
  uint8_t head_ = 0;
  uint8_t count_ = 0;
  I2cRequest* active_ = nullptr;
  uint64_t results_[7] = {};
  uint64_t refused_ = 0;
  uint64_t bytes_ = 0;
  uint8_t high_water_ = 0;
};

/// The board's two buses, shared by every driver. Context: any.
QwiicBus& qwiic_bus(uint8_t index);

}  // namespace stepdance
