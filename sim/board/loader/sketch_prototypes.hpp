// Finds the functions an .ino defines at file scope, as the Arduino IDE does to write their prototypes.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace stepdance::sim {

/// One function defined at file scope of a sketch file.
struct SketchFunction {
  std::string name;
  /// The declaration to insert before first use: the definition's head (template header,
  /// storage class, return type, name, parameters with their default arguments, trailing
  /// noexcept / -> type), comments dropped, followed by ';'.
  std::string prototype;
  /// 1-based line of the function's name in the scanned text.
  std::size_t line = 0;
  /// The conditional directives the definition sits in, outermost first. Each entry is the
  /// opening #if/#ifdef/#ifndef followed by the #elif/#else lines met before the definition's
  /// branch; replaying them (then one #endif each) puts the prototype under the same condition.
  std::vector<std::vector<std::string>> conditions;
  /// Byte ranges [first, second) of the definition's default arguments ("= value"), which the
  /// sketch assembly blanks out: a default may be given once, and the prototype now gives it.
  std::vector<std::pair<std::size_t, std::size_t>> default_arguments;
};

/// What scanning one sketch file found.
struct SketchScan {
  std::vector<SketchFunction> functions;
  /// Byte offset before which prototypes go: the start of the line where the first function
  /// definition begins (or of the outermost conditional around it). When something other than
  /// blanks precedes the definition on that line (the end of a comment, another declaration),
  /// the definition's first character instead. Meaningless when `functions` is empty.
  std::size_t insertion_offset = 0;
  /// 1-based line number of insertion_offset.
  std::size_t insertion_line = 1;
  /// 0-based column of insertion_offset (0 at a line start); the assembly pads the resumed line
  /// with this many spaces so the compiler's columns stay right.
  std::size_t insertion_column = 0;
};

/// Scans C++ source text (one .ino) for function definitions at file scope: not members
/// (`A::f`), operators, functions inside namespaces, classes or extern "C" blocks, or macro
/// invocations with a body (`ISR(x) {`, which has no return type). Understands comments, string,
/// character and raw string literals, digit separators and line-continued directives.
/// Known limits, shared with the IDE: prototypes go before the first definition, so a type
/// declared after it cannot appear in a prototype; a default argument whose value holds a
/// top-level comma inside template brackets (`= std::pair<int, int>()`) is cut at the comma.
/// Context: any thread (pure function).
SketchScan scan_sketch_functions(std::string_view text);

}  // namespace stepdance::sim
