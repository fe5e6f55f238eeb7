// Engine: stage order, registries, overflow faults, kHz and loop contexts, load, LoopDelay.
#include <stdint.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "stepdance/core/block.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/stage.hpp"
#include "support/engine_fixture.hpp"

namespace stepdance {
namespace {

using Log = std::vector<std::string>;

// A block that writes its name into a log whenever the engine runs it.
class Recorder : public Block {
 public:
  Recorder(Log& log, std::string name) : log_(log), name_(std::move(name)) {}
  Status begin(Stage stage) { return register_in(stage); }
  void run() override { log_.push_back(name_); }
  void loop() override { log_.push_back(name_ + ".loop"); }

 private:
  Log& log_;
  std::string name_;
};

// Frame functions are plain function pointers, so they log through a global.
Log* g_function_log = nullptr;
void early_function() { g_function_log->push_back("early"); }
void late_function() { g_function_log->push_back("late"); }
int g_calls = 0;
void count_call() { ++g_calls; }

class EngineTest : public test_support::EngineFixture {
 protected:
  void SetUp() override {
    EngineFixture::SetUp();
    g_function_log = &log;
    g_calls = 0;
  }
  void TearDown() override {
    g_function_log = nullptr;
    EngineFixture::TearDown();
  }
  // Runs n frames with a fresh log and returns what ran.
  Log frames(uint32_t n) {
    log.clear();
    hal_manual::run_frames(n);
    return log;
  }
  size_t occurrences(const std::string& name) const {
    size_t n = 0;
    for (const std::string& entry : log) n += entry == name ? 1 : 0;
    return n;
  }
  Log log;
};

// ---- Stage order and registration ----------------------------------------------------------

TEST_F(EngineTest, StagesRunInFixedOrderWhateverTheRegistrationOrder) {
  Recorder post(log, "post"), output(log, "output"), channel(log, "channel"), pre(log, "pre"), input(log, "input");
  ASSERT_EQ(post.begin(Stage::kPostChannel), Status::kOk);
  ASSERT_EQ(output.begin(Stage::kOutputPorts), Status::kOk);
  ASSERT_EQ(channel.begin(Stage::kChannels), Status::kOk);
  ASSERT_EQ(pre.begin(Stage::kPreChannel), Status::kOk);
  ASSERT_EQ(input.begin(Stage::kInputPorts), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  EXPECT_EQ(frames(1), (Log{"input", "pre", "channel", "output", "post"}));
  EXPECT_EQ(frames(2), (Log{"input", "pre", "channel", "output", "post",  //
                            "input", "pre", "channel", "output", "post"}));
}

TEST_F(EngineTest, RegistrationOrderWithinAStage) {
  Recorder a(log, "a"), c1(log, "c1"), b(log, "b"), c2(log, "c2"), c(log, "c"), in(log, "in");
  a.begin(Stage::kPreChannel);
  c1.begin(Stage::kChannels);
  b.begin(Stage::kPreChannel);
  c2.begin(Stage::kChannels);
  c.begin(Stage::kPreChannel);
  in.begin(Stage::kInputPorts);
  ASSERT_EQ(dance_start(), Status::kOk);
  EXPECT_EQ(frames(1), (Log{"in", "a", "b", "c", "c1", "c2"}));
  EXPECT_EQ(engine().count(Stage::kPreChannel), 3u);
  EXPECT_EQ(engine().count(Stage::kChannels), 2u);
}

TEST_F(EngineTest, BlockRegisteredAfterStartJoinsAtTheEndOfItsStage) {
  Recorder first(log, "first"), late(log, "late");
  first.begin(Stage::kPreChannel);
  ASSERT_EQ(dance_start(), Status::kOk);
  EXPECT_EQ(frames(1), Log{"first"});
  late.begin(Stage::kPreChannel);
  EXPECT_EQ(frames(1), (Log{"first", "late"}));
}

TEST_F(EngineTest, RegisteringTwiceInOneStageIsANoOp) {
  Recorder a(log, "a");
  EXPECT_EQ(a.begin(Stage::kPreChannel), Status::kOk);
  EXPECT_EQ(a.begin(Stage::kPreChannel), Status::kOk);
  EXPECT_EQ(engine().count(Stage::kPreChannel), 1u);
  ASSERT_EQ(dance_start(), Status::kOk);
  EXPECT_EQ(frames(1), Log{"a"});
}

TEST_F(EngineTest, NullBlockIsABadArgumentNotAFault) {
  EXPECT_EQ(engine().add(Stage::kPreChannel, nullptr), Status::kBadArgument);
  EXPECT_EQ(engine().count(Stage::kPreChannel), 0u);
  EXPECT_EQ(fault_reason(), FaultReason::kNone);
}

TEST_F(EngineTest, NothingRunsBeforeStartOrAfterStop) {
  Recorder a(log, "a");
  a.begin(Stage::kPreChannel);
  EXPECT_EQ(frames(10), Log{});
  EXPECT_FALSE(engine().running());
  EXPECT_EQ(engine().frame_count(), 0u);

  ASSERT_EQ(dance_start(), Status::kOk);
  EXPECT_TRUE(engine().running());
  EXPECT_TRUE(hal_manual::frame_timer_running());
  EXPECT_TRUE(hal_manual::khz_timer_running());
  EXPECT_EQ(frames(7).size(), 7u);
  EXPECT_EQ(engine().frame_count(), 7u);

  engine().stop();
  EXPECT_FALSE(engine().running());
  EXPECT_EQ(frames(3), Log{});
  EXPECT_EQ(engine().frame_count(), 7u);
}

TEST_F(EngineTest, StartTwiceIsHarmless) {
  Recorder a(log, "a");
  a.begin(Stage::kPreChannel);
  ASSERT_EQ(dance_start(), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  EXPECT_EQ(frames(2), (Log{"a", "a"}));
}

TEST_F(EngineTest, ClearUnregistersEverythingAndZeroesTheFrameCount) {
  Recorder a(log, "a");
  a.begin(Stage::kPreChannel);
  ASSERT_EQ(dance_start(), Status::kOk);
  hal_manual::run_frames(4);
  engine().clear();
  EXPECT_EQ(engine().frame_count(), 0u);
  EXPECT_EQ(engine().count(Stage::kPreChannel), 0u);
  EXPECT_FALSE(engine().running());
  ASSERT_EQ(dance_start(), Status::kOk);
  EXPECT_EQ(frames(3), Log{});
  EXPECT_EQ(engine().frame_count(), 3u);
}

// ---- Kilohertz and loop contexts -----------------------------------------------------------

TEST_F(EngineTest, KilohertzBlocksRunAfterEveryTwentyFifthFrame) {
  Recorder tick(log, "tick"), pre(log, "pre");
  tick.begin(Stage::kKilohertz);
  pre.begin(Stage::kPreChannel);
  ASSERT_EQ(dance_start(), Status::kOk);
  frames(24);
  EXPECT_EQ(occurrences("tick"), 0u);
  EXPECT_EQ(occurrences("pre"), 24u);
  EXPECT_EQ(frames(1), (Log{"pre", "tick"}));  // frame 25: the frame first, then the tick
  frames(100);
  EXPECT_EQ(occurrences("tick"), 4u);
  EXPECT_EQ(occurrences("pre"), 100u);
}

// A block with work at both rates: run() in its frame stage, run_kilohertz() at the tick.
class TwoRateRecorder : public Recorder {
 public:
  using Recorder::Recorder;
  void run_kilohertz() override { log_kilohertz_ += 1; }
  int kilohertz_calls() const { return log_kilohertz_; }

 private:
  int log_kilohertz_ = 0;
};

TEST_F(EngineTest, KilohertzStageCallsRunKilohertzNotTheFrameEntry) {
  TwoRateRecorder both(log, "both");
  both.begin(Stage::kPreChannel);
  both.begin(Stage::kKilohertz);
  ASSERT_EQ(dance_start(), Status::kOk);
  frames(50);
  EXPECT_EQ(occurrences("both"), 50u);   // the frame entry once per frame, never at the tick
  EXPECT_EQ(both.kilohertz_calls(), 2);  // 50 frames of 40 µs = 2 ms
}

TEST_F(EngineTest, KilohertzBlocksWaitForStart) {
  Recorder tick(log, "tick");
  tick.begin(Stage::kKilohertz);
  EXPECT_EQ(frames(50), Log{});
}

TEST_F(EngineTest, LoopBlocksRunOnlyFromDanceLoop) {
  Recorder looper(log, "looper"), pre(log, "pre");
  looper.begin(Stage::kLoop);
  pre.begin(Stage::kPreChannel);
  ASSERT_EQ(dance_start(), Status::kOk);
  frames(100);
  EXPECT_EQ(occurrences("looper"), 0u);
  EXPECT_EQ(occurrences("looper.loop"), 0u);
  log.clear();
  dance_loop();
  dance_loop();
  EXPECT_EQ(log, (Log{"looper.loop", "looper.loop"}));  // loop(), not run(); pre not looped
}

TEST_F(EngineTest, DanceLoopWorksBeforeStart) {
  Recorder looper(log, "looper");
  looper.begin(Stage::kLoop);
  dance_loop();
  EXPECT_EQ(log, Log{"looper.loop"});
}

TEST_F(EngineTest, DisabledBlocksAreSkippedInEveryContext) {
  Recorder a(log, "a"), b(log, "b"), c(log, "c"), tick(log, "tick"), looper(log, "looper");
  a.begin(Stage::kPreChannel);
  b.begin(Stage::kPreChannel);
  c.begin(Stage::kChannels);
  tick.begin(Stage::kKilohertz);
  looper.begin(Stage::kLoop);
  ASSERT_EQ(dance_start(), Status::kOk);
  b.disable();
  tick.disable();
  looper.disable();
  EXPECT_FALSE(b.is_enabled());
  frames(25);
  dance_loop();
  EXPECT_EQ(occurrences("a"), 25u);
  EXPECT_EQ(occurrences("b"), 0u);
  EXPECT_EQ(occurrences("tick"), 0u);
  EXPECT_EQ(occurrences("looper.loop"), 0u);
  b.enable();
  EXPECT_EQ(frames(1), (Log{"a", "b", "c"}));
  EXPECT_EQ(engine().count(Stage::kPreChannel), 2u);  // disabling never unregisters
}

TEST_F(EngineTest, DestroyingABlockUnregistersItFromEveryStage) {
  Recorder keeper(log, "keeper");
  keeper.begin(Stage::kPreChannel);
  {
    Recorder temporary(log, "temporary");
    temporary.begin(Stage::kPreChannel);
    temporary.begin(Stage::kKilohertz);
    temporary.begin(Stage::kLoop);
    EXPECT_EQ(engine().count(Stage::kPreChannel), 2u);
    EXPECT_EQ(engine().count(Stage::kKilohertz), 1u);
    EXPECT_EQ(engine().count(Stage::kLoop), 1u);
  }
  EXPECT_EQ(engine().count(Stage::kPreChannel), 1u);
  EXPECT_EQ(engine().count(Stage::kKilohertz), 0u);
  EXPECT_EQ(engine().count(Stage::kLoop), 0u);
  ASSERT_EQ(dance_start(), Status::kOk);
  frames(25);
  dance_loop();
  EXPECT_EQ(occurrences("keeper"), 25u);
  EXPECT_EQ(log.size(), 25u);
}

// ---- Registry overflow and faults ----------------------------------------------------------

struct RegistryCase {
  Stage stage;
  size_t capacity;
  const char* name;
};

const RegistryCase kRegistries[] = {
    {Stage::kInputPorts, 8, "input-port stage registry"},
    {Stage::kPreChannel, 48, "pre-channel stage registry"},
    {Stage::kChannels, 24, "channel registry"},
    {Stage::kOutputPorts, 4, "output-port registry"},
    {Stage::kPostChannel, 16, "post-channel stage registry"},
    {Stage::kKilohertz, 32, "kilohertz registry"},
    {Stage::kLoop, 32, "loop registry"},
};

TEST_F(EngineTest, EveryRegistryFaultsOnOverflowAndNamesItself) {
  for (const RegistryCase& registry : kRegistries) {
    SCOPED_TRACE(registry.name);
    test_support::reset_global_state();
    EXPECT_EQ(Engine::capacity(registry.stage), registry.capacity);
    std::vector<std::unique_ptr<Recorder>> blocks;
    for (size_t i = 0; i <= registry.capacity; ++i) {
      blocks.push_back(std::make_unique<Recorder>(log, "b"));
    }
    for (size_t i = 0; i < registry.capacity; ++i) {
      ASSERT_EQ(blocks[i]->begin(registry.stage), Status::kOk) << i;
    }
    EXPECT_EQ(fault_reason(), FaultReason::kNone);
    EXPECT_FALSE(hal_manual::in_safe_state());

    EXPECT_EQ(blocks.back()->begin(registry.stage), Status::kFull);
    EXPECT_EQ(engine().count(registry.stage), registry.capacity);
    EXPECT_EQ(fault_reason(), FaultReason::kRegistryFull);
    EXPECT_STREQ(fault_detail(), registry.name);
    EXPECT_EQ(fault_count(), 1u);
    EXPECT_EQ(hal_manual::last_fault_log(), std::string("registry full: ") + registry.name);
    EXPECT_TRUE(hal_manual::in_safe_state());
  }
}

TEST_F(EngineTest, OverflowWhileRunningStopsTheFrames) {
  std::vector<std::unique_ptr<Recorder>> blocks;
  for (int i = 0; i < 9; ++i) blocks.push_back(std::make_unique<Recorder>(log, "b"));
  for (int i = 0; i < 8; ++i) blocks[i]->begin(Stage::kInputPorts);
  ASSERT_EQ(dance_start(), Status::kOk);
  hal_manual::run_frames(5);
  EXPECT_EQ(blocks[8]->begin(Stage::kInputPorts), Status::kFull);
  EXPECT_FALSE(hal_manual::frame_timer_running());
  EXPECT_FALSE(hal_manual::khz_timer_running());
  EXPECT_FALSE(engine().running());
  hal_manual::run_frames(5);
  EXPECT_EQ(engine().frame_count(), 5u);
}

TEST_F(EngineTest, DanceStartRefusesWhileFaulted) {
  fault(FaultReason::kInvariant, "test invariant");
  EXPECT_EQ(hal_manual::last_fault_log(), "invariant broken: test invariant");
  EXPECT_EQ(dance_start(), Status::kBadArgument);
  EXPECT_FALSE(engine().running());
  EXPECT_FALSE(hal_manual::frame_timer_running());
  hal_manual::run_frames(3);
  EXPECT_EQ(engine().frame_count(), 0u);

  clear_fault();
  EXPECT_EQ(dance_start(), Status::kOk);
  hal_manual::run_frames(3);
  EXPECT_EQ(engine().frame_count(), 3u);
}

TEST_F(EngineTest, RestartAfterAFaultWhileRunning) {
  ASSERT_EQ(dance_start(), Status::kOk);
  hal_manual::run_frames(2);
  fault(FaultReason::kHardware, "test hardware");
  EXPECT_FALSE(engine().running());
  hal_manual::run_frames(2);
  EXPECT_EQ(engine().frame_count(), 2u);
  EXPECT_EQ(dance_start(), Status::kBadArgument);

  clear_fault();  // the user acknowledges the fault and starts again
  EXPECT_EQ(dance_start(), Status::kOk);
  EXPECT_TRUE(hal_manual::frame_timer_running());
  hal_manual::run_frames(3);
  EXPECT_EQ(engine().frame_count(), 5u);
}

TEST_F(EngineTest, OnlyTheFirstFaultIsRecorded) {
  fault(FaultReason::kQueueFull, "first");
  fault(FaultReason::kInvariant, "second");
  EXPECT_EQ(fault_reason(), FaultReason::kQueueFull);
  EXPECT_STREQ(fault_detail(), "first");
  EXPECT_EQ(fault_count(), 2u);
  EXPECT_EQ(hal_manual::last_fault_log(), "queue full: first");
}

// ---- Frame functions -----------------------------------------------------------------------

TEST_F(EngineTest, FrameFunctionsBeforeStartRunFirstAfterStartRunLast) {
  Recorder input(log, "input"), post(log, "post");
  post.begin(Stage::kPostChannel);
  input.begin(Stage::kInputPorts);
  ASSERT_EQ(add_function_to_frame(&early_function), Status::kOk);
  ASSERT_EQ(dance_start(), Status::kOk);
  ASSERT_EQ(add_function_to_frame(&late_function), Status::kOk);
  EXPECT_EQ(frames(1), (Log{"early", "input", "post", "late"}));
}

TEST_F(EngineTest, NullFrameFunctionIsRefused) {
  EXPECT_EQ(add_function_to_frame(nullptr), Status::kBadArgument);
  EXPECT_EQ(fault_reason(), FaultReason::kNone);
}

TEST_F(EngineTest, FrameFunctionTablesHoldEightEach) {
  for (int i = 0; i < 8; ++i) ASSERT_EQ(add_function_to_frame(&count_call), Status::kOk) << i;
  ASSERT_EQ(dance_start(), Status::kOk);
  for (int i = 0; i < 8; ++i) ASSERT_EQ(add_function_to_frame(&count_call), Status::kOk) << i;
  hal_manual::run_frames(1);
  EXPECT_EQ(g_calls, 16);
  EXPECT_EQ(fault_reason(), FaultReason::kNone);

  EXPECT_EQ(add_function_to_frame(&count_call), Status::kFull);
  EXPECT_EQ(fault_reason(), FaultReason::kRegistryFull);
  EXPECT_STREQ(fault_detail(), "frame function table");
  EXPECT_TRUE(hal_manual::in_safe_state());
}

// ---- Load metrics (budget: 600 MHz / 25 kHz = 24 000 cycles per frame) ---------------------

// Starts the engine and runs n frames that each cost `cycles`.
void run_costed_frames(uint32_t cycles, uint32_t n) {
  hal_manual::set_cycles_per_read(cycles);
  if (!engine().running()) {
    ASSERT_EQ(dance_start(), Status::kOk);
  }
  hal_manual::run_frames(n);
}

TEST_F(EngineTest, LoadMetricsStartAtZero) {
  EXPECT_EQ(engine().load().frames(), 0u);
  EXPECT_EQ(engine().load().peak_fraction(), 0.0);
  EXPECT_EQ(engine().load().average_fraction(), 0.0);
  EXPECT_EQ(stepdance_get_cpu_usage(), 0.0f);
  EXPECT_EQ(stepdance_get_average_cpu_usage(), 0.0f);
  EXPECT_EQ(stepdance_get_frame_overruns(), 0u);
}

TEST_F(EngineTest, PeakAndAverageAreExactFractionsOfTheBudget) {
  run_costed_frames(10000, 3);  // the original overflowed above 4294 cycles
  const LoadMetrics& load = engine().load();
  EXPECT_EQ(load.last_cycles(), 10000u);
  EXPECT_EQ(load.peak_cycles(), 10000u);
  EXPECT_EQ(load.total_cycles(), 30000u);
  EXPECT_EQ(load.frames(), 3u);
  EXPECT_EQ(load.overruns(), 0u);
  EXPECT_DOUBLE_EQ(load.peak_fraction(), 10000.0 / 24000.0);
  EXPECT_DOUBLE_EQ(load.average_fraction(), 10000.0 / 24000.0);
  EXPECT_FLOAT_EQ(stepdance_get_cpu_usage(), 10000.0f / 24000.0f);

  run_costed_frames(30000, 1);  // one overrun: peak 1.25, average (3·10000 + 30000)/4 = 15000
  EXPECT_EQ(load.last_cycles(), 30000u);
  EXPECT_EQ(load.peak_fraction(), 1.25);
  EXPECT_EQ(load.average_fraction(), 0.625);
  EXPECT_EQ(load.overruns(), 1u);
  EXPECT_EQ(stepdance_get_cpu_usage(), 1.25f);
  EXPECT_EQ(stepdance_get_average_cpu_usage(), 0.625f);
  EXPECT_EQ(stepdance_get_frame_overruns(), 1u);

  run_costed_frames(1200, 1);  // the peak holds
  EXPECT_EQ(load.last_cycles(), 1200u);
  EXPECT_EQ(load.peak_fraction(), 1.25);
}

TEST_F(EngineTest, AroundTheOriginalOverflowThreshold) {
  run_costed_frames(4294, 1);
  EXPECT_DOUBLE_EQ(engine().load().peak_fraction(), 4294.0 / 24000.0);
  run_costed_frames(4295, 1);
  EXPECT_DOUBLE_EQ(engine().load().peak_fraction(), 4295.0 / 24000.0);
  EXPECT_DOUBLE_EQ(engine().load().average_fraction(), 4294.5 / 24000.0);
}

TEST_F(EngineTest, OverrunMeansStrictlyOverBudget) {
  run_costed_frames(24000, 2);
  EXPECT_EQ(engine().load().overruns(), 0u);
  EXPECT_EQ(engine().load().peak_fraction(), 1.0);
  run_costed_frames(24001, 3);
  EXPECT_EQ(engine().load().overruns(), 3u);
}

TEST_F(EngineTest, HugeFrameCostsDoNotOverflow) {
  run_costed_frames(4000000000u, 5);  // 4·10^9 cycles per frame: totals pass 2^32
  const LoadMetrics& load = engine().load();
  EXPECT_EQ(load.peak_cycles(), 4000000000u);
  EXPECT_EQ(load.total_cycles(), 20000000000ull);
  EXPECT_EQ(load.overruns(), 5u);
  EXPECT_DOUBLE_EQ(load.peak_fraction(), 4000000000.0 / 24000.0);
  EXPECT_DOUBLE_EQ(load.average_fraction(), 4000000000.0 / 24000.0);
}

TEST_F(EngineTest, ManyFramesDoNotOverflowTheTotal) {
  run_costed_frames(50000, 100000);  // 5·10^9 cycles in total
  const LoadMetrics& load = engine().load();
  EXPECT_EQ(load.frames(), 100000u);
  EXPECT_EQ(load.total_cycles(), 5000000000ull);
  EXPECT_EQ(load.overruns(), 100000u);
  EXPECT_DOUBLE_EQ(load.average_fraction(), 50000.0 / 24000.0);
  EXPECT_EQ(engine().frame_count(), 100000u);
}

TEST_F(EngineTest, MetricsResetClearsEverything) {
  run_costed_frames(30000, 2);
  stepdance_metrics_reset();
  const LoadMetrics& load = engine().load();
  EXPECT_EQ(load.frames(), 0u);
  EXPECT_EQ(load.peak_cycles(), 0u);
  EXPECT_EQ(load.total_cycles(), 0u);
  EXPECT_EQ(stepdance_get_cpu_usage(), 0.0f);
  EXPECT_EQ(stepdance_get_frame_overruns(), 0u);
  run_costed_frames(1200, 1);  // a smaller peak shows after the reset
  EXPECT_DOUBLE_EQ(load.peak_fraction(), 1200.0 / 24000.0);
  EXPECT_EQ(load.frames(), 1u);
}

// ---- LoopDelay ----------------------------------------------------------------------------

class LoopDelayTest : public EngineTest {
 protected:
  void SetUp() override {
    EngineTest::SetUp();
    test_support::reset_global_state(0xFFFFFFFFu - 5000);  // the µs clock wraps 5001 µs in
  }
  // Advances time by us, then calls periodic_call once.
  void call_after(uint32_t us) {
    hal_manual::advance_us(us);
    delay.periodic_call(&count_call, 10);
  }
  LoopDelay delay;
};

TEST_F(LoopDelayTest, CallsOncePerIntervalAcrossTheMicrosecondWrap) {
  call_after(0);  // the first call only arms the timer
  EXPECT_EQ(g_calls, 0);
  call_after(9999);
  EXPECT_EQ(g_calls, 0);
  call_after(1);  // 10 ms after arming, on the far side of the wrap
  EXPECT_EQ(g_calls, 1);
  call_after(0);
  EXPECT_EQ(g_calls, 1);
  call_after(10000);
  EXPECT_EQ(g_calls, 2);
}

TEST_F(LoopDelayTest, PeriodsDoNotDrift) {
  // Polled every 3 ms for 300 ms: deadlines stay on the 10 ms grid, so exactly 30 calls
  // (a delay that restarted from each late call would manage only 25).
  call_after(0);
  for (int i = 0; i < 100; ++i) call_after(3000);
  EXPECT_EQ(g_calls, 30);
}

TEST_F(LoopDelayTest, FallingFarBehindCallsOnceAndResynchronises) {
  call_after(0);
  call_after(35000);  // three periods late: one call, not three
  EXPECT_EQ(g_calls, 1);
  call_after(0);
  EXPECT_EQ(g_calls, 1);
  call_after(9999);
  EXPECT_EQ(g_calls, 1);
  call_after(1);  // the next deadline counts from the late call
  EXPECT_EQ(g_calls, 2);
}

TEST_F(LoopDelayTest, FrameTimeAlsoCounts) {
  call_after(0);
  hal_manual::run_frames(249);  // 9960 µs
  delay.periodic_call(&count_call, 10);
  EXPECT_EQ(g_calls, 0);
  hal_manual::run_frames(1);  // 10 000 µs
  delay.periodic_call(&count_call, 10);
  EXPECT_EQ(g_calls, 1);
}

}  // namespace
}  // namespace stepdance
