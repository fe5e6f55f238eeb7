// QwiicTwist: identification, polling, unwrapping the count, clearing latched events, writes.
#include "stepdance/qwiic/qwiic_twist.hpp"

#include "stepdance/core/text_writer.hpp"
#include "stepdance/hal/hal.hpp"

namespace stepdance {
namespace {

constexpr uint8_t kFirstPolled = twist::kStatus;                            // 0x01
constexpr uint8_t kPolledBytes = twist::kSinceButtonMs + 2 - kFirstPolled;  // through 0x0C
static_assert(kPolledBytes == 12, "the poll reads registers 0x01..0x0C");

uint16_t little_endian(const uint8_t* bytes) { return static_cast<uint16_t>(bytes[0] | (bytes[1] << 8)); }
uint8_t low_byte(uint16_t value) { return static_cast<uint8_t>(value & 0xFF); }
uint8_t high_byte(uint16_t value) { return static_cast<uint8_t>(value >> 8); }

}  // namespace

// Two stages: the loop polls the knob over I2C, the frame (pre-channel) hands the latest count to the
// output port. The count starts at 0 whatever the knob's register holds, so plugging in a knob that
// was turned before never moves the machine.
Status QwiicTwist::begin(uint8_t bus, uint8_t address) {
  if (address > 0x7F) return Status::kBadArgument;
  bus_ = &qwiic_bus(bus);
  const Status claimed = bus_->begin();
  if (claimed != Status::kOk) return claimed;
  address_ = address;
  read_request_.context = this;
  read_request_.done = &QwiicTwist::on_read_done;
  write_request_.context = this;
  write_request_.done = &QwiicTwist::on_write_done;
  output.begin(&position_counts_, BLOCKPORT_UNDEFINED, this);
  output.reset(0, true);
  state_ = State::kIdentifying;
  const Status frame = register_in(Stage::kPreChannel);
  if (frame != Status::kOk) return frame;
  return register_in(Stage::kLoop);
}

// 5 ms at the fastest: each poll is a 13-byte transfer on a bus shared with other devices (a display).
Status QwiicTwist::set_poll_interval_ms(uint16_t interval_ms) {
  if (interval_ms < 5 || interval_ms > 1000) return Status::kBadArgument;
  poll_interval_ms_ = interval_ms;
  return Status::kOk;
}

// Loop context. Identification (the ID register must read 0x5C, SparkFun's Qwiic Twist register map)
// comes before any poll, and is retried once per kRetryMs after a failure or a wrong device. Writes
// (colour, clearing events) go out only when the knob is known to be ready.
void QwiicTwist::service() {
  if (state_ == State::kNotStarted) return;
  const uint32_t now_us = hal::micros_now();
  if (state_ == State::kFailed || state_ == State::kWrongDevice) {
    if (now_us - failed_at_us_ < kRetryMs * 1000u) return;
    state_ = State::kIdentifying;
  }
  if (!read_request_.in_flight() &&
      (state_ == State::kIdentifying || now_us - last_poll_us_ >= poll_interval_ms_ * 1000u)) {
    last_poll_us_ = now_us;
    start_read();
  }
  if (state_ == State::kReady && write_count_ > 0 && !write_request_.in_flight()) {
    const PendingWrite& next = writes_[write_head_];
    for (uint8_t i = 0; i < next.length; ++i) write_buffer_[i] = next.bytes[i];
    write_request_.transfer = hal::I2cTransfer{address_, write_buffer_, next.length, nullptr, 0};
    if (bus_->submit(write_request_) == Status::kOk) {
      clear_on_wire_ = next.bytes[0] == twist::kStatus;
      write_head_ = static_cast<uint8_t>((write_head_ + 1) % kWriteQueue);
      --write_count_;
    } else {
      write_request_.result = hal::I2cResult::kIdle;
    }
  }
}

// One write-then-read transfer: register 0x01 (status) through 0x0C (time since the button), so one
// poll gives status, version, count and both timers consistently.
void QwiicTwist::start_read() {
  const bool identifying = state_ == State::kIdentifying;
  read_command_ = identifying ? twist::kId : kFirstPolled;
  read_request_.transfer =
      hal::I2cTransfer{address_, &read_command_, 1, registers_, static_cast<uint16_t>(identifying ? 1 : kPolledBytes)};
  if (bus_->submit(read_request_) != Status::kOk) read_request_.result = hal::I2cResult::kIdle;
}

void QwiicTwist::on_read_done(void* self, hal::I2cResult result) {
  static_cast<QwiicTwist*>(self)->finish_read(result);
}

// A status clear that reached the knob ends the latched click: the next clicked bit is a new one.
void QwiicTwist::on_write_done(void* self, hal::I2cResult result) {
  auto* knob = static_cast<QwiicTwist*>(self);
  if (knob->clear_on_wire_) {
    knob->clear_on_wire_ = false;
    knob->clear_queued_ = false;
    if (result == hal::I2cResult::kOk) knob->click_latch_counted_ = false;
  }
  if (result != hal::I2cResult::kOk) knob->fail(result, State::kFailed);
}

void QwiicTwist::finish_read(hal::I2cResult result) {
  if (result != hal::I2cResult::kOk) {
    fail(result, State::kFailed);
    return;
  }
  if (state_ == State::kIdentifying) {
    if (registers_[0] != twist::kIdValue) {
      fail(hal::I2cResult::kOk, State::kWrongDevice);
      return;
    }
    state_ = State::kReady;
    reported_state_ = State::kReady;
    last_failure_ = hal::I2cResult::kIdle;
    have_baseline_ = false;
    hal::log_message("QwiicTwist: ready");
    return;
  }
  take_registers();
}

// The knob's count register is a 16-bit signed value that wraps; the position is the sum of the
// wrapped differences, so it grows past ±32767 without a jump. The first poll after identification
// (or after writing the count) only sets the baseline.
void QwiicTwist::take_registers() {
  const auto at = [this](uint8_t reg) { return &registers_[reg - kFirstPolled]; };
  version_ = static_cast<uint16_t>((at(twist::kVersion)[0] << 8) | at(twist::kVersion)[1]);
  const auto register_count = static_cast<int16_t>(little_endian(at(twist::kCount)));
  if (have_baseline_) {
    count_ += static_cast<int16_t>(static_cast<uint16_t>(register_count) - static_cast<uint16_t>(last_register_count_));
  }
  have_baseline_ = true;
  last_register_count_ = register_count;
  since_movement_ms_ = little_endian(at(twist::kSinceMovementMs));
  since_button_ms_ = little_endian(at(twist::kSinceButtonMs));
  ++polls_;
  counts_to_frame_.push(count_);  // full: the frame is behind and takes a later count instead
  take_status(*at(twist::kStatus));
}

// Events latch in the status register until written back, and the Twist's firmware (1.x) lets a
// write replace the moved (bit 0) and clicked (bit 2) bits together, keeping held (bit 1): one bit
// cannot be cleared alone. A 0 in clicked also wipes a click that came after the poll; a 1 would
// invent one. A click sets its bit at the release, so the status is written only after a poll
// that saw the button up: no click can then land before the write unless a whole press and release
// fit between the poll and the write. A click latched while the button is down again stays
// latched (counted once) until a poll sees the button up; a release seen meanwhile (held, then up)
// is a second click, merged into the latch.
void QwiicTwist::take_status(uint8_t status) {
  const bool held = (status & twist::kStatusPressed) != 0;
  const bool released = pressed_ && !held;
  pressed_ = held;
  bool clicked = false;
  if ((status & twist::kStatusClicked) != 0) {
    clicked = !click_latch_counted_ || released;
    click_latch_counted_ = true;
  } else {
    click_latch_counted_ = false;
  }
  const uint8_t events = status & (twist::kStatusMoved | twist::kStatusClicked);
  if (!held && events != 0 && !clear_queued_) {
    const uint8_t clear[] = {twist::kStatus, 0};
    clear_queued_ = queue_write(clear, sizeof clear) == Status::kOk;
  }
  if (!clicked) return;
  ++clicks_;
  if (on_click_ != nullptr) on_click_();
}

void QwiicTwist::fail(hal::I2cResult result, State state) {
  ++failures_;
  const bool news = reported_state_ != state || last_failure_ != result;  // retries failing alike stay quiet
  reported_state_ = state;
  state_ = state;
  last_failure_ = result;
  failed_at_us_ = hal::micros_now();
  if (!news) return;
  char text[96];
  TextWriter line(text, sizeof text);
  line.text("QwiicTwist: QWIIC").unsigned_number(bus_->index()).text(" address ").unsigned_number(address_).text(": ");
  if (state == State::kWrongDevice) {
    line.text("not a Qwiic Twist (id ").unsigned_number(registers_[0]).text(")");
  } else {
    line.text(hal::to_string(result));
  }
  line.text(", retrying every second");
  hal::log_message(line.c_str());
}

// A register write is the register address then its bytes (little-endian for 16-bit registers); the
// small queue keeps them in order and refuses when full rather than overwrite one.
Status QwiicTwist::queue_write(const uint8_t* bytes, uint8_t length) {
  if (length > sizeof writes_[0].bytes) return Status::kBadArgument;
  if (write_count_ == kWriteQueue) return Status::kFull;
  PendingWrite& slot = writes_[(write_head_ + write_count_) % kWriteQueue];
  for (uint8_t i = 0; i < length; ++i) slot.bytes[i] = bytes[i];
  slot.length = length;
  ++write_count_;
  return Status::kOk;
}

Status QwiicTwist::set_color(uint8_t red, uint8_t green, uint8_t blue) {
  const uint8_t bytes[] = {twist::kRed, red, green, blue};
  return queue_write(bytes, sizeof bytes);
}

Status QwiicTwist::connect_color(int16_t red_per_detent, int16_t green_per_detent, int16_t blue_per_detent) {
  const auto r = static_cast<uint16_t>(red_per_detent);
  const auto g = static_cast<uint16_t>(green_per_detent);
  const auto b = static_cast<uint16_t>(blue_per_detent);
  const uint8_t bytes[] = {twist::kConnectRed, low_byte(r), high_byte(r), low_byte(g),
                           high_byte(g),       low_byte(b), high_byte(b)};
  return queue_write(bytes, sizeof bytes);
}

// Writes the knob's own count register; the machine-side count (count_) is not changed by it.
Status QwiicTwist::set_register_count(int16_t count) {
  const auto value = static_cast<uint16_t>(count);
  const uint8_t bytes[] = {twist::kCount, low_byte(value), high_byte(value)};
  const Status queued = queue_write(bytes, sizeof bytes);
  if (queued == Status::kOk) have_baseline_ = false;  // the next poll re-baselines: no jump
  return queued;
}

Status QwiicTwist::enable_interrupts(bool on_turn, bool on_button) {
  const uint8_t bits =
      static_cast<uint8_t>((on_turn ? twist::kInterruptOnTurn : 0) | (on_button ? twist::kInterruptOnButton : 0));
  const uint8_t bytes[] = {twist::kEnableInterrupts, bits};
  return queue_write(bytes, sizeof bytes);
}

Status QwiicTwist::set_turn_interrupt_timeout_ms(uint16_t timeout_ms) {
  const uint8_t bytes[] = {twist::kTurnInterruptTimeoutMs, low_byte(timeout_ms), high_byte(timeout_ms)};
  return queue_write(bytes, sizeof bytes);
}

// Frame context (pre-channel). The loop pushes counts into a single-producer/single-consumer queue;
// the frame drains it and uses the latest, so a slow loop never makes the frame wait and stale counts
// are skipped. When the queue is full the loop drops that count and a later one carries the position.
void QwiicTwist::run() {
  int32_t latest = 0;
  bool fresh = false;
  while (counts_to_frame_.pop(latest) == Status::kOk) fresh = true;
  if (fresh) output.set(latest);
  output.push();
}

void QwiicTwist::report_counters(CounterSink& sink) const {
  sink.counter("polls", polls_);
  sink.counter("clicks", clicks_);
  sink.counter("failures", failures_);
  sink.counter("ready", state_ == State::kReady ? 1 : 0);
}

}  // namespace stepdance
