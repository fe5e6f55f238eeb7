// Selects the board from the sketch's module macro and defines the original's pin names.
// This is the one place the public API reads a preprocessor macro: sketches choose their
// board with `#define module_driver` or `#define module_basic` before including stepdance.hpp
// (the original library's macros), or name any board table with `#define STEPDANCE_BOARD <table>`
// after including the header that defines it (a board the original never had, or a test's).
#pragma once

#include "stepdance/boards/board.hpp"

namespace stepdance::sketch {

#if defined(STEPDANCE_BOARD)
constexpr const BoardDefinition& kBoard = STEPDANCE_BOARD;
#elif defined(module_basic)
constexpr const BoardDefinition& kBoard = kBasicModuleV1;
#else
constexpr const BoardDefinition& kBoard = kDriverModuleV1;
#endif

/// Runs once, before setup(), in whichever translation unit includes this header first.
inline const bool kBoardSelected = (select_board(kBoard), true);

}  // namespace stepdance::sketch

/// Marks an absent pin, as in the original's configuration header.
constexpr uint8_t TEENSY_PIN_NULL = stepdance::kNoPin;

constexpr uint8_t IO_A1 = stepdance::sketch::kBoard.io_a[0];
constexpr uint8_t IO_A2 = stepdance::sketch::kBoard.io_a[1];
constexpr uint8_t IO_A3 = stepdance::sketch::kBoard.io_a[2];
constexpr uint8_t IO_A4 = stepdance::sketch::kBoard.io_a[3];
constexpr uint8_t IO_D1 = stepdance::sketch::kBoard.io_d[0];
constexpr uint8_t IO_D2 = stepdance::sketch::kBoard.io_d[1];

constexpr uint8_t OUTPUT_A_ENABLE = stepdance::sketch::kBoard.output_ports[0].enable;
constexpr uint8_t OUTPUT_B_ENABLE = stepdance::sketch::kBoard.output_ports[1].enable;
constexpr uint8_t OUTPUT_C_ENABLE = stepdance::sketch::kBoard.output_ports[2].enable;
constexpr uint8_t OUTPUT_D_ENABLE = stepdance::sketch::kBoard.output_ports[3].enable;
constexpr uint8_t OUTPUT_A_VREF = stepdance::sketch::kBoard.output_ports[0].vref;
constexpr uint8_t OUTPUT_B_VREF = stepdance::sketch::kBoard.output_ports[1].vref;
constexpr uint8_t OUTPUT_C_VREF = stepdance::sketch::kBoard.output_ports[2].vref;
constexpr uint8_t OUTPUT_D_VREF = stepdance::sketch::kBoard.output_ports[3].vref;
constexpr uint8_t LIMIT_A = stepdance::sketch::kBoard.output_ports[0].limit;
constexpr uint8_t LIMIT_B = stepdance::sketch::kBoard.output_ports[1].limit;
constexpr uint8_t LIMIT_C = stepdance::sketch::kBoard.output_ports[2].limit;
constexpr uint8_t LIMIT_D = stepdance::sketch::kBoard.output_ports[3].limit;
