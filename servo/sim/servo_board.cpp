// servo_board.cpp: the real servo driver firmware (.elf) running on a simavr ATtiny84, with probes.
#include "servo_board.h"

#include <simavr/avr_ioport.h>  // AVR_IOCTL_IOPORT_GETIRQ, IOPORT_IRQ_PIN*
#include <simavr/avr_timer.h>   // AVR_IOCTL_TIMER_GETIRQ, TIMER_IRQ_OUT_COMP
#include <simavr/sim_avr.h>     // avr_t, avr_make_mcu_by_name, avr_run
#include <simavr/sim_elf.h>     // elf_firmware_t, elf_read_firmware
#include <simavr/sim_io.h>      // avr_register_io_write, avr_io_getirq

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "elf_symbol.h"

namespace servo_sim {
namespace {

constexpr std::uint32_t kAvrDataSpaceTag = 0x800000;  // avr-gcc's marker for SRAM addresses
constexpr std::uint8_t kClockSelectMask = 0x07;       // TCCR1B CS12:10
constexpr std::uint8_t kTov1Mask = 0x01;

// Frees what elf_read_firmware() allocated; simavr keeps its own copies once loaded.
void release_firmware(elf_firmware_t& firmware) {
  std::free(firmware.flash);
  std::free(firmware.eeprom);
  std::free(firmware.fuse);
  std::free(firmware.lockbits);
  for (std::uint32_t i = 0; i < firmware.symbolcount; ++i) {
    std::free(firmware.symbol[i]);
  }
  std::free(firmware.symbol);
}

}  // namespace

ServoBoard::ServoBoard(const std::string& elf_path, const std::string& position_symbol) {
  const std::optional<std::uint32_t> position = elf_symbol_address(elf_path, position_symbol);
  if (!position || (*position & kAvrDataSpaceTag) == 0) {
    throw std::runtime_error("no SRAM symbol '" + position_symbol + "' in " + elf_path);
  }
  position_address_ = static_cast<std::uint16_t>(*position - kAvrDataSpaceTag);

  elf_firmware_t firmware;
  std::memset(&firmware, 0, sizeof firmware);
  if (elf_read_firmware(elf_path.c_str(), &firmware) != 0) {
    throw std::runtime_error("simavr cannot read " + elf_path);
  }
  std::strcpy(firmware.mmcu, "attiny84");
  firmware.frequency = kCyclesPerUs * 1'000'000;
  for (std::size_t i = 0; i < fuses_.size() && firmware.fuse != nullptr && i < firmware.fusesize; ++i) {
    fuses_[i] = firmware.fuse[i];
  }

  avr_ = avr_make_mcu_by_name(firmware.mmcu);
  if (avr_ == nullptr) {
    release_firmware(firmware);
    throw std::runtime_error("this simavr has no attiny84 core");
  }
  avr_init(avr_);
  avr_load_firmware(avr_, &firmware);
  release_firmware(firmware);

  step_irq_ = avr_io_getirq(avr_, AVR_IOCTL_IOPORT_GETIRQ('A'), IOPORT_IRQ_PIN7);
  dir_irq_ = avr_io_getirq(avr_, AVR_IOCTL_IOPORT_GETIRQ('A'), IOPORT_IRQ_PIN6);
  avr_raise_irq(step_irq_, 0);
  avr_raise_irq(dir_irq_, 0);
  avr_irq_t* compare_b = avr_io_getirq(avr_, AVR_IOCTL_TIMER_GETIRQ('1'), TIMER_IRQ_OUT_COMP + AVR_TIMER_COMPB);
  if (compare_b == nullptr) {
    throw std::runtime_error("this simavr has no Timer1 compare-B output");
  }
  avr_irq_register_notify(compare_b, &ServoBoard::on_compare_b_output, this);
  avr_register_io_write(avr_, reg::kOcr1bl, &ServoBoard::on_ocr1bl_write, this);
  avr_register_io_write(avr_, reg::kTccr1b, &ServoBoard::on_tccr1b_write, this);
}

ServoBoard::~ServoBoard() {
  if (avr_ != nullptr) {
    avr_terminate(avr_);
    std::free(avr_);  // allocated by avr_make_mcu_by_name()
  }
}

void ServoBoard::play(const std::vector<PinEvent>& events) {
  pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(next_pending_));
  next_pending_ = 0;
  pending_.insert(pending_.end(), events.begin(), events.end());
  std::stable_sort(pending_.begin(), pending_.end(),
                   [](const PinEvent& a, const PinEvent& b) { return a.time_us < b.time_us; });
  if (!pending_.empty()) {
    const std::uint64_t first_cycle = pending_.front().time_us * kCyclesPerUs;
    const std::uint64_t delay = first_cycle > avr_->cycle ? first_cycle - avr_->cycle : 0;
    avr_cycle_timer_register(avr_, delay, &ServoBoard::on_pin_event, this);
  }
}

