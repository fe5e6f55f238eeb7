// The HAL conformance suite: the facade's contract (src/stepdance/hal/*.hpp), written once as
// typed GoogleTest cases and run against every backend through a small adapter per backend.
//
// Every expected value comes from the facade's comments (units, ranges, ordering, return codes)
// or from the Teensy 4.1 pin facts those comments cite, never from a backend's own constants.
// A test's name says the clause it checks. A clause a backend cannot support is named in that
// backend's skip list (Adapter::skip_reason), so the run reports it as skipped, with the reason.
//
// An adapter is a struct of static functions (the backends are global, as on a board):
//   static const char* skip_reason(Clause)  why a clause cannot run here, or nullptr
//   static void reset()                     power-on state of the backend and its harness
//   static void settle()                    runs the interrupts a HAL call left pending
//   static void advance_us(uint32_t us)     time passes; no timer fires
//   static void tick()                      one 40 µs frame tick of the board's frame clock
//   static protocol::FrameWords launched(uint8_t port)  what the port began shifting out at
//                                           the latest tick (all zero: nothing)
//   static void inject_pulse(uint8_t port, const protocol::CapturedPulse&)  a pulse arrives
//   static void set_quadrature(uint8_t index, int32_t count)  the decoder counted edges
//   static void set_adc_fraction(uint8_t pin, double fraction)  the pin's voltage, 0..1 of
//                                           full scale, is converted once
//   static void drive_pin(uint8_t pin, bool high)  something outside drives an input pin
//   static void feed_console(const std::string&)   bytes arrive from the host
//   static std::string take_console_output()       bytes the board sent to the host
//   static bool drivers_disabled()           the backend's outputs are in their safe state
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "stepdance/hal/console.hpp"
#include "stepdance/hal/hal.hpp"
#include "stepdance/hal/nonvolatile.hpp"
#include "stepdance/hal/storage.hpp"

namespace hal_conformance {

/// The clauses of the contract the suite checks, one per test.
enum class Clause {
  kMicrosUnits,
  kCyclesRate,
  kFrameTimerTicks,
  kFramePeriod,
  kKhzTimer,
  kTimersStop,
  kPortOutClaims,
  kPortOutWaveform,
  kCaptureDelivery,
  kCaptureClock,
  kQuadrature,
  kAdcRange,
  kAdcPins,
  kGpioOutput,
  kGpioInput,
  kGpioPins,
  kConsoleBytes,
  kStorageRoundTrip,
  kNonvolatileRoundTrip,
  kCriticalNesting,
  kFaultSafeState,
};

using ::stepdance::Status;
using stepdance::protocol::FrameWords;

// ---- Facts of the contract and of the board (not of any backend) ---------------------------
constexpr uint32_t kFramePeriodUs = 40;            // the frame period every board runs by default
constexpr uint32_t kKhzPeriodUs = 1000;            // the kilohertz timer's period
constexpr uint32_t kCoreHz = 600000000u;           // hal.hpp: cycles_per_second() on a Teensy 4.x
constexpr uint32_t kBusTicksPerUs = 150;           // Teensy 4.x bus clock: 150 MHz
constexpr uint32_t kCaptureCounterMask = 0xFFFFu;  // 16-bit capture counters
constexpr uint16_t kAdcFullScale = 1023;           // hal.hpp: 10-bit conversions, 0..1023
constexpr uint8_t kAdcPin = 14;                    // Teensy 4.x: pin 14 = A0
constexpr uint8_t kPinWithoutAdc = 13;             // Teensy 4.x: pin 13 (the LED) has no ADC input
constexpr uint8_t kGpioPin = 13;
constexpr uint8_t kInputPin = 2;
constexpr uint8_t kMissingPin = 200;    // no Teensy has a pin 200
constexpr uint8_t kMissingPort = 4;     // ports are 0..3 (A..D)
constexpr uint8_t kMissingEncoder = 2;  // decoders are 0 (ENC1) and 1 (ENC2)

// ---- What the timers' handlers saw -----------------------------------------------------------
struct TimerLog {
  std::vector<uint32_t> frame_us;  // micros_now() at each frame ISR
  uint32_t khz_calls = 0;
  // The frame ISR hands these words to the ports listed, one entry per call, then idle words.
  std::vector<FrameWords> to_hand;
  std::vector<uint8_t> ports;
  std::vector<FrameWords> handed;  // what each call handed over (one entry per call)
};
inline TimerLog& timer_log() {
  static TimerLog log;
  return log;
}
inline void on_frame() {
  TimerLog& log = timer_log();
  log.frame_us.push_back(stepdance::hal::micros_now());
  const size_t call = log.handed.size();
  const FrameWords words = call < log.to_hand.size() ? log.to_hand[call] : FrameWords{0, 0};
  for (uint8_t port : log.ports) stepdance::hal::port_out_frame(port, words);
  log.handed.push_back(words);
}
inline void on_khz() { ++timer_log().khz_calls; }

// ---- What the capture sink saw ---------------------------------------------------------------
struct CaptureLog {
  std::vector<stepdance::protocol::CapturedPulse> pulses;
  std::vector<void*> contexts;
};
inline void capture_sink(void* context, const stepdance::protocol::CapturedPulse& pulse) {
  auto* log = static_cast<CaptureLog*>(context);
  log->pulses.push_back(pulse);
  log->contexts.push_back(context);
}

template <typename Adapter>
class HalContract : public ::testing::Test {
 protected:
  void SetUp() override {
    timer_log() = TimerLog{};
    Adapter::reset();
  }
  void TearDown() override { stepdance::hal::timers_stop(); }
};

TYPED_TEST_SUITE_P(HalContract);

// GTEST_SKIP returns only from the function it is written in, so each test opens with this.
#define HAL_CONTRACT_SKIP_UNLESS(clause)                                       \
  do {                                                                         \
    if (const char* why = TypeParam::skip_reason(clause)) GTEST_SKIP() << why; \
  } while (0)

// ---- Time ------------------------------------------------------------------------------------

TYPED_TEST_P(HalContract, MicrosNowCountsMicrosecondsAndNeverGoesBack) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kMicrosUnits);
  const uint32_t start = stepdance::hal::micros_now();
  uint32_t previous = start;
  for (int step = 0; step < 10; ++step) {
    TypeParam::advance_us(100);
    const uint32_t now = stepdance::hal::micros_now();
    EXPECT_LT(now - previous, 0x80000000u) << "went back at step " << step;  // wrap-safe order
    previous = now;
  }
  // 1000 µs passed; a backend whose reads take time may add part of a microsecond.
  EXPECT_GE(previous - start, 1000u);
  EXPECT_LE(previous - start, 1001u);
}

