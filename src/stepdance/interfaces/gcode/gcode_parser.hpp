// Turns one line of G-code text into a GcodeBlock, checking its syntax as Grbl does.
#pragma once

#include <stddef.h>

#include "stepdance/interfaces/gcode/gcode_block.hpp"
#include "stepdance/interfaces/gcode/grbl_error.hpp"

namespace stepdance::gcode {

/// Choices about which dialect the parser accepts.
struct ParserOptions {
  /// Accept 3D-printer files: M82/M83 set the E mode, and housekeeping codes (temperatures, fans,
  /// progress, messages: M73, M84, M104–M109, M140, M190, M106/M107, M115, M117, M201–M205,
  /// M220/M221, M862.x, M900) are accepted without action: the code and the words after it (its
  /// parameters; M117's and M862's are free text) are left out of the block, the words before it
  /// stay (`G1 X10 M106 S255` moves to X10). A G or M word among such parameters would be lost,
  /// so that line is error 20. Off: such M codes are error 20.
  bool accept_printer_codes = true;
};

/// Parses one line (without its line end; a trailing CR is tolerated). Whitespace, `( )` and `;`
/// comments, a leading `/` and a lone `%` are skipped; letters are case-insensitive. Checks
/// everything that needs no machine state: number syntax (magnitude below 10^12), known commands,
/// one command per modal group, no repeated value word, N/F/P/S/T/L not negative,
/// N ≤ 10,000,000, T ≤ 255. Numbers have no exponent: an E written against the number before it
/// (`X1e1`, `X1E1`) is read as one and the line refused as Grbl refuses it (error:20); an E word
/// (the extruder) needs a blank or a comment before it (`X1 E1`). On error, `out` is unspecified
/// and nothing else changes.
/// Context: loop (pure function).
GrblError parse_line(const char* text, size_t length, GcodeBlock& out, const ParserOptions& options = {});

/// Parses a whole text as one number in G-code syntax ([+|-]digits[.digits], blanks allowed,
/// magnitude below 10^12). False if anything else is there. Context: any (pure function).
bool parse_number(const char* text, size_t length, double& value);

}  // namespace stepdance::gcode
