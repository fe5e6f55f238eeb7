// Counters and warnings handed out one at a time (counter_report.hpp).
#include "stepdance/core/counter_report.hpp"

#include "stepdance/core/block.hpp"
#include "stepdance/core/counters.hpp"
#include "stepdance/core/engine.hpp"
#include "stepdance/core/fault.hpp"

namespace stepdance {
namespace {

// Numbers blocks of one class in the engine's order, then hands their counters on.
class CounterForwarder : public CounterSink {
 public:
  CounterForwarder(CounterEmit emit, void* context) : emit_(emit), context_(context) {}
  void visit(const Block& block) {
    block_ = block.type_name();
    instance_ = 0;
    for (uint32_t i = 0; i < seen_count_; ++i) instance_ += seen_[i] == block_ ? 1u : 0u;
    if (seen_count_ < kMaxBlocks) seen_[seen_count_++] = block_;
    block.report_counters(*this);
  }
  void counter(const char* name, uint64_t value) override { emit_(context_, block_, instance_, name, value); }

 private:
  // Blocks beyond this many are still reported; only their instance numbers stop growing.
  static constexpr uint32_t kMaxBlocks = 256;
  CounterEmit emit_;
  void* context_;
  const char* block_ = "";
  uint32_t instance_ = 0;
  const char* seen_[kMaxBlocks] = {};
  uint32_t seen_count_ = 0;
};

}  // namespace

// Loop context (reports, the simulator's counter dump). Blocks are numbered per class in engine order
// (Channel 0, Channel 1, …), the way a user names them.
void report_block_counters(CounterEmit emit, void* context) {
  CounterForwarder forwarder(emit, context);
  engine().for_each_block([](Block* block, void* state) { static_cast<CounterForwarder*>(state)->visit(*block); },
                          &forwarder);
}

void report_warnings(WarningEmit emit, void* context) {
  WarningTally tally;
  for (uint32_t i = 0; warning_tally(i, tally); ++i)
    emit(context, tally.source, to_string(tally.reason), tally.detail, tally.count);
}

}  // namespace stepdance