TYPED_TEST_P(HalContract, CyclesNowRunsAtCyclesPerSecond) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kCyclesRate);
  EXPECT_EQ(stepdance::hal::cycles_per_second(), kCoreHz);
  const uint32_t start = stepdance::hal::cycles_now();
  TypeParam::advance_us(1000);
  const uint32_t elapsed = stepdance::hal::cycles_now() - start;
  const uint32_t expected = kCoreHz / 1000u;  // 1 ms of cycles
  EXPECT_GE(elapsed, expected);
  EXPECT_LE(elapsed, expected + 600u) << "more than 1 µs of extra cycles";
}

// ---- Timers ----------------------------------------------------------------------------------

TYPED_TEST_P(HalContract, FrameTimerCallsOnFrameOncePerTick) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kFrameTimerTicks);
  ASSERT_EQ(stepdance::hal::frame_timer_start(kFramePeriodUs, &on_frame), Status::kOk);
  TypeParam::settle();
  const size_t before = timer_log().frame_us.size();
  for (int tick = 0; tick < 5; ++tick) TypeParam::tick();
  EXPECT_EQ(timer_log().frame_us.size(), before + 5);
}

TYPED_TEST_P(HalContract, FrameTimerCallsOnFrameEveryPeriodUs) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kFramePeriod);
  ASSERT_EQ(stepdance::hal::frame_timer_start(kFramePeriodUs, &on_frame), Status::kOk);
  TypeParam::settle();
  for (int tick = 0; tick < 5; ++tick) TypeParam::tick();
  const std::vector<uint32_t>& at = timer_log().frame_us;
  ASSERT_GE(at.size(), 5u);
  for (size_t i = 1; i < at.size(); ++i) EXPECT_EQ(at[i] - at[i - 1], kFramePeriodUs) << "between calls " << i;
}

