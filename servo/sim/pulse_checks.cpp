// pulse_checks.cpp: checks shared by the harness scenarios (registers, period timing, OCR1B updates).
#include "pulse_checks.h"

#include <algorithm>
#include <iostream>
#include <set>
#include <string>

namespace servo_sim {
namespace {

constexpr std::uint8_t kTccr1aExpected = 0x22;   // COM1B1 | WGM11: OC1B non-inverting, WGM11:10 = 10
constexpr std::uint8_t kTccr1bExpected = 0x1A;   // WGM13 | WGM12 | CS11: mode 14, clk/8
constexpr std::uint8_t kServoPinMask = 1u << 5;  // PA5 / OC1B
constexpr std::uint8_t kStepPinMask = 1u << 7;   // PA7 / PCINT7
constexpr std::uint8_t kDirPinMask = 1u << 6;    // PA6
constexpr std::uint8_t kPcie0Mask = 1u << 4;
// The flag is seen after the instruction during which it was set (at most 4 cycles).
constexpr std::uint64_t kBoundaryToleranceCycles = 4;
// An edge just before a period end may still be in the interrupt when the main loop reads.
constexpr std::uint64_t kEdgeLatencyUs = 10;

std::string hex(unsigned value) {
  static const char* digits = "0123456789ABCDEF";
  return std::string("0x") + digits[(value >> 4) & 0xF] + digits[value & 0xF];
}

// Period end k (1-based) was seen where simavr's Timer1 puts it: start + k * period.
void check_period_ends(const ServoBoard& board, const Expectations& expect, Report& report) {
  const std::uint64_t start = board.timer_start_cycle().value_or(0);
  const std::uint64_t period_cycles = static_cast<std::uint64_t>(expect.period_us) * ServoBoard::kCyclesPerUs;
  const auto& ends = board.period_end_cycles();
  for (std::size_t k = 0; k < ends.size(); ++k) {
    const std::uint64_t nominal = start + (k + 1) * period_cycles;
    const std::uint64_t seen = ends[k];
    report.that("period end " + std::to_string(k + 1), seen >= nominal && seen - nominal <= kBoundaryToleranceCycles,
                "at cycle " + std::to_string(seen) + ", expected " + std::to_string(nominal));
  }
  const std::uint64_t whole_periods = (board.now_cycles() - start) / period_cycles;
  report.that("period count", ends.size() + 1 >= whole_periods && ends.size() <= whole_periods,
              std::to_string(ends.size()) + " period ends seen in " + std::to_string(whole_periods) + " whole periods");
}

// The OCR1B values allowed for a write at write_cycle after period_end_cycle.
std::set<std::uint16_t> allowed_compares(const Waveform& waveform, const Expectations& expect,
                                         std::uint64_t period_end_cycle, std::uint64_t write_cycle) {
  std::set<std::uint16_t> allowed;
  const std::uint64_t end_us = period_end_cycle / ServoBoard::kCyclesPerUs;
  const std::uint64_t from_us = end_us > kEdgeLatencyUs ? end_us - kEdgeLatencyUs : 0;
  for (std::uint64_t t = from_us; t <= write_cycle / ServoBoard::kCyclesPerUs; ++t) {
    allowed.insert(expect.compare(waveform.position_at_us(t)));
  }
  return allowed;
}

}  // namespace

void check_configuration(const ServoBoard& board, const Expectations& expect, Report& report) {
  report.equal<unsigned>("ICR1 (TOP, period - 1)", expect.top(), board.read16(reg::kIcr1l));
  report.that("TCCR1A", board.read8(reg::kTccr1a) == kTccr1aExpected,
              "expected " + hex(kTccr1aExpected) + ", got " + hex(board.read8(reg::kTccr1a)));
  report.that("TCCR1B", board.read8(reg::kTccr1b) == kTccr1bExpected,
              "expected " + hex(kTccr1bExpected) + ", got " + hex(board.read8(reg::kTccr1b)));
  const std::uint8_t ddra = board.read8(reg::kDdra);
  report.that("PA5 (OC1B) is an output", (ddra & kServoPinMask) != 0);
  report.that("PA6/PA7 (DIR/STEP) are inputs", (ddra & (kStepPinMask | kDirPinMask)) == 0);
  report.that("PCMSK0 selects only PA7", board.read8(reg::kPcmsk0) == kStepPinMask,
              "got " + hex(board.read8(reg::kPcmsk0)));
  report.that("GIMSK.PCIE0 set", (board.read8(reg::kGimsk) & kPcie0Mask) != 0);
  report.equal("timer starts", 1, board.timer_start_count());
  const char* names[] = {"low fuse", "high fuse", "extended fuse"};
  for (std::size_t i = 0; i < expect.fuses.size(); ++i) {
    report.that(names[i], board.fuses()[i] == expect.fuses[i],
                "expected " + hex(expect.fuses[i]) + ", got " + hex(board.fuses()[i]));
  }
}

void check_pulse_updates(const ServoBoard& board, const Waveform& waveform, const Expectations& expect,
                         Report& report) {
  check_period_ends(board, expect, report);
  const auto& writes = board.ocr1b_writes();
  const auto& ends = board.period_end_cycles();
  if (!report.that("OCR1B written at start-up", !writes.empty())) {
    return;
  }
  const std::uint64_t start = board.timer_start_cycle().value_or(0);
  report.that("first OCR1B write precedes the timer start", writes.front().cycle < start);
  report.equal<unsigned>("start-up OCR1B (neutral width - 1)", expect.compare(0), writes.front().value);

  // Every period end that is old enough must have exactly one write in its window, and no write
  // may fall outside a window.
  const std::uint64_t window_cycles = kUpdateWindowUs * ServoBoard::kCyclesPerUs;
  std::size_t next_write = 1;
  for (std::size_t k = 0; k < ends.size(); ++k) {
    const std::uint64_t window_end = ends[k] + window_cycles;
    std::size_t in_window = 0;
    while (next_write < writes.size() && writes[next_write].cycle <= window_end) {
      const RegisterWrite16& write = writes[next_write];
      if (!report.that(
              "OCR1B write inside an update window", write.cycle >= ends[k],
              "write at cycle " + std::to_string(write.cycle) + " before period end " + std::to_string(ends[k]))) {
        return;
      }
      const auto allowed = allowed_compares(waveform, expect, ends[k], write.cycle);
      report.that("OCR1B after period end " + std::to_string(k + 1), allowed.count(write.value) == 1,
                  "wrote " + std::to_string(write.value) + ", expected one of [" + std::to_string(*allowed.begin()) +
                      ".." + std::to_string(*allowed.rbegin()) + "]");
      ++in_window;
      ++next_write;
    }
    if (window_end <= board.now_cycles()) {
      report.equal("OCR1B writes after period end " + std::to_string(k + 1), std::size_t{1}, in_window);
    }
  }
  report.that("no OCR1B write outside the update windows", next_write == writes.size(),
              std::to_string(writes.size() - next_write) + " stray write(s)");
}

void check_neutral_output_pulses(const ServoBoard& board, const Expectations& expect, Report& report) {
  // simavr arms the first pulse in the cycle TCCR1B is written, one cycle early.
  constexpr std::uint64_t kToleranceCycles = 1;
  const std::uint64_t period_cycles = static_cast<std::uint64_t>(expect.period_us) * ServoBoard::kCyclesPerUs;
  const std::uint64_t width_cycles = static_cast<std::uint64_t>(expect.width_us(0)) * ServoBoard::kCyclesPerUs;
  const auto within = [](std::uint64_t actual, std::uint64_t expected) {
    return actual + kToleranceCycles >= expected && actual <= expected + kToleranceCycles;
  };
  const auto& output = board.compare_b_output();
  int pulses = 0;
  int bad_periods = 0;
  int bad_widths = 0;
  for (std::size_t i = 1; i < output.size(); ++i) {
    const std::uint64_t span = output[i].cycle - output[i - 1].cycle;
    if (output[i - 1].high && !output[i].high) {
      ++pulses;
      bad_widths += within(span, width_cycles) ? 0 : 1;
    }
    if (output[i].high && i >= 2 && output[i - 2].high) {
      bad_periods += within(output[i].cycle - output[i - 2].cycle, period_cycles) ? 0 : 1;
    }
  }
  report.that("compare-B output pulses seen", pulses > 0);
  report.equal("compare-B periods not " + std::to_string(expect.period_us) + " us", 0, bad_periods);
  report.equal("compare-B pulses not " + std::to_string(expect.width_us(0)) + " us", 0, bad_widths);
}

void check_settled(const ServoBoard& board, const Waveform& waveform, const Expectations& expect, Report& report,
                   const std::string& label) {
  const std::int32_t position = waveform.position_at_us(board.now_cycles() / ServoBoard::kCyclesPerUs);
  report.equal(label + ": SRAM step position", position, board.position_steps());
  report.equal<unsigned>(label + ": OCR1B", expect.compare(position), board.read16(reg::kOcr1bl));
}

void run_checking_position(ServoBoard& board, const Waveform& waveform, std::uint64_t grid_start_us,
                           std::uint64_t until_us, Report& report) {
  constexpr std::uint64_t kCheckOffsetUs = 30;
  const std::uint64_t now_us = board.now_cycles() / ServoBoard::kCyclesPerUs;
  std::uint64_t frame_us = grid_start_us;
  if (now_us > grid_start_us) {
    frame_us += (now_us - grid_start_us) / Waveform::kFrameUs * Waveform::kFrameUs;
  }
  int mismatches = 0;
  for (; frame_us + kCheckOffsetUs <= until_us; frame_us += Waveform::kFrameUs) {
    const std::uint64_t at_us = frame_us + kCheckOffsetUs;
    board.run_until_us(at_us);
    const std::int32_t expected = waveform.position_at_us(at_us);
    const std::int32_t actual = board.position_steps();
    if (expected != actual && mismatches++ < 5) {
      std::cout << "  detail: SRAM position at " << at_us << " us: expected " << expected << ", got " << actual << '\n';
    }
  }
  board.run_until_us(until_us);
  report.equal("frames whose SRAM position was wrong", 0, mismatches);
}

}  // namespace servo_sim
