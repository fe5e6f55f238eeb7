// The function and object names of a firmware ELF, for naming addresses in reports.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace stepdance::sim::image {

/// The symbols of one ELF (STT_FUNC, STT_OBJECT and named STT_NOTYPE), sorted by address.
/// Filled once by the loader; lookups are read-only. Context: the simulator's thread.
class ElfSymbols {
 public:
  struct Symbol {
    uint32_t address = 0;  ///< Thumb bit cleared for functions
    uint32_t size_bytes = 0;
    bool is_function = false;
    std::string name;  ///< as in the ELF (mangled C++ names stay mangled)
  };

  /// Adds one symbol (the loader's job). Call sort() after the last one.
  void add(Symbol symbol) { symbols_.push_back(std::move(symbol)); }
  void sort();
  void clear() { symbols_.clear(); }

  /// The function containing `address` (its [address, address + size) range, or the nearest
  /// function below it when sizes are 0), or null.
  const Symbol* function_at(uint32_t address) const;
  /// The address of the symbol `name` (exact, mangled) in `address`; false if absent.
  bool find(const std::string& name, uint32_t& address) const;
  /// "setup()+0x12": the demangled name of the function containing `address` and the offset,
  /// or "" if none.
  std::string describe(uint32_t address) const;
  /// The demangled name of the function containing `address`, or "".
  std::string function_name(uint32_t address) const;
  size_t size() const { return symbols_.size(); }

 private:
  std::vector<Symbol> symbols_;
};

/// `name` demangled if it is a mangled C++ name, else itself.
std::string demangle(const std::string& name);

}  // namespace stepdance::sim::image