TYPED_TEST_P(HalContract, KhzTimerCallsOnTickEveryPeriodUsAfterTheFrame) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kKhzTimer);
  ASSERT_EQ(stepdance::hal::frame_timer_start(kFramePeriodUs, &on_frame), Status::kOk);
  ASSERT_EQ(stepdance::hal::khz_timer_start(kKhzPeriodUs, &on_khz), Status::kOk);
  TypeParam::settle();
  // 100 frame ticks are 4 ms: four kilohertz ticks.
  for (int tick = 0; tick < 100; ++tick) TypeParam::tick();
  EXPECT_EQ(timer_log().khz_calls, 100u * kFramePeriodUs / kKhzPeriodUs);
}

TYPED_TEST_P(HalContract, TimersStopEndsBothTimers) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kTimersStop);
  ASSERT_EQ(stepdance::hal::frame_timer_start(kFramePeriodUs, &on_frame), Status::kOk);
  ASSERT_EQ(stepdance::hal::khz_timer_start(kKhzPeriodUs, &on_khz), Status::kOk);
  TypeParam::settle();
  stepdance::hal::timers_stop();
  const size_t frames = timer_log().frame_us.size();
  const uint32_t khz = timer_log().khz_calls;
  for (int tick = 0; tick < 50; ++tick) TypeParam::tick();
  EXPECT_EQ(timer_log().frame_us.size(), frames);
  EXPECT_EQ(timer_log().khz_calls, khz);
}

// ---- Output ports ----------------------------------------------------------------------------

TYPED_TEST_P(HalContract, PortOutBeginClaimsOnceAndRefusesAMissingPort) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kPortOutClaims);
  EXPECT_EQ(stepdance::hal::port_out_begin(3), Status::kOk);
  EXPECT_EQ(stepdance::hal::port_out_begin(3), Status::kBusy);
  EXPECT_EQ(stepdance::hal::port_out_begin(kMissingPort), Status::kNoSuchPin);
}

TYPED_TEST_P(HalContract, PortOutShiftsTheHandedWordsUnchangedAtTheNextTick) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kPortOutWaveform);
  // Distinct STEP and DIR words, with the highest bit set (bit 0 is the idle level, kept low).
  const std::vector<FrameWords> words = {
      {0x0000000Cu, 0x0000000Eu}, {0x80000300u, 0x00000380u}, {0x00F00000u, 0xFFFFFFFEu}};
  timer_log().to_hand = words;
  timer_log().ports = {0, 1};
  ASSERT_EQ(stepdance::hal::port_out_begin(0), Status::kOk);
  ASSERT_EQ(stepdance::hal::port_out_begin(1), Status::kOk);
  ASSERT_EQ(stepdance::hal::frame_timer_start(kFramePeriodUs, &on_frame), Status::kOk);
  TypeParam::settle();
  size_t checked = 0;
  for (int tick = 0; tick < 6; ++tick) {
    const std::vector<FrameWords> handed = timer_log().handed;  // before this tick's frame
    TypeParam::tick();
    const FrameWords expected = handed.empty() ? FrameWords{0, 0} : handed.back();
    for (uint8_t port : {uint8_t{0}, uint8_t{1}}) {
      const FrameWords out = TypeParam::launched(port);
      EXPECT_EQ(out.step_bits, expected.step_bits) << "tick " << tick << " port " << int{port};
      EXPECT_EQ(out.dir_bits, expected.dir_bits) << "tick " << tick << " port " << int{port};
    }
    if (!handed.empty() && handed.size() <= words.size()) ++checked;
  }
  EXPECT_EQ(checked, words.size()) << "every handed frame went out once";
}

// ---- Input ports -----------------------------------------------------------------------------

TYPED_TEST_P(HalContract, CapturedPulseReachesTheSinkUnchangedWithItsContext) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kCaptureDelivery);
  CaptureLog log;
  ASSERT_EQ(stepdance::hal::port_in_begin(2, stepdance::protocol::DirSampleEdge::kRising, &capture_sink, &log),
            Status::kOk);
  const stepdance::protocol::CapturedPulse first{100, 400, true, 0};
  const stepdance::protocol::CapturedPulse second{65000, 70, false, 2};  // wrapped, two periods later
  TypeParam::inject_pulse(2, first);
  TypeParam::inject_pulse(2, second);
  ASSERT_EQ(log.pulses.size(), 2u);
  EXPECT_EQ(log.pulses[0].rise_ticks, 100u);
  EXPECT_EQ(log.pulses[0].fall_ticks, 400u);
  EXPECT_TRUE(log.pulses[0].dir_high);
  EXPECT_EQ(log.pulses[1].rise_ticks, 65000u);
  EXPECT_EQ(log.pulses[1].fall_ticks, 70u);
  EXPECT_FALSE(log.pulses[1].dir_high);
  EXPECT_EQ(log.pulses[1].extra_periods, 2u);
  EXPECT_EQ(log.contexts[0], &log);
  EXPECT_EQ(
      stepdance::hal::port_in_begin(kMissingPort, stepdance::protocol::DirSampleEdge::kRising, &capture_sink, &log),
      Status::kNoSuchPin);
}

