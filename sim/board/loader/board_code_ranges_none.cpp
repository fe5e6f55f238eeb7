// find_board_code where code has no address in memory (WebAssembly): no ranges, no frame named.
#include "board/loader/board_code_ranges.hpp"

namespace stepdance::sim {

void find_board_code(void*, uintptr_t&, CodeRanges&) {}

}  // namespace stepdance::sim
