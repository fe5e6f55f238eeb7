// The frame engine: fixed registries per stage, the frame (25 kHz by default), the 1 kHz tick and the loop.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/fixed_list.hpp"
#include "stepdance/core/load_metrics.hpp"
#include "stepdance/core/stage.hpp"
#include "stepdance/core/status.hpp"

namespace stepdance {

/// Capacity of each stage's registry. A registration beyond it faults (never silently ignored).
struct EngineCapacity {
  static constexpr size_t kInputPorts = 8;
  static constexpr size_t kPreChannel = 48;
  static constexpr size_t kChannels = 24;
  static constexpr size_t kOutputPorts = 4;
  static constexpr size_t kPostChannel = 16;
  static constexpr size_t kKilohertz = 32;
  static constexpr size_t kLoop = 32;
  static constexpr size_t kFrameFunctions = 8;
};

/// Runs registered blocks: one frame every frame_period_us() (40 µs unless the sketch chose
/// another with set_frame_period_us()) in stage order, kilohertz blocks every 1 ms,
/// loop blocks on every dance_loop(). One instance per board (see engine()).
class Engine {
 public:
  /// A raw function called every frame (the original's add_function_to_frame).
  using FrameFunction = void (*)();

  /// Adds a block to a stage's registry, in order. kFull → fault(kRegistryFull). Context: loop.
  Status add(Stage stage, Block* block);
  /// Removes a block from every registry. Context: loop.
  void remove(Block* block);
  /// Number of blocks registered in a stage. Context: any.
  size_t count(Stage stage) const;
  /// Capacity of a stage's registry. Context: any.
  static size_t capacity(Stage stage);

  /// Adds a raw frame function: before start() it runs ahead of the input-port stage, after
  /// start() it runs after the post-channel stage. kFull → fault. Context: loop.
  Status add_frame_function(FrameFunction function);

  /// Asks every block to accept the chosen frame period (a refusal → kBadArgument), orders every
  /// stage from the BlockPort graph (producers before consumers; a cycle is
  /// reported once as a warning naming the blocks and that stage keeps begin() order), then
  /// starts the frame and kilohertz timers through the HAL. Refuses (kBadArgument) while a fault
  /// is recorded. Context: loop.
  Status start();
  /// Stops both timers. Context: any.
  void stop();
  /// True between start() and stop(). Context: any.
  bool running() const { return running_; }

  /// One frame: frame functions, the five stages, then load accounting. Context: frame ISR.
  void run_frame();
  /// One kilohertz tick: run_kilohertz() of each kilohertz block. Context: kilohertz ISR.
  void run_kilohertz_tick();
  /// One pass of the loop stage. Context: loop.
  void run_loop();

  /// Loop passes run so far (wraps; compare for equality): lets loop blocks share a per-pass
  /// budget, e.g. one I2C transfer per pass. Context: loop.
  uint32_t loop_passes() const { return loop_passes_; }
  /// Frames run since start (wraps after ~2 days at 25 kHz, ~12 hours at 100 kHz; use differences). Context: any.
  uint32_t frame_count() const { return frame_count_; }
  /// Frame-ISR load statistics. Context: any (reads are not atomic across fields).
  const LoadMetrics& load() const { return load_; }
  /// Blocks run so far in the current (or last) frame: the simulator's CPU-cost model counts
  /// them. Context: any.
  uint32_t blocks_run_in_frame() const { return blocks_run_; }
  /// Clears the load statistics. Context: loop.
  void reset_load() { load_.reset(); }

  /// Calls visit(block, context) once for every registered block (a block registered in several
  /// stages is visited once), in stage order then registration order. Context: loop.
  void for_each_block(void (*visit)(Block* block, void* context), void* context);

  /// Unregisters everything and stops (tests and simulator resets). Context: loop.
  void clear();

 private:
  using Registry = FixedList<Block*, EngineCapacity::kPreChannel>;
  Registry& registry(Stage stage) { return registries_[static_cast<uint8_t>(stage)]; }
  const Registry& registry(Stage stage) const { return registries_[static_cast<uint8_t>(stage)]; }
  void run_stage(Registry& blocks);
  void order_stages();
  // Asks every block whether it can run at the chosen period (each refusal is on the fault path).
  bool blocks_accept_frame_period();
  // Asks every block whether it can work with the ports its sketch mapped (check_wiring()).
  bool blocks_accept_wiring();

  Registry registries_[kNumStages];
  FixedList<FrameFunction, EngineCapacity::kFrameFunctions> early_functions_;
  FixedList<FrameFunction, EngineCapacity::kFrameFunctions> late_functions_;
  // Names of the blocks of a cycle, per stage: the warning keeps a pointer to its text.
  char cycle_names_[kNumStages][96] = {};
  LoadMetrics load_;
  uint32_t frame_budget_cycles_ = 24000;  // CPU cycles per frame, set from the HAL at start()
  volatile uint32_t frame_count_ = 0;
  uint32_t blocks_run_ = 0;
  uint32_t loop_passes_ = 0;
  volatile bool running_ = false;
};

/// The board's engine. Context: any.
Engine& engine();

}  // namespace stepdance
