// elf_symbol.h: looks up a symbol's address in an ELF file's symbol table (libelf).
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace servo_sim {

// Returns the st_value of the first symbol called name in elf_path, or nothing if the file cannot
// be read or has no such symbol. For AVR data symbols the value carries the 0x800000 data-space tag.
std::optional<std::uint32_t> elf_symbol_address(const std::string& elf_path, const std::string& name);

}  // namespace servo_sim
