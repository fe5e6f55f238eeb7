// A test-only board, "Test Module": a table defined in the test tree alone, to show that a board
// is its table plus its registration (ScopedKind<BoardRegistry> in a test, a line of
// stepdance::kBoards for a built-in one) and nothing else. Its pins are deliberately unlike both
// real modules'.
#pragma once

#include "stepdance/boards/board_checks.hpp"
#include "stepdance/boards/board_definition.hpp"

namespace stepdance::test {

/// On a Teensy 4.0: two output ports with driver sockets, one input port, ENC1 only, A1–A2,
/// D1 and QWIIC0.
inline constexpr BoardDefinition kTestModule = {
    "Test Module v0",
    "test",
    "STEPDANCE_BOARD stepdance::test::kTestModule",
    &kTeensy40,
    &kTeensy40,  // the 4.0 only
    2,
    {{23, 22, 30, 24, 31}, {21, 20, 32, 25, 33}, {}, {}},
    1,
    {{4, 6}, {}, {}, {}},
    {{0, 1}, {kNoPin, kNoPin}},
    {26, 27, kNoPin, kNoPin},
    {28, kNoPin},
    true,
    {{18, 19}, {kNoPin, kNoPin}},
};
static_assert(board_is_valid(kTestModule), "the test board's table must fit its Teensy 4.0");

}  // namespace stepdance::test