TYPED_TEST_P(HalContract, CaptureClockIsTheBusClockOnSixteenBitCounters) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kCaptureClock);
  for (uint8_t port = 0; port < 4; ++port) {
    const stepdance::protocol::CaptureClock clock = stepdance::hal::port_in_clock(port);
    EXPECT_EQ(clock.ticks_per_us, kBusTicksPerUs) << "port " << int{port};
    EXPECT_EQ(clock.counter_mask, kCaptureCounterMask) << "port " << int{port};
  }
}

// ---- Quadrature ------------------------------------------------------------------------------

TYPED_TEST_P(HalContract, QuadratureReadsTheCountAndWriteOverwritesIt) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kQuadrature);
  ASSERT_EQ(stepdance::hal::quadrature_begin(0), Status::kOk);
  ASSERT_EQ(stepdance::hal::quadrature_begin(1), Status::kOk);
  EXPECT_EQ(stepdance::hal::quadrature_begin(kMissingEncoder), Status::kNoSuchPin);
  TypeParam::set_quadrature(0, -1234);
  TypeParam::set_quadrature(1, 40000);
  EXPECT_EQ(stepdance::hal::quadrature_read(0), -1234);
  EXPECT_EQ(stepdance::hal::quadrature_read(1), 40000);
  stepdance::hal::quadrature_write(0, 77);
  EXPECT_EQ(stepdance::hal::quadrature_read(0), 77);
  EXPECT_EQ(stepdance::hal::quadrature_read(1), 40000) << "writing one decoder changed the other";
}

// ---- Analog inputs ---------------------------------------------------------------------------

TYPED_TEST_P(HalContract, AdcReadsTenBitsAndCountsConversions) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kAdcRange);
  ASSERT_EQ(stepdance::hal::adc_begin(kAdcPin), Status::kOk);
  const uint32_t before = stepdance::hal::adc_sample_count(kAdcPin);
  TypeParam::set_adc_fraction(kAdcPin, 0.0);
  EXPECT_EQ(stepdance::hal::adc_read(kAdcPin), 0u);
  TypeParam::set_adc_fraction(kAdcPin, 1.0);
  EXPECT_EQ(stepdance::hal::adc_read(kAdcPin), kAdcFullScale);
  TypeParam::set_adc_fraction(kAdcPin, 0.5);
  EXPECT_NEAR(stepdance::hal::adc_read(kAdcPin), 512, 1);
  EXPECT_EQ(stepdance::hal::adc_sample_count(kAdcPin) - before, 3u);
}

TYPED_TEST_P(HalContract, AdcBeginRefusesAPinWithoutAdc) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kAdcPins);
  EXPECT_EQ(stepdance::hal::adc_begin(kPinWithoutAdc), Status::kNoSuchPin);
  EXPECT_EQ(stepdance::hal::adc_begin(kMissingPin), Status::kNoSuchPin);
}

// ---- Digital pins ----------------------------------------------------------------------------

TYPED_TEST_P(HalContract, GpioOutputReadsBackTheLevelItDrives) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kGpioOutput);
  ASSERT_EQ(stepdance::hal::gpio_mode(kGpioPin, stepdance::hal::PinMode::kOutput), Status::kOk);
  stepdance::hal::gpio_write(kGpioPin, true);
  EXPECT_TRUE(stepdance::hal::gpio_read(kGpioPin));
  stepdance::hal::gpio_write(kGpioPin, false);
  EXPECT_FALSE(stepdance::hal::gpio_read(kGpioPin));
}

TYPED_TEST_P(HalContract, GpioInputReadsTheLevelDrivenFromOutside) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kGpioInput);
  ASSERT_EQ(stepdance::hal::gpio_mode(kInputPin, stepdance::hal::PinMode::kInput), Status::kOk);
  TypeParam::drive_pin(kInputPin, true);
  EXPECT_TRUE(stepdance::hal::gpio_read(kInputPin));
  TypeParam::drive_pin(kInputPin, false);
  EXPECT_FALSE(stepdance::hal::gpio_read(kInputPin));
}

