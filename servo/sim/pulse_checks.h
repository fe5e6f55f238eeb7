// pulse_checks.h: checks shared by the harness scenarios (registers, period timing, OCR1B updates).
#pragma once

#include <cstdint>

#include "expectations.h"
#include "report.h"
#include "servo_board.h"
#include "waveform.h"

namespace servo_sim {

// OCR1B writes must follow a period end (TOV1) within this many us.
constexpr std::uint64_t kUpdateWindowUs = 50;

// Timer1, port and interrupt configuration right after start-up, and the fuse bytes.
void check_configuration(const ServoBoard& board, const Expectations& expect, Report& report);

// Period ends are exactly period_us apart from the timer start; OCR1B starts at neutral, then is
// written once per period right after each period end, with the value for a position the waveform
// held between that period end and the write.
void check_pulse_updates(const ServoBoard& board, const Waveform& waveform, const Expectations& expect, Report& report);

// While the position stays 0: simavr's compare-B output (see ServoBoard::compare_b_output) rises
// exactly once per period and every pulse is the neutral width, i.e. ICR1 + 1 and OCR1B + 1 us.
void check_neutral_output_pulses(const ServoBoard& board, const Expectations& expect, Report& report);

// The SRAM position equals the waveform's position now, and so does the last OCR1B written.
// Call at least one full period after the last pulse.
void check_settled(const ServoBoard& board, const Waveform& waveform, const Expectations& expect, Report& report,
                   const std::string& label);

// Runs board to until_us, comparing the SRAM position with the waveform's in every 40 us frame
// (30 us into the frame, when the frame's STEP pulse has been handled). The frame grid starts at
// grid_start_us.
void run_checking_position(ServoBoard& board, const Waveform& waveform, std::uint64_t grid_start_us,
                           std::uint64_t until_us, Report& report);

}  // namespace servo_sim
