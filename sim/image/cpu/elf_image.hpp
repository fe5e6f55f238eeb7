// A Teensy 4.x firmware ELF as the loader sees it: what to put where, where to start, the names.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/cpu/elf_symbols.hpp"

namespace stepdance::sim::image {

/// One PT_LOAD segment, placed by its physical (load) address: FlexSPI flash images link code
/// that runs from ITCM with a flash load address, and the boot copies it (startup's job).
struct ElfSegment {
  uint32_t physical_address = 0;
  uint32_t virtual_address = 0;
  uint32_t memory_bytes = 0;   ///< p_memsz (the rest past `bytes` is zero)
  std::vector<uint8_t> bytes;  ///< p_filesz bytes from the file
};

/// A 32-bit little-endian ARM executable. Context: the simulator's thread, once per board.
struct ElfImage {
  uint32_t entry = 0;  ///< e_entry (Thumb bit as linked)
  std::vector<ElfSegment> segments;
  ElfSymbols symbols;

  /// Reads `path`. On failure returns false with `error` saying why in one line (not a file,
  /// not ELF, not 32-bit ARM little-endian, not an executable, a segment outside the file, …).
  bool load(const std::string& path, std::string& error);
};

}  // namespace stepdance::sim::image
