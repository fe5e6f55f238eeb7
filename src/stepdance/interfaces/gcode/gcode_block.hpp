// One parsed line of G-code: its G/M commands by modal group and its value words.
#pragma once

#include <stdint.h>

namespace stepdance::gcode {

/// Modal groups of G commands, as the RS274/NGC standard and Grbl define them.
enum class GGroup : uint8_t {
  kNonModal = 0,  ///< G4, G10, G28, G28.1, G30, G30.1, G53, G92, G92.1
  kMotion,        ///< G0, G1, G2, G3, G80
  kPlane,         ///< G17, G18, G19
  kDistance,      ///< G90, G91
  kArcDistance,   ///< G91.1
  kFeedMode,      ///< G93, G94
  kUnits,         ///< G20, G21
  kCutterComp,    ///< G40
  kToolLength,    ///< G49
  kCoordSystem,   ///< G54 .. G59
  kPathControl,   ///< G61
  kCount,
};

/// Modal groups of M commands.
enum class MGroup : uint8_t {
  kStopping = 0,  ///< M0, M1, M2, M30
  kSpindle,       ///< M3, M4, M5
  kCoolant,       ///< M7, M8, M9
  kExtruder,      ///< M82, M83 (3D-printer files: absolute / relative E)
  kCount,
};

/// A G or M number times ten, so G38.2 is 382 and G1 is 10.
using CommandCode = uint16_t;

/// Index of a value word letter in GcodeBlock::values ('A' → 0 ... 'Z' → 25).
constexpr uint8_t word_index(char upper_letter) { return static_cast<uint8_t>(upper_letter - 'A'); }

/// A line after parsing: syntax checked, nothing executed yet.
struct GcodeBlock {
  CommandCode g[static_cast<int>(GGroup::kCount)] = {};
  CommandCode m[static_cast<int>(MGroup::kCount)] = {};
  uint16_t g_groups_present = 0;  ///< bit per GGroup
  uint8_t m_groups_present = 0;   ///< bit per MGroup
  uint32_t words_present = 0;     ///< bit per letter of value words (F, I, J, K, L, N, P, R, S, T, X, Y, Z, E)
  double values[26] = {};         ///< value of each present word, as written (units not applied)
  /// The line held a printer housekeeping M code (ParserOptions::accept_printer_codes): that code
  /// and the words after it (its parameters) are not in the block; the words before it are.
  bool printer_housekeeping = false;

  bool has_g(GGroup group) const { return (g_groups_present >> static_cast<int>(group)) & 1u; }
  bool has_m(MGroup group) const { return (m_groups_present >> static_cast<int>(group)) & 1u; }
  CommandCode g_code(GGroup group) const { return g[static_cast<int>(group)]; }
  CommandCode m_code(MGroup group) const { return m[static_cast<int>(group)]; }
  bool has_word(char upper_letter) const { return (words_present >> word_index(upper_letter)) & 1u; }
  double word(char upper_letter) const { return values[word_index(upper_letter)]; }
};

}  // namespace stepdance::gcode