TYPED_TEST_P(HalContract, GpioModeRefusesAMissingPin) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kGpioPins);
  EXPECT_EQ(stepdance::hal::gpio_mode(kMissingPin, stepdance::hal::PinMode::kOutput), Status::kNoSuchPin);
  EXPECT_FALSE(stepdance::hal::gpio_read(kMissingPin));
}

// ---- Console ---------------------------------------------------------------------------------

inline std::string every_byte_value() {
  std::string bytes;
  for (int value = 0; value < 256; ++value) bytes.push_back(static_cast<char>(value));
  bytes += "\r\n\0\xFF";  // line ends and the values a text path would alter, again
  return bytes;
}

TYPED_TEST_P(HalContract, ConsoleBytesPassUnchangedAndInOrder) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kConsoleBytes);
  const std::string bytes = every_byte_value();
  TypeParam::feed_console(bytes);
  stepdance::ByteStream& console = stepdance::hal::console();
  EXPECT_EQ(console.bytes_available(), bytes.size());
  std::string received;
  for (int byte = console.read_byte(); byte >= 0; byte = console.read_byte())
    received.push_back(static_cast<char>(byte));
  EXPECT_EQ(received, bytes);
  EXPECT_EQ(console.bytes_available(), 0u);
  size_t sent = 0;
  while (sent < bytes.size()) {
    const size_t wrote =
        console.write_bytes(reinterpret_cast<const uint8_t*>(bytes.data()) + sent, bytes.size() - sent);
    ASSERT_GT(wrote, 0u);
    sent += wrote;
  }
  EXPECT_EQ(TypeParam::take_console_output(), bytes);
}

// ---- Storage ---------------------------------------------------------------------------------

TYPED_TEST_P(HalContract, StorageReadsBackWhatWasWrittenThenEndOfFile) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kStorageRoundTrip);
  stepdance::FileStorage& storage = stepdance::hal::storage();
  const std::string bytes = every_byte_value();
  int handle = -1;
  ASSERT_EQ(storage.open("conformance.bin", stepdance::FileMode::kWriteTruncate, handle), Status::kOk);
  EXPECT_GE(handle, 0);
  ASSERT_EQ(storage.write(handle, reinterpret_cast<const uint8_t*>(bytes.data()), 100), Status::kOk);
  ASSERT_EQ(storage.close(handle), Status::kOk);
  ASSERT_EQ(storage.open("conformance.bin", stepdance::FileMode::kAppend, handle), Status::kOk);
  ASSERT_EQ(storage.write(handle, reinterpret_cast<const uint8_t*>(bytes.data()) + 100, bytes.size() - 100),
            Status::kOk);
  ASSERT_EQ(storage.close(handle), Status::kOk);
  ASSERT_EQ(storage.open("conformance.bin", stepdance::FileMode::kRead, handle), Status::kOk);
  std::string back(bytes.size() + 10, '?');
  size_t total = 0;
  size_t read = 0;
  while (storage.read(handle, reinterpret_cast<uint8_t*>(&back[total]), back.size() - total, read) == Status::kOk &&
         read > 0) {
    total += read;
  }
  back.resize(total);
  EXPECT_EQ(back, bytes);
  EXPECT_EQ(read, 0u) << "end of file reads 0 bytes";
  EXPECT_EQ(storage.close(handle), Status::kOk);
}

TYPED_TEST_P(HalContract, NonvolatileStoreReadsBackWritesAndErasedBytesAreFF) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kNonvolatileRoundTrip);
  stepdance::NonvolatileStore& store = stepdance::hal::nonvolatile_store();
  const size_t size = store.size_bytes();
  // nonvolatile_store.hpp: 1080 bytes on a Teensy 4.0, 4284 on a 4.1.
  EXPECT_TRUE(size == 1080 || size == 4284) << size;
  uint8_t tail[8] = {};
  ASSERT_EQ(store.read(size - sizeof tail, tail, sizeof tail), Status::kOk);
  for (uint8_t byte : tail) EXPECT_EQ(byte, 0xFFu) << "never-written bytes read as erased flash";
  const uint8_t written[5] = {0x00, 0x5A, 0xA5, 0xFF, 0x01};
  ASSERT_EQ(store.write(100, written, sizeof written), Status::kOk);
  uint8_t back[5] = {};
  ASSERT_EQ(store.read(100, back, sizeof back), Status::kOk);
  for (size_t i = 0; i < sizeof back; ++i) EXPECT_EQ(back[i], written[i]) << i;
  EXPECT_EQ(store.read(size - 2, back, 3), Status::kBadArgument);
  EXPECT_EQ(store.write(size, written, 1), Status::kBadArgument);
}

