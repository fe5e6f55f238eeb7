// QwiicTwist: the SparkFun Qwiic Twist RGB knob over a QwiicBus, as a BlockPort source and a
// source of turns and clicks for menus.
#pragma once

#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/block_port.hpp"
#include "stepdance/core/spsc_queue.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/qwiic/qwiic_bus.hpp"
#include "stepdance/qwiic/twist_registers.hpp"

namespace stepdance {

/// The knob is polled from the loop every poll interval (default 20 ms) with one transfer that
/// reads its registers 0x01..0x0C (status, version, interrupt enables, count, difference, the
/// two "milliseconds since" timers). Clicks and turns latched in the status register are cleared
/// by writing it, only after a poll that saw the button up (a click latches at its release, and a
/// write clears clicks that arrived after the poll too). Register writes (colour, count,
/// interrupts) queue up to kWriteQueue deep.
///
/// count() is the detents turned since begin(), unwrapped from the 16-bit register; the
/// `output` BlockPort carries it into the frame like an Encoder's count (set_ratio gives world
/// units), handed over through a single-producer queue. begin() first checks the ID register; a
/// missing knob or another device there is logged once and retried every second.
class QwiicTwist : public Block {
 public:
  const char* type_name() const override { return "QwiicTwist"; }
  using Callback = void (*)();
  static constexpr uint8_t kWriteQueue = 4;
  static constexpr uint32_t kRetryMs = 1000;

  enum class State : uint8_t { kNotStarted, kIdentifying, kReady, kFailed, kWrongDevice };

  /// Claims the bus, registers in the loop and pre-channel stages. Context: loop.
  Status begin(uint8_t bus = QWIIC_1, uint8_t address = twist::kDefaultAddress);
  /// How often the knob is read (5..1000 ms). Context: loop.
  Status set_poll_interval_ms(uint16_t interval_ms);
  /// world_units per `counts` detents on `output` (24 detents a turn). Context: loop.
  void set_ratio(double world_units, double counts = 1.0) { output.set_ratio(world_units, counts); }

  /// Detents turned since begin(), clockwise positive. Context: loop.
  int32_t count() const { return count_; }
  /// Clicks (press and release) seen since begin(). Context: loop.
  uint32_t clicks() const { return clicks_; }
  /// True while the button is held, as of the last poll. Context: loop.
  bool pressed() const { return pressed_; }
  /// The knob's own timers as of the last poll (ms, saturating at 65535). Context: loop.
  uint16_t ms_since_movement() const { return since_movement_ms_; }
  uint16_t ms_since_button() const { return since_button_ms_; }
  /// Firmware version (major × 256 + minor) read at the last poll. Context: loop.
  uint16_t firmware_version() const { return version_; }
  State state() const { return state_; }
  /// The latest failed transfer's result since the knob last became ready (kIdle if none).
  /// Context: loop.
  hal::I2cResult last_result() const { return last_failure_; }
  /// Polls completed. Context: loop.
  uint32_t polls() const { return polls_; }

  /// Queued register writes (kFull when kWriteQueue are waiting). Context: loop.
  Status set_color(uint8_t red, uint8_t green, uint8_t blue);
  Status connect_color(int16_t red_per_detent, int16_t green_per_detent, int16_t blue_per_detent);
  /// Writes the knob's count register (count() keeps counting on without a jump). Context: loop.
  Status set_register_count(int16_t count);
  Status enable_interrupts(bool on_turn, bool on_button);
  Status set_turn_interrupt_timeout_ms(uint16_t timeout_ms);

  /// Called from dance_loop() once per click. Context: loop.
  void set_callback_on_click(Callback callback) { on_click_ = callback; }

  /// The knob's count: counts inside, world units outside.
  BlockPort output;

  void loop() override { service(); }
  /// Frame work: the latest count from the loop onto `output`, pushed. Context: frame ISR.
  void run() override;
  void report_counters(CounterSink& sink) const override;

 private:
  struct PendingWrite {
    uint8_t bytes[8];
    uint8_t length;
  };
  static void on_read_done(void* self, hal::I2cResult result);
  static void on_write_done(void* self, hal::I2cResult result);
  void service();
  void start_read();
  void finish_read(hal::I2cResult result);
  void take_registers();
  void take_status(uint8_t status);
  void fail(hal::I2cResult result, State state);
  Status queue_write(const uint8_t* bytes, uint8_t length);

  QwiicBus* bus_ = nullptr;
  uint8_t address_ = twist::kDefaultAddress;
  State state_ = State::kNotStarted;
  State reported_state_ = State::kNotStarted;
  uint16_t poll_interval_ms_ = 20;
  uint32_t last_poll_us_ = 0;
  uint32_t failed_at_us_ = 0;
  hal::I2cResult last_failure_ = hal::I2cResult::kIdle;
  I2cRequest read_request_;
  I2cRequest write_request_;
  uint8_t read_command_ = twist::kId;
  uint8_t registers_[12] = {};  // 0x01..0x0C (or the ID alone while identifying)
  PendingWrite writes_[kWriteQueue] = {};
  uint8_t write_head_ = 0;
  uint8_t write_count_ = 0;
  uint8_t write_buffer_[8] = {};
  bool have_baseline_ = false;
  int16_t last_register_count_ = 0;
  int32_t count_ = 0;
  uint32_t clicks_ = 0;
  bool pressed_ = false;
  bool click_latch_counted_ = false;  // the clicked bit the knob holds was counted already
  bool clear_queued_ = false;         // a status clear waits in the queue or is on the wire
  bool clear_on_wire_ = false;        // the write on the wire is that clear
  uint16_t since_movement_ms_ = 0;
  uint16_t since_button_ms_ = 0;
  uint16_t version_ = 0;
  uint32_t polls_ = 0;
  uint64_t failures_ = 0;
  Callback on_click_ = nullptr;
  SpscQueue<int32_t, 4> counts_to_frame_;
  DecimalPosition position_counts_ = 0;
};

}  // namespace stepdance
