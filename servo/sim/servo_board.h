// servo_board.h: the real servo driver firmware (.elf) running on a simavr ATtiny84, with probes.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "waveform.h"

struct avr_t;
struct avr_irq_t;

namespace servo_sim {

// Data-space addresses (I/O address + 0x20, ATtiny84 datasheet register summary).
namespace reg {
constexpr std::uint16_t kTifr1 = 0x2B;  // bit 0: TOV1
constexpr std::uint16_t kPcmsk0 = 0x32;
constexpr std::uint16_t kDdra = 0x3A;
constexpr std::uint16_t kGimsk = 0x5B;   // bit 4: PCIE0
constexpr std::uint16_t kIcr1l = 0x44;   // ICR1H follows at +1
constexpr std::uint16_t kOcr1bl = 0x48;  // OCR1BH follows at +1
constexpr std::uint16_t kTccr1b = 0x4E;
constexpr std::uint16_t kTccr1a = 0x4F;
}  // namespace reg

// A level change of a digital signal.
struct LevelChange {
  std::uint64_t cycle;
  bool high;
};

// A 16-bit register value, recorded when the CPU wrote its low byte (which completes the write).
struct RegisterWrite16 {
  std::uint64_t cycle;
  std::uint16_t value;
};

class ServoBoard {
 public:
  static constexpr std::uint64_t kCyclesPerUs = 8;  // 8 MHz internal RC, as fused

  // Loads elf_path into a fresh ATtiny84 at 8 MHz; position_symbol names the firmware's 32-bit step
  // position in SRAM. Throws std::runtime_error if the ELF or the symbol cannot be loaded.
  ServoBoard(const std::string& elf_path, const std::string& position_symbol);
  ~ServoBoard();
  ServoBoard(const ServoBoard&) = delete;
  ServoBoard& operator=(const ServoBoard&) = delete;

  // Schedules pin events (absolute times, at or after now) on STEP (PA7) and DIR (PA6).
  void play(const std::vector<PinEvent>& events);

  // Runs the CPU until time_us. Throws std::runtime_error if the firmware crashes or stops.
  void run_until_us(std::uint64_t time_us);

  std::uint64_t now_cycles() const;

  // The firmware's step position, read from SRAM.
  std::int32_t position_steps() const;

  std::uint8_t read8(std::uint16_t address) const;
  std::uint16_t read16(std::uint16_t low_address) const;

  // Every write of OCR1B, in order.
  const std::vector<RegisterWrite16>& ocr1b_writes() const { return ocr1b_writes_; }

  // simavr's Timer1 compare-B output: the waveform OC1B would carry (set at BOTTOM, cleared after
  // the OCR1B match). simavr 1.6 does not route it to PA5 in mode 14, and its width does not follow
  // later OCR1B writes; it is trustworthy only while OCR1B keeps its start-up value.
  const std::vector<LevelChange>& compare_b_output() const { return compare_b_output_; }

  // Cycles at which TOV1 (counter reached TOP: end of a PWM period) was seen set.
  const std::vector<std::uint64_t>& period_end_cycles() const { return period_end_cycles_; }

  // Cycle of the first TCCR1B write that selected a clock, if any; and how many such writes.
  std::optional<std::uint64_t> timer_start_cycle() const { return timer_start_cycle_; }
  int timer_start_count() const { return timer_start_count_; }

  // Low, high and extended fuse bytes from the ELF's .fuse section (0 when absent).
  const std::array<std::uint8_t, 3>& fuses() const { return fuses_; }

 private:
  static std::uint64_t on_pin_event(avr_t* avr, std::uint64_t when, void* param);
  static void on_ocr1bl_write(avr_t* avr, std::uint16_t address, std::uint8_t value, void* param);
  static void on_compare_b_output(avr_irq_t* irq, std::uint32_t value, void* param);
  static void on_tccr1b_write(avr_t* avr, std::uint16_t address, std::uint8_t value, void* param);

  avr_t* avr_ = nullptr;
  avr_irq_t* step_irq_ = nullptr;
  avr_irq_t* dir_irq_ = nullptr;
  std::uint16_t position_address_ = 0;
  std::vector<PinEvent> pending_;
  std::size_t next_pending_ = 0;
  std::vector<RegisterWrite16> ocr1b_writes_;
  std::vector<LevelChange> compare_b_output_;
  std::vector<std::uint64_t> period_end_cycles_;
  bool tov1_was_set_ = false;
  std::optional<std::uint64_t> timer_start_cycle_;
  int timer_start_count_ = 0;
  std::array<std::uint8_t, 3> fuses_{};
};

}  // namespace servo_sim
