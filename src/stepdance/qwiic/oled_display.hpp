// OledDisplay: a 128×32 SSD1306 OLED (SparkFun QWIIC OLED 0.91") with a framebuffer in the board
// and partial updates over a QwiicBus.
#pragma once

#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/qwiic/qwiic_bus.hpp"

namespace stepdance {

/// The display keeps its picture in the board (the framebuffer) and sends only what changed:
/// the screen is 16 chunks (4 pages of 8 rows × 4 runs of 32 columns), and a changed chunk
/// goes out as two transfers, its address window (7 bytes) and its 32 data bytes (33 bytes,
/// 0.77 ms at 400 kHz). With one transfer per loop pass (QwiicBus), no pass spends more than
/// that on the display; a full redraw takes 32 passes.
///
/// Drawing: set_pixel(), or text in a grid of 21 columns × 4 rows of 6×8-pixel cells in our
/// 5×7 font (lowercase shows as capitals). Errors: a display that does not answer, or a faulty
/// bus, is logged once, shown by state()/last_result(), and retried every second (with the
/// init sequence again, as a display that was unplugged has forgotten it). Nothing blocks.
class OledDisplay : public Block {
 public:
  const char* type_name() const override { return "OledDisplay"; }

  static constexpr uint8_t kWidthPx = 128;
  static constexpr uint8_t kHeightPx = 32;
  static constexpr uint8_t kPages = kHeightPx / 8;
  static constexpr uint8_t kChunkColumns = 32;
  static constexpr uint8_t kTextColumns = 21;  ///< 6-pixel cells in 128 pixels
  static constexpr uint8_t kTextRows = 4;
  static constexpr uint8_t kCellWidthPx = 6;
  /// The SparkFun board's address (its jumper selects 0x3D instead).
  static constexpr uint8_t kDefaultAddress = 0x3C;
  /// How long to wait before trying a display that failed again (ms).
  static constexpr uint32_t kRetryMs = 1000;

  /// Where the display is.
  enum class State : uint8_t {
    kNotStarted,
    kStarting,  ///< init sequence queued
    kReady,     ///< initialised; updates flow
    kFailed,    ///< the last transfer failed (see last_result()); retried after kRetryMs
  };

  /// Claims the bus (QWIIC_1 for the board-mounted display) and registers in the loop stage;
  /// the init sequence and a blank screen follow from dance_loop(). Errors from the bus.
  /// Context: loop.
  Status begin(uint8_t bus = QWIIC_1, uint8_t address = kDefaultAddress);

  /// Blanks the framebuffer. Context: loop.
  void clear();
  /// Lights (on) or darkens pixel (x, y), 0 ≤ x < 128, 0 ≤ y < 32 (others are ignored). Context: loop.
  void set_pixel(uint8_t x, uint8_t y, bool on);
  /// The framebuffer's pixel (x, y). Context: loop.
  bool pixel(uint8_t x, uint8_t y) const;
  /// Draws `text` from cell (column, row) on, cut at the right edge. Context: loop.
  void draw_text(uint8_t column, uint8_t row, const char* text);
  /// Replaces text row `row` (0..3) by `text`, padded with blanks to the right edge; a row that
  /// is already shown sends nothing. Context: loop.
  void print_line(uint8_t row, const char* text);

  /// True when the display shows the framebuffer (nothing left to send). Context: loop.
  bool up_to_date() const { return state_ == State::kReady && dirty_chunks_ == 0 && !request_.in_flight(); }
  State state() const { return state_; }
  /// The result of the latest failed transfer since the display last became ready (kIdle if
  /// none). Context: loop.
  hal::I2cResult last_result() const { return last_failure_; }
  /// The framebuffer, page by page: byte [page × 128 + x] holds rows page×8 .. page×8+7 of
  /// column x, bit 0 on top (the controller's RAM layout). Context: loop.
  const uint8_t* framebuffer() const { return ram_; }

  void loop() override { send_next(); }
  void report_counters(CounterSink& sink) const override;

 private:
  static constexpr uint8_t kChunksPerPage = kWidthPx / kChunkColumns;
  static void on_done(void* self, hal::I2cResult result);
  void send_next();
  void send_init();
  void send_window(uint8_t chunk);
  void send_data(uint8_t chunk);
  void finish(hal::I2cResult result);
  void fail(hal::I2cResult result);
  void mark_dirty(uint8_t page, uint8_t first_x, uint8_t last_x);
  void submit(uint8_t length);

  enum class Step : uint8_t { kInit, kWindow, kData };
  QwiicBus* bus_ = nullptr;
  uint8_t address_ = kDefaultAddress;
  State state_ = State::kNotStarted;
  Step step_ = Step::kInit;
  uint8_t chunk_ = 0;
  uint16_t dirty_chunks_ = 0xFFFF;  // bit page × 4 + run
  uint32_t failed_at_us_ = 0;
  hal::I2cResult last_failure_ = hal::I2cResult::kIdle;
  uint64_t chunks_sent_ = 0;
  uint64_t failures_ = 0;
  I2cRequest request_;
  uint8_t tx_[1 + kChunkColumns] = {};
  uint8_t ram_[kPages * kWidthPx] = {};
  char lines_[kTextRows][kTextColumns + 1] = {};
};

}  // namespace stepdance
