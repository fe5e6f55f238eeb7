// Symbol lookups for reports.
#include "image/cpu/elf_symbols.hpp"

#include <cxxabi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace stepdance::sim::image {

std::string demangle(const std::string& name) {
  int status = 0;
  char* text = abi::__cxa_demangle(name.c_str(), nullptr, nullptr, &status);
  if (status != 0 || text == nullptr) return name;
  std::string result(text);
  std::free(text);
  return result;
}

void ElfSymbols::sort() {
  std::stable_sort(symbols_.begin(), symbols_.end(), [](const Symbol& a, const Symbol& b) {
    if (a.address != b.address) return a.address < b.address;
    return a.is_function && !b.is_function;
  });
}

const ElfSymbols::Symbol* ElfSymbols::function_at(uint32_t address) const {
  auto after = std::upper_bound(symbols_.begin(), symbols_.end(), address,
                                [](uint32_t a, const Symbol& s) { return a < s.address; });
  // The innermost function whose range holds the address; a sizeless one only if nearest.
  const Symbol* sizeless = nullptr;
  while (after != symbols_.begin()) {
    --after;
    if (!after->is_function) continue;
    if (after->size_bytes == 0) {
      if (sizeless == nullptr) sizeless = &*after;
      continue;
    }
    if (address - after->address < after->size_bytes) return &*after;
    if (address - after->address > (1u << 20)) break;  // nothing this far below can hold it
  }
  return sizeless;
}

bool ElfSymbols::find(const std::string& name, uint32_t& address) const {
  for (const Symbol& symbol : symbols_) {
    if (symbol.name == name) {
      address = symbol.address;
      return true;
    }
  }
  return false;
}

std::string ElfSymbols::function_name(uint32_t address) const {
  const Symbol* symbol = function_at(address);
  return symbol == nullptr ? std::string() : demangle(symbol->name);
}

std::string ElfSymbols::describe(uint32_t address) const {
  const Symbol* symbol = function_at(address);
  if (symbol == nullptr) return "";
  char offset[24];
  std::snprintf(offset, sizeof offset, "+0x%X", address - symbol->address);
  return demangle(symbol->name) + offset;
}

}  // namespace stepdance::sim::image