// ---- Critical sections -----------------------------------------------------------------------

TYPED_TEST_P(HalContract, CriticalSectionsNestAndRestoreTheOuterState) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kCriticalNesting);
  const uint32_t outer = stepdance::hal::irq_save();  // interrupts were on
  const uint32_t inner = stepdance::hal::irq_save();  // they were off
  EXPECT_NE(inner, outer) << "irq_save() must tell 'on' from 'off'";
  stepdance::hal::irq_restore(inner);
  const uint32_t still = stepdance::hal::irq_save();  // restoring the inner state keeps them off
  EXPECT_EQ(still, inner);
  stepdance::hal::irq_restore(still);
  stepdance::hal::irq_restore(outer);
  const uint32_t after = stepdance::hal::irq_save();  // the outer restore turned them back on
  EXPECT_EQ(after, outer);
  stepdance::hal::irq_restore(after);
  {
    stepdance::hal::CriticalSection guard;
    EXPECT_EQ(stepdance::hal::irq_save(), inner) << "inside a CriticalSection interrupts are off";
    stepdance::hal::irq_restore(inner);
  }
  const uint32_t out = stepdance::hal::irq_save();
  EXPECT_EQ(out, outer) << "the guard's end restored them";
  stepdance::hal::irq_restore(out);
}

// ---- Fault -----------------------------------------------------------------------------------

TYPED_TEST_P(HalContract, EnterSafeStateStopsFramesAndDisablesTheDrivers) {
  HAL_CONTRACT_SKIP_UNLESS(Clause::kFaultSafeState);
  timer_log().to_hand = std::vector<FrameWords>(100, FrameWords{0x00000C00u, 0x00000E00u});
  timer_log().ports = {2};
  ASSERT_EQ(stepdance::hal::port_out_begin(2), Status::kOk);
  ASSERT_EQ(stepdance::hal::frame_timer_start(kFramePeriodUs, &on_frame), Status::kOk);
  TypeParam::settle();
  TypeParam::tick();
  EXPECT_FALSE(TypeParam::drivers_disabled());
  stepdance::hal::enter_safe_state();
  const size_t frames = timer_log().frame_us.size();
  for (int tick = 0; tick < 5; ++tick) {
    TypeParam::tick();
    const FrameWords out = TypeParam::launched(2);
    EXPECT_EQ(out.step_bits | out.dir_bits, 0u) << "a frame went out after the safe state, tick " << tick;
  }
  EXPECT_EQ(timer_log().frame_us.size(), frames) << "the frame ISR ran after the safe state";
  EXPECT_TRUE(TypeParam::drivers_disabled());
}

REGISTER_TYPED_TEST_SUITE_P(
    HalContract, MicrosNowCountsMicrosecondsAndNeverGoesBack, CyclesNowRunsAtCyclesPerSecond,
    FrameTimerCallsOnFrameOncePerTick, FrameTimerCallsOnFrameEveryPeriodUs,
    KhzTimerCallsOnTickEveryPeriodUsAfterTheFrame, TimersStopEndsBothTimers,
    PortOutBeginClaimsOnceAndRefusesAMissingPort, PortOutShiftsTheHandedWordsUnchangedAtTheNextTick,
    CapturedPulseReachesTheSinkUnchangedWithItsContext, CaptureClockIsTheBusClockOnSixteenBitCounters,
    QuadratureReadsTheCountAndWriteOverwritesIt, AdcReadsTenBitsAndCountsConversions, AdcBeginRefusesAPinWithoutAdc,
    GpioOutputReadsBackTheLevelItDrives, GpioInputReadsTheLevelDrivenFromOutside, GpioModeRefusesAMissingPin,
    ConsoleBytesPassUnchangedAndInOrder, StorageReadsBackWhatWasWrittenThenEndOfFile,
    NonvolatileStoreReadsBackWritesAndErasedBytesAreFF, CriticalSectionsNestAndRestoreTheOuterState,
    EnterSafeStateStopsFramesAndDisablesTheDrivers);

}  // namespace hal_conformance
