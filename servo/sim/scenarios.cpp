// scenarios.cpp: the simavr harness scenarios; each loads the firmware afresh and checks one behaviour.
#include "scenarios.h"

#include <cstdint>
#include <string>
#include <vector>

#include "pulse_checks.h"
#include "servo_board.h"
#include "waveform.h"

namespace servo_sim {
namespace {

constexpr std::uint64_t kStimulusStartUs = 1000;  // well after start-up (a few us)

// Idle frames covering two whole periods, so that the position reaches OCR1B.
std::uint64_t settle_frames(const Expectations& expect) {
  return (2 * static_cast<std::uint64_t>(expect.period_us)) / Waveform::kFrameUs + 1;
}

// Plays the whole waveform, checking the position every frame, and checks OCR1B at its end.
void play_and_check(const Expectations& expect, Report& report, const Waveform& waveform, const std::string& label) {
  ServoBoard board(expect.elf_path, expect.position_symbol);
  board.play(waveform.events());
  run_checking_position(board, waveform, kStimulusStartUs, waveform.end_us(), report);
  check_settled(board, waveform, expect, report, label);
  check_pulse_updates(board, waveform, expect, report);
}

}  // namespace

void scenario_start_up(const Expectations& expect, Report& report) {
  report.begin("servo_start_up");
  ServoBoard board(expect.elf_path, expect.position_symbol);
  board.run_until_us(static_cast<std::uint64_t>(3 * expect.period_us + expect.period_us / 2));
  check_configuration(board, expect, report);
  const Waveform idle(0);
  check_pulse_updates(board, idle, expect, report);
  check_settled(board, idle, expect, report, "idle");
  check_neutral_output_pulses(board, expect, report);
  report.equal("period ends in 3.5 periods", std::size_t{3}, board.period_end_cycles().size());
  report.end();
}

void scenario_stepdance_stream(const Expectations& expect, Report& report) {
  report.begin("servo_stepdance_stream");
  Waveform waveform(kStimulusStartUs);
  waveform.stepdance_steps(300);
  waveform.pause_frames(settle_frames(expect));
  waveform.stepdance_steps(-120);
  waveform.pause_frames(settle_frames(expect));
  report.equal("waveform position", 180, waveform.final_position_steps());
  play_and_check(expect, report, waveform, "after +300 -120");
  report.end();
}

void scenario_direction_changes(const Expectations& expect, Report& report) {
  report.begin("servo_direction_changes");
  std::vector<std::int8_t> directions;
  std::uint32_t lcg = 12345;
  for (int i = 0; i < 3000; ++i) {
    lcg = lcg * 1103515245u + 12345u;
    directions.push_back(((lcg >> 16) & 3u) == 0 ? -1 : 1);  // drifts forward, many reversals
  }
  Waveform waveform(kStimulusStartUs);
  waveform.stepdance_frames(directions);
  waveform.pause_frames(settle_frames(expect));
  play_and_check(expect, report, waveform, "after 3000 frames");
  report.end();
}

void scenario_dir_sampled_at_rising_edge(const Expectations& expect, Report& report) {
  report.begin("servo_dir_sampled_at_rising_edge");
  // 7 us pulses whose DIR flips 6 us after the rising edge: 150 forward, 50 reverse by the
  // rising-edge level; a firmware reading DIR at the falling edge would end at -100 instead.
  Waveform waveform(kStimulusStartUs);
  for (int i = 0; i < 200; ++i) {
    waveform.frame_with_dir_flip_mid_pulse(i % 4 != 0, 7, 6);
  }
  waveform.pause_frames(settle_frames(expect));
  report.equal("waveform position", 100, waveform.final_position_steps());
  play_and_check(expect, report, waveform, "after 200 flipped frames");
  report.end();
}

void scenario_clamp_beyond_window(const Expectations& expect, Report& report) {
  report.begin("servo_clamp_beyond_window");
  const std::int32_t top = expect.top_limit_steps;
  const std::int32_t bottom = expect.bottom_limit_steps;
  // Each leg runs at the full 25 kHz, so the position crosses a limit between two period ends;
  // the positions visited are top + 100, top - 50, bottom - 100, 0.
  const std::vector<std::int32_t> legs = {top + 100, -150, bottom - top - 50, -bottom + 100};
  Waveform waveform(kStimulusStartUs);
  std::vector<std::uint64_t> checkpoints_us;
  for (const std::int32_t steps : legs) {
    waveform.stepdance_steps(steps);
    waveform.pause_frames(settle_frames(expect));
    checkpoints_us.push_back(waveform.end_us());
  }
  ServoBoard board(expect.elf_path, expect.position_symbol);
  board.play(waveform.events());
  for (const std::uint64_t checkpoint_us : checkpoints_us) {
    run_checking_position(board, waveform, kStimulusStartUs, checkpoint_us, report);
    const std::int32_t position = waveform.position_at_us(checkpoint_us);
    check_settled(board, waveform, expect, report, "at position " + std::to_string(position));
  }
  report.equal("final position", 0, waveform.final_position_steps());
  check_pulse_updates(board, waveform, expect, report);
  report.end();
}

void scenario_step_edges_during_position_read(const Expectations& expect, Report& report) {
  report.begin("servo_step_edges_during_position_read");
  ServoBoard board(expect.elf_path, expect.position_symbol);
  constexpr std::uint64_t kTimerStartedUs = 100;
  board.run_until_us(kTimerStartedUs);
  if (!report.that("timer started", board.timer_start_cycle().has_value())) {
    report.end();
    return;
  }
  const std::uint64_t timer_start_us = *board.timer_start_cycle() / ServoBoard::kCyclesPerUs;
  const auto period_us = static_cast<std::uint64_t>(expect.period_us);
  // Period k gets a +1 edge at its end + (k - 5) us (-4..+11 us), and a -1 edge half a period later.
  Waveform waveform(kTimerStartedUs);
  waveform.step_at_us(kStimulusStartUs, -1);
  constexpr int kSweptPeriods = 16;
  for (int k = 1; k <= kSweptPeriods; ++k) {
    const std::uint64_t period_end_us = timer_start_us + static_cast<std::uint64_t>(k) * period_us;
    waveform.step_at_us(period_end_us + static_cast<std::uint64_t>(k) - 5, +1);
    waveform.step_at_us(period_end_us + period_us / 2, -1);
  }
  waveform.pause_frames(settle_frames(expect));
  board.play(waveform.events());
  board.run_until_us(waveform.end_us());
  check_settled(board, waveform, expect, report, "after the sweep");
  check_pulse_updates(board, waveform, expect, report);
  report.end();
}

void scenario_every_signal_width(const Expectations& expect, Report& report) {
  report.begin("servo_every_signal_width");
  Waveform waveform(kStimulusStartUs);
  for (std::uint32_t pulse_us = 2; pulse_us <= 7; ++pulse_us) {
    waveform.stepdance_steps(40, pulse_us);
    waveform.stepdance_steps(-15, pulse_us);
  }
  waveform.pause_frames(settle_frames(expect));
  play_and_check(expect, report, waveform, "after 2..7 us signals");
  report.end();
}

}  // namespace servo_sim
