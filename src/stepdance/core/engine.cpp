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
    "input-port stage registry",   "pre-channel stage registry", "channel registry", "output-port registry",
    "post-channel stage registry", "kilohertz registry",         "loop registry",
};

}  // namespace

const char* to_string(Stage stage) {
  const uint8_t index = static_cast<uint8_t>(stage);
  return index < kNumStages ? kRegistryNames[index] : "unknown stage";
}

// A function-local static, made on first use: blocks are often globals, constructed in an order
// that is unspecified across files, so the engine must exist whenever the first of them asks.
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

// Registering twice is harmless (a begin() called again, several devices on one QwiicBus).
// A full registry is fatal, not a warning: a block that silently never runs would be a machine that
// ignores part of its sketch.
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

// Called from Block's destructor; under a critical section so a frame never runs a destroyed block.
void Engine::remove(Block* block) {
  hal::CriticalSection guard;
  for (Registry& blocks : registries_) blocks.remove(block);
}

size_t Engine::count(Stage stage) const { return registry(stage).size(); }

// The original's add_function_to_frame() (original-library.md §1.3): functions added before
// dance_start() run before the input-port stage, those added while running after the post-channel
// stage. Unlike the original, a full table is reported, not silently ignored.
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

// Every block checks the frame period first, then its wiring (a refusal leaves nothing running),
// then the stages are ordered once, here, not per frame. A fatal fault in force refuses the start until clear_fault().
// The frame budget is the CPU cycles in one frame period, the denominator of the load figures.
Status Engine::start() {
  if (fault_reason() != FaultReason::kNone) return Status::kBadArgument;
  if (running_) return Status::kOk;
  if (!blocks_accept_frame_period()) return Status::kBadArgument;
  if (!blocks_accept_wiring()) return Status::kBadArgument;
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

bool Engine::blocks_accept_wiring() {
  bool accepted = true;
  for_each_block(
      [](Block* block, void* all) {
        if (!block->check_wiring()) *static_cast<bool*>(all) = false;
      },
      &accepted);
  return accepted;
}

// Within a stage, a block must run after the blocks that feed it through BlockPorts, or its input
// would be one frame late (the original ran registration order: original-library.md §1.3). A
// cycle cannot be ordered: begin() order is kept and a warning names the blocks, since the sketch
// still runs (with one frame of delay in the loop).
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

// Frame context: a disabled block is skipped, not removed, so enable() resumes it in place.
void Engine::run_stage(Registry& blocks) {
  uint32_t ran = 0;  // counted locally: a member would be reloaded around every virtual call
  for (Block* block : blocks) {
    if (!block->is_enabled()) continue;
    block->run();
    ++ran;
  }
  blocks_run_ += ran;
}

// Frame-ISR context, once per frame period (40 µs by default; spec "Frames"). Stage order: input
// ports, pre-channel, channels, output ports, post-channel (the original's, original-library.md §1.3),
// so a pulse received or generated in a frame leaves on the output ports in that same frame. The
// cycle count covers the whole frame, for stepdance_get_cpu_usage() and the overrun count.
void Engine::run_frame() {
  blocks_run_ = 0;
  const uint32_t started = hal::cycles_now();
  for (FrameFunction function : early_functions_) function();
  for (uint8_t stage = 0; stage < kNumFrameStages; ++stage) run_stage(registries_[stage]);
  for (FrameFunction function : late_functions_) function();
  frame_count_ = frame_count_ + 1;
  load_.record(hal::cycles_now() - started, frame_budget_cycles_);
}

// Kilohertz-ISR context (1 ms): slow inputs (buttons, analog maps) that need not run every frame.
void Engine::run_kilohertz_tick() {
  for (Block* block : registry(Stage::kKilohertz)) {
    if (block->is_enabled()) block->run_kilohertz();
  }
}

// Loop context (dance_loop). Fault subscribers are called here so a report made in an ISR is handled
// where it may print or send a reply.
void Engine::run_loop() {
  ++loop_passes_;
  for (Block* block : registry(Stage::kLoop)) {
    if (block->is_enabled()) block->loop();
  }
  deliver_fault_reports();  // subscribers run here, in the loop, never in the frame
}

// A block registered in several stages is visited once, at its first stage.
void Engine::for_each_block(void (*visit)(Block* block, void* context), void* context) {
  for (uint8_t stage = 0; stage < kNumStages; ++stage) {
    for (Block* block : registries_[stage]) {
      bool seen = false;
      for (uint8_t earlier = 0; earlier < stage && !seen; ++earlier) seen = registries_[earlier].contains(block);
      if (!seen) visit(block, context);
    }
  }
}

// For tests and fuzzers: everything back to an empty, stopped engine.
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
