// Inside a board's shared object: what the simulator HAL backend keeps besides the host table.
#pragma once

#include <stdint.h>

#include "board/abi/board_abi.h"

namespace stepdance::sim_runtime {

/// The simulator's model of a frame's CPU cost: Cortex-M7 cycles per block run, the mean of the
/// instruction counts of the Step-A-Sketch, Harmonograph and ClayTexturizer graphs under QEMU
/// (1,436 / 9, 1,899 / 13 and 2,522 / 16 blocks: 146 to 160) at one cycle per instruction.
constexpr uint32_t kModelCyclesPerBlock = 155;

/// Runs the frame ISR if the frame timer was started (the host calls this at each frame tick).
void run_frame_isr();
/// Runs the kilohertz ISR if that timer was started.
void run_khz_isr();
/// Hands a captured pulse to the sink registered for `port` (ignored if none).
void deliver_captured_pulse(uint8_t port, const StepdanceCapturedPulseV1& pulse);

}  // namespace stepdance::sim_runtime
