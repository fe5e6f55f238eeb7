// One set of physical code pages for every board that runs the same board library.
#pragma once

#include <cstddef>
#include <string>

namespace stepdance::sim {

/// `handle` (from dlopen) is a board's private copy of the library file `original_path`, byte for
/// byte. Maps each of the copy's read-only segments (its machine code and constants) again from
/// `original_path`, at the same address and with the same protection, so that the boards' copies
/// all run from the page cache's one copy of the original file: the processor's caches, which
/// are indexed by physical address, then hold the code once rather than once per board. Only
/// pages whose bytes equal the file's are remapped; writable segments (each board's globals,
/// its relocated tables) stay the board's own. Returns the bytes remapped (0 where the host has
/// no such mappings, as in WebAssembly, or on any failure, which leaves the copy as it was).
/// Context: loop, once per load, before any of the library's code runs besides its constructors.
size_t share_read_only_pages(void* handle, const std::string& original_path);

}  // namespace stepdance::sim
