// Where a loaded board library's machine code lies, for naming the sketch's frames in a backtrace.
#pragma once

#include <cstdint>

#include "board/loader/board_library.hpp"

namespace stepdance::sim {

/// Fills `load_base` and `code` for the library `handle` (from dlopen). ELF hosts read the
/// loaded segments (board_code_ranges_elf.cpp); a host whose code has no addresses in memory
/// (WebAssembly) leaves both empty, so no frame is named. Context: loop, once per load.
void find_board_code(void* handle, uintptr_t& load_base, CodeRanges& code);

}  // namespace stepdance::sim
