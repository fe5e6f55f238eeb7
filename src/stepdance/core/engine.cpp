// The frame engine: registries, stage order, timers and load accounting.
#include "stepdance/core/engine.hpp"

#include "stepdance/core/block_order.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/core/units.hpp"
#include "stepdance/hal/hal.hpp"

namespace stepdance {
namespace {

void frame_isr() { engine().run_frame(); }
void kilohertz_isr() { engine().run_kilohertz_tick(); }

// The stage names double as fault details, so they say which registry overflowed.
constexpr const char* kRegistryNames[kNumStages] = {
    "input-port stage registry", "pre-channel stage registry", "channel registry",
    "output-port registry",      "post-channel stage registry", "kilohertz registry",
    "loop registry",
};

}  // namespace

const char* to_string(Stage stage) {
  const uint8_t index = static_cast<uint8_t>(stage);
  return index < kNumStages ? kRegistryNames[index] : "unknown stage";
}

Engine& engine() {
  static Engine instance;
  return instance;
}

size_t Engine::capacity(Stage stage) {
  switch (stage) {
    case Stage::kInputPorts: return EngineCapacity::kInputPorts;
    case Stage::kPreChannel: return EngineCapacity::kPreChannel;
    case Stage::kChannels: return EngineCapacity::kChannels;
    case Stage::kOutputPorts: return EngineCapacity::kOutputPorts;
    case Stage::kPostChannel: return EngineCapacity::kPostChannel;
    case Stage::kKilohertz: return EngineCapacity::kKilohertz;
    case Stage::kLoop: return EngineCapacity::kLoop;
  }
  return 0;
}

Status Engine::add(Stage stage, Block* block) {
  if (block == nullptr) return Status::kBadArgument;
  Registry& blocks = registry(stage);
  if (blocks.contains(block)) return Status::kOk;
  if (blocks.size() >= capacity(stage)) {
    fault(FaultReason::kRegistryFull, to_string(stage));
    return Status::kFull;
  }
  // The frame ISR may be iterating this list: publish the entry and the new size atomically.
  hal::CriticalSection guard;
  return blocks.push_back(block);
}

void Engine::remove(Block* block) {
  hal::CriticalSection guard;
  for (Registry& blocks : registries_) blocks.remove(block);
}

size_t Engine::count(Stage stage) const { return registry(stage).size(); }

Status Engine::add_frame_function(FrameFunction function) {
  if (function == nullptr) return Status::kBadArgument;
  auto& functions = running_ ? late_functions_ : early_functions_;
  hal::CriticalSection guard;
  if (functions.push_back(function) != Status::kOk) {
    fault(FaultReason::kRegistryFull, "frame function table");
    return Status::kFull;
  }
  return Status::kOk;
}

Status Engine::start() {
  if (fault_reason() != FaultReason::kNone) return Status::kBadArgument;
  if (running_) return Status::kOk;
  if (!blocks_accept_frame_period()) return Status::kBadArgument;
  order_stages();
  running_ = true;
  frame_budget_cycles_ = hal::cycles_per_second() / frame_rate_hz();
  const Status frame = hal::frame_timer_start(frame_period_us(), &frame_isr);
  if (frame != Status::kOk) {
    running_ = false;
    return frame;
  }
  const Status tick = hal::khz_timer_start(kKilohertzPeriodUs, &kilohertz_isr);
  if (tick != Status::kOk) stop();
  return tick;
}

bool Engine::blocks_accept_frame_period() {
  bool accepted = true;
  for_each_block(
      [](Block* block, void* all) {
        if (!block->accept_frame_period(frame_period_us())) *static_cast<bool*>(all) = false;
      },
      &accepted);
  return accepted;
}

void Engine::order_stages() {
  for (uint8_t stage = 0; stage < kNumStages; ++stage) {
    Registry& blocks = registries_[stage];
    char* names = cycle_names_[stage];
    if (order_by_graph(blocks.begin(), blocks.size(), names, sizeof(cycle_names_[stage]))) continue;
    report_fault(FaultLevel::kWarning, FaultReason::kBadConfiguration, to_string(static_cast<Stage>(stage)), names);
  }
}

void Engine::stop() {
  hal::timers_stop();
  running_ = false;
}

void Engine::run_stage(Registry& blocks) {
  uint32_t ran = 0;  // counted locally: a member would be reloaded around every virtual call
  for (Block* block : blocks) {
    if (!block->is_enabled()) continue;
    block->run();
    ++ran;
  }
  blocks_run_ += ran;
}

void Engine::run_frame() {
  blocks_run_ = 0;
  const uint32_t started = hal::cycles_now();
  for (FrameFunction function : early_functions_) function();
  for (uint8_t stage = 0; stage < kNumFrameStages; ++stage) run_stage(registries_[stage]);
  for (FrameFunction function : late_functions_) function();
  frame_count_ = frame_count_ + 1;
  load_.record(hal::cycles_now() - started, frame_budget_cycles_);
}

void Engine::run_kilohertz_tick() {
  for (Block* block : registry(Stage::kKilohertz)) {
    if (block->is_enabled()) block->run_kilohertz();
  }
}

void Engine::run_loop() {
  ++loop_passes_;
  for (Block* block : registry(Stage::kLoop)) {
    if (block->is_enabled()) block->loop();
  }
  deliver_fault_reports();  // subscribers run here, in the loop, never in the frame
}

void Engine::for_each_block(void (*visit)(Block* block, void* context), void* context) {
  for (uint8_t stage = 0; stage < kNumStages; ++stage) {
    for (Block* block : registries_[stage]) {
      bool seen = false;
      for (uint8_t earlier = 0; earlier < stage && !seen; ++earlier) seen = registries_[earlier].contains(block);
      if (!seen) visit(block, context);
    }
  }
}

void Engine::clear() {
  stop();
  hal::CriticalSection guard;
  for (Registry& blocks : registries_) blocks.clear();
  early_functions_.clear();
  late_functions_.clear();
  load_.reset();
  frame_count_ = 0;
}

}  // namespace stepdance
