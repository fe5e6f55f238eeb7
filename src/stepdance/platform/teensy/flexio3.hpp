// FlexIO3 as the output-port engine: a hardware frame clock that launches every port's frame.
//
//   timer 4  "frame clock"   16-bit counter, free running; its output toggles every half period,
//                            so it rises once per frame period (40 µs): that rising edge IS the tick.
//   timer n  "port n"        n = 0..3, dual 8-bit baud mode, enabled on the rising edge of timer 4,
//                            32 bits at 1 µs, then disabled on compare. Shifter n (STEP) and
//                            shifter n+4 (DIR) shift on this one timer, so they stay in lock-step.
//   timer 5  "tick marker"   enabled on the same edge, disabled 4 FlexIO clocks later; its status
//                            flag raises the FlexIO3 interrupt (the tick ISR) once per frame.
//   timer 6  "commit guard"  enabled on the frame clock's falling edge (mid-period), disabled
//                            kCommitGuardClocks before the next tick; its flag (no interrupt)
//                            tells the commit that too little time is left to write every port.
//
// Shifters load SHIFTBUF when their timer is enabled (no start bit), so whatever sits in the
// buffers at a tick goes out at that tick, 1 µs per bit, LSB first. RM chapter 50 (FlexIO).
#pragma once

#if defined(__IMXRT1062__)

#include <stdint.h>

#include "stepdance/core/status.hpp"

namespace stepdance::platform::teensy::flexio {

/// FlexIO2/3 clock root: PLL3 480 MHz / 2 (pre-divider) / 2 (divider).
constexpr uint32_t kClockHz = 120000000u;
/// FlexIO clocks per microsecond (one frame bit).
constexpr uint32_t kClocksPerBit = kClockHz / 1000000u;
/// Bits in one frame transmission.
constexpr uint32_t kFrameBits = 32;
/// Shortest frame period the frame clock runs (a 4 µs transmission and 1 µs low).
constexpr uint32_t kMinFramePeriodUs = 5;
/// Ports on FlexIO3 (timers 0..3).
constexpr uint8_t kPorts = 4;
/// Timer numbers (timers 0..3 are the ports).
constexpr uint8_t kFrameClockTimer = 4;
constexpr uint8_t kTickMarkerTimer = 5;
constexpr uint8_t kCommitGuardTimer = 6;
/// FlexIO clocks from a tick to the marker's status flag.
constexpr uint32_t kMarkerDelayClocks = 4;
/// FlexIO clocks before a tick in which a commit no longer starts (3 µs): writing the 8 buffers
/// and settling takes under 1 µs, and the capture ISRs (priority 0, not masked by the commit) may
/// preempt it for up to 4 × 0.5 µs.
constexpr uint32_t kCommitGuardClocks = 3u * kClocksPerBit;

/// Clocks FlexIO2/3 from PLL3 at 120 MHz and enables FlexIO3 (once; later calls do nothing).
/// Note: FlexIO2 shares this clock root. Context: loop.
void power_up();
/// True once power_up() has run (registers are accessible). Context: any.
bool powered();

/// Configures port `port` (0..3): shifter port → STEP on FlexIO pin step_pin, shifter port + 4 →
/// DIR on dir_pin, both driven by timer `port`, which the frame clock triggers. Buffers zeroed.
/// Context: loop.
void configure_port(uint8_t port, uint8_t step_pin, uint8_t dir_pin);
/// Writes the next frame of a port; it goes out at the next tick. Context: frame or tick ISR.
void write_port(uint8_t port, uint32_t step_bits, uint32_t dir_bits);
/// Makes the preceding writes visible to FlexIO and waits longer than kMarkerDelayClocks, so a
/// tick_flag() read afterwards covers every tick that could have launched before the writes.
void settle_writes();

/// True if a tick happened since clear_tick_flag(). Context: any.
bool tick_flag();
/// True if the next tick is less than kCommitGuardClocks away (or has passed) since the last
/// clear_tick_flag(). Context: any.
bool guard_flag();
/// Clears the tick marker's and the commit guard's status flags (which also ends the tick
/// interrupt request). Context: any.
void clear_tick_flag();

/// Starts the frame clock with a period of period_us (first tick immediately) and enables the
/// tick interrupt. kBadArgument if the period cannot hold a 32 µs frame or overflows the timer
/// (half a period must also be longer than the commit guard).
/// Context: loop.
Status start_frame_clock(uint32_t period_us);
/// Stops the frame clock: no further ticks; a frame already being shifted completes. Context: any.
void stop_frame_clock();

}  // namespace stepdance::platform::teensy::flexio

#endif  // __IMXRT1062__