// Applies every event due at `when` and asks to be called again at the next one.
std::uint64_t ServoBoard::on_pin_event(avr_t*, std::uint64_t when, void* param) {
  auto* board = static_cast<ServoBoard*>(param);
  while (board->next_pending_ < board->pending_.size()) {
    const PinEvent& event = board->pending_[board->next_pending_];
    const std::uint64_t event_cycle = event.time_us * kCyclesPerUs;
    if (event_cycle > when) {
      return event_cycle;
    }
    avr_raise_irq(event.line == Line::step ? board->step_irq_ : board->dir_irq_, event.high ? 1 : 0);
    ++board->next_pending_;
  }
  return 0;
}

void ServoBoard::on_ocr1bl_write(avr_t* avr, std::uint16_t, std::uint8_t value, void* param) {
  auto* board = static_cast<ServoBoard*>(param);
  const auto high = static_cast<std::uint16_t>(avr->data[reg::kOcr1bl + 1] << 8);
  board->ocr1b_writes_.push_back({avr->cycle, static_cast<std::uint16_t>(high | value)});
}

void ServoBoard::on_compare_b_output(avr_irq_t*, std::uint32_t value, void* param) {
  auto* board = static_cast<ServoBoard*>(param);
  board->compare_b_output_.push_back({board->avr_->cycle, value != 0});
}

void ServoBoard::on_tccr1b_write(avr_t* avr, std::uint16_t, std::uint8_t value, void* param) {
  auto* board = static_cast<ServoBoard*>(param);
  if ((value & kClockSelectMask) != 0) {
    if (!board->timer_start_cycle_) {
      board->timer_start_cycle_ = avr->cycle;
    }
    ++board->timer_start_count_;
  }
}

void ServoBoard::run_until_us(std::uint64_t time_us) {
  const std::uint64_t end_cycle = time_us * kCyclesPerUs;
  while (avr_->cycle < end_cycle) {
    const int state = avr_run(avr_);
    if (state == cpu_Done || state == cpu_Crashed) {
      throw std::runtime_error("firmware stopped or crashed at cycle " + std::to_string(avr_->cycle));
    }
    const bool tov1_set = (avr_->data[reg::kTifr1] & kTov1Mask) != 0;
    if (tov1_set && !tov1_was_set_) {
      period_end_cycles_.push_back(avr_->cycle);
    }
    tov1_was_set_ = tov1_set;
  }
}

std::uint64_t ServoBoard::now_cycles() const { return avr_->cycle; }

std::int32_t ServoBoard::position_steps() const {
  std::uint32_t raw = 0;
  for (int i = 3; i >= 0; --i) {
    raw = (raw << 8) | avr_->data[position_address_ + i];
  }
  return static_cast<std::int32_t>(raw);
}

std::uint8_t ServoBoard::read8(std::uint16_t address) const { return avr_->data[address]; }

std::uint16_t ServoBoard::read16(std::uint16_t low_address) const {
  return static_cast<std::uint16_t>(avr_->data[low_address] | (avr_->data[low_address + 1] << 8));
}

}  // namespace servo_sim
