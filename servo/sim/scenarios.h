// scenarios.h: the simavr harness scenarios; each loads the firmware afresh and checks one behaviour.
#pragma once

#include "expectations.h"
#include "report.h"

namespace servo_sim {

// Start-up: registers, fuses, neutral pulse (also timed on simavr's compare-B output), one OCR1B
// write per period, position 0.
void scenario_start_up(const Expectations& expect, Report& report);

// A 25 kHz Stepdance stream (DIR 1 us ahead of 7 us STEP pulses) forward, then back.
void scenario_stepdance_stream(const Expectations& expect, Report& report);

// Direction changing between most frames, streaming across several period ends.
void scenario_direction_changes(const Expectations& expect, Report& report);

// DIR flips during the STEP pulse: the level at the rising edge decides.
void scenario_dir_sampled_at_rising_edge(const Expectations& expect, Report& report);

// Positions beyond the window clamp the width at the limit; the position keeps counting.
void scenario_clamp_beyond_window(const Expectations& expect, Report& report);

// STEP edges swept across the moment the main loop reads the position, while the position crosses
// -1 <-> 0 (all four bytes change): no torn value may reach OCR1B.
void scenario_step_edges_during_position_read(const Expectations& expect, Report& report);

// The shortest Stepdance signal (X, 2 us) and the other widths are all counted.
void scenario_every_signal_width(const Expectations& expect, Report& report);

}  // namespace servo_sim
