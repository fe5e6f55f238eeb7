// QwiicBus: a FIFO of I2cRequest pointers, one transfer started per loop pass over all buses.
#include "stepdance/qwiic/qwiic_bus.hpp"

#include "stepdance/core/engine.hpp"

namespace stepdance {
namespace {

// The loop pass in which some bus last started a transfer (shared: the budget is per pass).
uint32_t pass_of_last_start = 0;
bool started_in_any_pass = false;

// At most one transfer starts per loop pass across both buses: on a backend whose transfers block,
// each start costs the loop a transfer's wire time (≤ 0.9 ms at 400 kHz), and one per pass bounds it.
bool pass_budget_left() { return !started_in_any_pass || pass_of_last_start != engine().loop_passes(); }

void spend_pass_budget() {
  started_in_any_pass = true;
  pass_of_last_start = engine().loop_passes();
}

bool is_final(hal::I2cResult result) { return result != hal::I2cResult::kIdle && result != hal::I2cResult::kPending; }

}  // namespace

namespace hal {
const char* to_string(I2cResult result) {
  switch (result) {
    case I2cResult::kIdle: return "idle";
    case I2cResult::kPending: return "pending";
    case I2cResult::kOk: return "ok";
    case I2cResult::kAddressNack: return "address nack";
    case I2cResult::kDataNack: return "data nack";
    case I2cResult::kBusError: return "bus error";
    case I2cResult::kTimeout: return "timeout";
  }
  return "?";
}
}  // namespace hal

// Made on first use, like engine(): a sketch without QWIIC devices carries neither bus.
QwiicBus& qwiic_bus(uint8_t index) {
  static QwiicBus qwiic0(QWIIC_0);
  static QwiicBus qwiic1(QWIIC_1);
  return index == QWIIC_0 ? qwiic0 : qwiic1;
}

// Loop context. Several devices share a bus and each calls begin(); a second call is harmless (the
// engine ignores a block registered twice).
Status QwiicBus::begin(uint32_t clock_hz) {
  const Status claimed = hal::i2c_begin(index_, clock_hz);
  if (claimed != Status::kOk) return claimed;
  begun_ = true;
  return register_in(Stage::kLoop);
}

void QwiicBus::clear() {
  head_ = 0;
  count_ = 0;
  active_ = nullptr;
  started_in_any_pass = false;
}

// Any context that is not an ISR. Requests are queued by pointer (no copy, no heap): the caller owns the
// request and must not reuse it while in_flight(). A full queue refuses and counts (refused_full).
Status QwiicBus::submit(I2cRequest& request) {
  if (!begun_) return Status::kNotStarted;
  if (request.in_flight()) return Status::kBusy;
  const hal::I2cTransfer& transfer = request.transfer;
  if (transfer.write_length > hal::kI2cMaxTransferBytes || transfer.read_length > hal::kI2cMaxTransferBytes ||
      transfer.address > 0x7F) {
    return Status::kBadArgument;
  }
  if (count_ == kCapacity) {
    ++refused_;
    return Status::kFull;
  }
  request.result = hal::I2cResult::kPending;
  waiting_[(head_ + count_) % kCapacity] = &request;
  ++count_;
  if (queued() > high_water_) high_water_ = queued();
  return Status::kOk;
}

// Loop context: polls the transfer on the wire (non-blocking backends) or starts the next one.
void QwiicBus::service() {
  if (active_ != nullptr && !finish_active()) return;  // still on the wire
  if (count_ == 0 || !pass_budget_left()) return;
  start_next();
  // A blocking backend has already finished it: deliver the result in this same pass.
  if (active_ != nullptr) finish_active();
}

// True once the bus is free again (the active request, if any, has its result).
// The done callback runs after active_ is cleared, so it may submit the next request of a chain
// (OledDisplay's window → data) without seeing the bus busy.
bool QwiicBus::finish_active() {
  const hal::I2cResult result = hal::i2c_poll(index_);
  if (!is_final(result)) return false;
  I2cRequest* finished = active_;
  active_ = nullptr;
  count(result);
  finished->result = result;
  if (finished->done != nullptr) finished->done(finished->context, result);  // may submit again
  return true;
}

void QwiicBus::start_next() {
  I2cRequest* next = waiting_[head_];
  head_ = static_cast<uint8_t>((head_ + 1) % kCapacity);
  --count_;
  spend_pass_budget();
  const Status started = hal::i2c_start(index_, next->transfer);
  if (started != Status::kOk) {
    // The backend refused it outright (a bus left mid-transfer by others, a lost claim): the
    // request fails as a bus error rather than waiting forever.
    count(hal::I2cResult::kBusError);
    next->result = hal::I2cResult::kBusError;
    if (next->done != nullptr) next->done(next->context, hal::I2cResult::kBusError);
    return;
  }
  bytes_ += next->transfer.write_length + next->transfer.read_length;
  active_ = next;
}

void QwiicBus::count(hal::I2cResult result) {
  const uint8_t slot = static_cast<uint8_t>(result);
  if (slot < sizeof results_ / sizeof results_[0]) ++results_[slot];
}

void QwiicBus::report_counters(CounterSink& sink) const {
  sink.counter("bus", index_);
  sink.counter("ok", results_[static_cast<uint8_t>(hal::I2cResult::kOk)]);
  sink.counter("address_nack", results_[static_cast<uint8_t>(hal::I2cResult::kAddressNack)]);
  sink.counter("data_nack", results_[static_cast<uint8_t>(hal::I2cResult::kDataNack)]);
  sink.counter("bus_error", results_[static_cast<uint8_t>(hal::I2cResult::kBusError)]);
  sink.counter("timeout", results_[static_cast<uint8_t>(hal::I2cResult::kTimeout)]);
  sink.counter("refused_full", refused_);
  sink.counter("bytes", bytes_);
  sink.counter("queue_high_water", high_water_);
}

}  // namespace stepdance
