// OledDisplay: init sequence, chunked updates, failure and retry.
#include "stepdance/qwiic/oled_display.hpp"

#include "stepdance/core/text_writer.hpp"
#include "stepdance/hal/hal.hpp"
#include "stepdance/qwiic/font_5x7.hpp"
#include "stepdance/qwiic/ssd1306.hpp"

namespace stepdance {
namespace {

using namespace ssd1306;

// The power-on configuration of a 128×32 panel with its internal charge pump, in the order the
// datasheet's software flow chart gives (display off first, on last). One command a line with its
// argument bytes, which clang-format would split apart.
// clang-format off
constexpr uint8_t kInitSequence[] = {
    kControlCommands,
    kDisplayOff,
    kSetClock, 0x80,
    kSetMultiplex, OledDisplay::kHeightPx - 1,
    kSetDisplayOffset, 0x00,
    kStartLineZero,
    kChargePump, kChargePumpOn,
    kSetAddressingMode, kHorizontalAddressing,
    kSegmentRemap,
    kComScanReversed,
    kSetComPins, 0x02,
    kSetContrast, 0x8F,
    kSetPrecharge, 0xF1,
    kSetVcomDeselect, 0x40,
    kDeactivateScroll,
    kFollowRam,
    kNormalDisplay,
    kDisplayOn,
};
// clang-format on

constexpr uint8_t kLineUnknown = 0x01;  // a row cache entry that matches no text

}  // namespace

// Loop context only: the display is drawn in RAM and sent over I2C from the loop, never from the frame
// (a full 512-byte refresh is about 12 ms of wire time at 400 kHz). Everything starts dirty so the first pass after the
// init sequence paints the whole panel, whatever it showed before a reset.
Status OledDisplay::begin(uint8_t bus, uint8_t address) {
  if (address > 0x7F) return Status::kBadArgument;
  bus_ = &qwiic_bus(bus);
  const Status claimed = bus_->begin();
  if (claimed != Status::kOk) return claimed;
  address_ = address;
  request_.context = this;
  request_.done = &OledDisplay::on_done;
  state_ = State::kStarting;
  dirty_chunks_ = 0xFFFF;
  for (auto& line : lines_) line[0] = static_cast<char>(kLineUnknown);
  return register_in(Stage::kLoop);
}

// The text-row cache is invalidated too, so the next print_line() redraws even the same text.
void OledDisplay::clear() {
  for (uint8_t& column : ram_) column = 0;
  dirty_chunks_ = 0xFFFF;
  for (auto& line : lines_) line[0] = static_cast<char>(kLineUnknown);
}

// SSD1306 display RAM layout (datasheet, GDDRAM): a byte is 8 vertical pixels of one page (8 rows), bit 0 at the
// top, so y selects page y/8 and bit y%8. Only a real change marks its chunk dirty, keeping the bus idle
// for a static picture.
void OledDisplay::set_pixel(uint8_t x, uint8_t y, bool on) {
  if (x >= kWidthPx || y >= kHeightPx) return;
  const uint8_t page = y / 8;
  uint8_t& column = ram_[page * kWidthPx + x];
  const uint8_t bit = static_cast<uint8_t>(1u << (y % 8));
  const uint8_t updated = on ? static_cast<uint8_t>(column | bit) : static_cast<uint8_t>(column & ~bit);
  if (updated == column) return;
  column = updated;
  mark_dirty(page, x, x);
  lines_[page][0] = static_cast<char>(kLineUnknown);
}

bool OledDisplay::pixel(uint8_t x, uint8_t y) const {
  if (x >= kWidthPx || y >= kHeightPx) return false;
  return (ram_[(y / 8) * kWidthPx + x] >> (y % 8)) & 1u;
}

// Text rows are the 4 pages of the 128×32 panel; each character is a 6-pixel cell (5 glyph columns and
// one blank), 21 cells to a row. Only changed bytes are written to RAM and marked dirty.
void OledDisplay::draw_text(uint8_t column, uint8_t row, const char* text) {
  if (row >= kTextRows || text == nullptr) return;
  uint8_t* page = &ram_[row * kWidthPx];
  uint8_t cell = column;
  for (; *text != '\0' && cell < kTextColumns; ++text, ++cell) {
    const uint8_t* glyph = font5x7::glyph(*text);
    const uint8_t x0 = static_cast<uint8_t>(cell * kCellWidthPx);
    for (uint8_t i = 0; i < kCellWidthPx; ++i) {
      const uint8_t bits = i < font5x7::kColumns ? glyph[i] : 0;
      if (page[x0 + i] != bits) {
        page[x0 + i] = bits;
        mark_dirty(row, static_cast<uint8_t>(x0 + i), static_cast<uint8_t>(x0 + i));
      }
    }
  }
  lines_[row][0] = static_cast<char>(kLineUnknown);
}

// For a status screen redrawn every refresh: the row is padded to its full width (so shorter text
// erases what was there) and skipped entirely when identical to what the row already shows.
void OledDisplay::print_line(uint8_t row, const char* text) {
  if (row >= kTextRows || text == nullptr) return;
  char padded[kTextColumns + 1];
  uint8_t length = 0;
  for (; length < kTextColumns && text[length] != '\0'; ++length) padded[length] = text[length];
  for (uint8_t i = length; i < kTextColumns; ++i) padded[i] = ' ';
  padded[kTextColumns] = '\0';
  bool same = true;
  for (uint8_t i = 0; i <= kTextColumns && same; ++i) same = lines_[row][i] == padded[i];
  if (same) return;
  draw_text(0, row, padded);
  // The two columns right of the last cell (126, 127) stay blank.
  for (uint8_t i = 0; i <= kTextColumns; ++i) lines_[row][i] = padded[i];
}

// Dirty state is one bit per 32-column chunk of a page: 4 pages × 4 chunks = the 16 bits of dirty_chunks_.
// A chunk is the unit of transfer, small enough that one I2C write never holds the bus for long.
void OledDisplay::mark_dirty(uint8_t page, uint8_t first_x, uint8_t last_x) {
  for (uint8_t run = first_x / kChunkColumns; run <= last_x / kChunkColumns; ++run) {
    dirty_chunks_ = static_cast<uint16_t>(dirty_chunks_ | (1u << (page * kChunksPerPage + run)));
  }
}

// A full bus queue is not an error: the request is left idle and send_next() tries again next pass.
void OledDisplay::submit(uint8_t length) {
  request_.transfer = hal::I2cTransfer{address_, tx_, length, nullptr, 0};
  if (bus_->submit(request_) != Status::kOk) request_.result = hal::I2cResult::kIdle;  // full: retried next pass
}

// Loop context, one transfer in flight at a time. After a failure the panel is retried once per
// kRetryMs with the full init (it may have been unplugged or lost power), so a display plugged in
// later starts working without a reset.
void OledDisplay::send_next() {
  if (state_ == State::kNotStarted || request_.in_flight()) return;
  if (state_ == State::kFailed) {
    if (hal::micros_now() - failed_at_us_ < kRetryMs * 1000u) return;
    state_ = State::kStarting;
  }
  if (state_ == State::kStarting) {
    send_init();
    return;
  }
  if (dirty_chunks_ == 0) return;
  uint8_t chunk = 0;
  while ((dirty_chunks_ & (1u << chunk)) == 0) ++chunk;
  send_window(chunk);
}

void OledDisplay::send_init() {
  // The init sequence is longer than a data chunk's buffer: it is sent from flash directly.
  step_ = Step::kInit;
  request_.transfer = hal::I2cTransfer{address_, kInitSequence, sizeof kInitSequence, nullptr, 0};
  if (bus_->submit(request_) != Status::kOk) request_.result = hal::I2cResult::kIdle;
}

// A chunk is two transfers: set the column and page address window (datasheet commands 0x21/0x22),
// then the data; in horizontal addressing mode the data fills the window left to right.
void OledDisplay::send_window(uint8_t chunk) {
  step_ = Step::kWindow;
  chunk_ = chunk;
  const uint8_t page = chunk / kChunksPerPage;
  const uint8_t first_x = static_cast<uint8_t>((chunk % kChunksPerPage) * kChunkColumns);
  const uint8_t window[] = {kControlCommands,
                            kSetColumnRange,
                            first_x,
                            static_cast<uint8_t>(first_x + kChunkColumns - 1),
                            kSetPageRange,
                            page,
                            page};
  for (uint8_t i = 0; i < sizeof window; ++i) tx_[i] = window[i];
  submit(sizeof window);
}

void OledDisplay::send_data(uint8_t chunk) {
  step_ = Step::kData;
  const uint8_t page = chunk / kChunksPerPage;
  const uint8_t first_x = static_cast<uint8_t>((chunk % kChunksPerPage) * kChunkColumns);
  tx_[0] = kControlData;
  for (uint8_t i = 0; i < kChunkColumns; ++i) tx_[1 + i] = ram_[page * kWidthPx + first_x + i];
  // Cleared when copied: drawing while the bytes are on the wire marks the chunk again.
  dirty_chunks_ = static_cast<uint16_t>(dirty_chunks_ & ~(1u << chunk));
  submit(1 + kChunkColumns);
}

void OledDisplay::on_done(void* self, hal::I2cResult result) { static_cast<OledDisplay*>(self)->finish(result); }

// Bus completion callback (loop context, from QwiicBus::service): the window transfer chains the data
// transfer of the same chunk.
void OledDisplay::finish(hal::I2cResult result) {
  if (result != hal::I2cResult::kOk) {
    fail(result);
    return;
  }
  switch (step_) {
    case Step::kInit:
      state_ = State::kReady;
      last_failure_ = hal::I2cResult::kIdle;
      hal::log_message("OledDisplay: ready");
      break;
    case Step::kWindow: send_data(chunk_); break;
    case Step::kData: ++chunks_sent_; break;
  }
}

// Logs only a new kind of failure: a panel that stays absent would otherwise log every second.
void OledDisplay::fail(hal::I2cResult result) {
  ++failures_;
  // A display that came back after a failure may have lost power: it gets the whole init again
  // and every chunk.
  dirty_chunks_ = 0xFFFF;
  const bool news = last_failure_ != result;  // a retry failing the same way says nothing new
  state_ = State::kFailed;
  last_failure_ = result;
  failed_at_us_ = hal::micros_now();
  if (!news) return;
  char text[96];
  TextWriter line(text, sizeof text);
  line.text("OledDisplay: QWIIC").unsigned_number(bus_->index()).text(" address ").unsigned_number(address_);
  line.text(": ").text(hal::to_string(result)).text(", retrying every second");
  hal::log_message(line.c_str());
}

void OledDisplay::report_counters(CounterSink& sink) const {
  sink.counter("chunks_sent", chunks_sent_);
  sink.counter("failures", failures_);
  sink.counter("ready", state_ == State::kReady ? 1 : 0);
}

}  // namespace stepdance
