// G-code line syntax: words, numbers, comments and the modal-group table.
#include "stepdance/interfaces/gcode/gcode_parser.hpp"

#include <math.h>

namespace stepdance::gcode {
namespace {

/// Reads significant characters of a line, skipping blanks and `( )` comments; `;` ends it.
class Cursor {
 public:
  Cursor(const char* text, size_t length) : text_(text), length_(length) {}

  /// The next significant character, upper-cased, or 0 at the end of the line.
  char peek() {
    skip_insignificant();
    if (pos_ >= length_) return 0;
    const char c = text_[pos_];
    return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c;
  }
  void advance() { ++pos_; }
  /// True when the next character directly follows a digit or a point, nothing between them.
  bool follows_number() const {
    if (pos_ == 0 || pos_ >= length_) return false;
    const char c = text_[pos_ - 1];
    return (c >= '0' && c <= '9') || c == '.';
  }

 private:
  void skip_insignificant() {
    while (pos_ < length_) {
      const char c = text_[pos_];
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
        ++pos_;
      } else if (c == '(') {
        while (pos_ < length_ && text_[pos_] != ')') ++pos_;
        if (pos_ < length_) ++pos_;
      } else if (c == ';') {
        pos_ = length_;
      } else {
        return;
      }
    }
  }

  const char* text_;
  size_t length_;
  size_t pos_ = 0;
};

/// Numbers at or beyond this magnitude are refused: no machine travels 10^12 mm, and keeping
/// values far from the double range keeps every later product (inches, offsets) finite.
constexpr double kLargestNumber = 1e12;

bool is_digit(char c) { return c >= '0' && c <= '9'; }

/// Reads [+|-]digits[.digits] (at least one digit). False if none or not finite.
// Grbl's read_float accepts exactly this (sign, digits, one point); exponents are not G-code.
bool read_number(Cursor& cursor, double& value) {
  bool negative = false;
  char c = cursor.peek();
  if (c == '+' || c == '-') {
    negative = (c == '-');
    cursor.advance();
  }
  double magnitude = 0.0;
  double scale = 1.0;
  bool after_point = false;
  int digits = 0;
  for (c = cursor.peek(); is_digit(c) || (c == '.' && !after_point); c = cursor.peek()) {
    cursor.advance();
    if (c == '.') {
      after_point = true;
      continue;
    }
    magnitude = magnitude * 10.0 + (c - '0');
    if (after_point) scale *= 10.0;
    ++digits;
  }
  if (digits == 0) return false;
  value = (negative ? -magnitude : magnitude) / scale;
  return fabs(value) < kLargestNumber;
}

struct CommandEntry {
  CommandCode code;
  uint8_t group;
};

// The G codes Grbl 1.1 accepts (×10, so G28.1 = 281) with their NIST modal groups; two codes of one
// group on a line are error:21.
constexpr CommandEntry kGCommands[] = {
    {0, uint8_t(GGroup::kMotion)},        {10, uint8_t(GGroup::kMotion)},       {20, uint8_t(GGroup::kMotion)},
    {30, uint8_t(GGroup::kMotion)},       {40, uint8_t(GGroup::kNonModal)},     {100, uint8_t(GGroup::kNonModal)},
    {170, uint8_t(GGroup::kPlane)},       {180, uint8_t(GGroup::kPlane)},       {190, uint8_t(GGroup::kPlane)},
    {200, uint8_t(GGroup::kUnits)},       {210, uint8_t(GGroup::kUnits)},       {280, uint8_t(GGroup::kNonModal)},
    {281, uint8_t(GGroup::kNonModal)},    {300, uint8_t(GGroup::kNonModal)},    {301, uint8_t(GGroup::kNonModal)},
    {400, uint8_t(GGroup::kCutterComp)},  {431, uint8_t(GGroup::kToolLength)},  {490, uint8_t(GGroup::kToolLength)},
    {530, uint8_t(GGroup::kNonModal)},    {540, uint8_t(GGroup::kCoordSystem)}, {550, uint8_t(GGroup::kCoordSystem)},
    {560, uint8_t(GGroup::kCoordSystem)}, {570, uint8_t(GGroup::kCoordSystem)}, {580, uint8_t(GGroup::kCoordSystem)},
    {590, uint8_t(GGroup::kCoordSystem)}, {610, uint8_t(GGroup::kPathControl)}, {800, uint8_t(GGroup::kMotion)},
    {900, uint8_t(GGroup::kDistance)},    {910, uint8_t(GGroup::kDistance)},    {911, uint8_t(GGroup::kArcDistance)},
    {920, uint8_t(GGroup::kNonModal)},    {921, uint8_t(GGroup::kNonModal)},    {930, uint8_t(GGroup::kFeedMode)},
    {940, uint8_t(GGroup::kFeedMode)},
};

constexpr CommandEntry kMCommands[] = {
    {0, uint8_t(MGroup::kStopping)},   {10, uint8_t(MGroup::kStopping)}, {20, uint8_t(MGroup::kStopping)},
    {300, uint8_t(MGroup::kStopping)}, {30, uint8_t(MGroup::kSpindle)},  {40, uint8_t(MGroup::kSpindle)},
    {50, uint8_t(MGroup::kSpindle)},   {70, uint8_t(MGroup::kCoolant)},  {80, uint8_t(MGroup::kCoolant)},
    {90, uint8_t(MGroup::kCoolant)},
};

/// Printer housekeeping M numbers accepted without action when printer codes are on.
// When printer codes are on, one of these M codes and the words after it (its parameters) are left out
// of the block (the motion planner has no heaters or fans); the words before it stay; see docs/gcode.md.
constexpr uint16_t kPrinterHousekeeping[] = {73,  84,  104, 105, 106, 107, 109, 115, 117, 140,
                                             190, 201, 202, 203, 204, 205, 220, 221, 862, 900};
/// Housekeeping codes whose parameters are free text: M117's message, M862's quoted model names.
constexpr uint16_t kPrinterTextCodes[] = {117, 862};

template <size_t N>
const CommandEntry* find_command(const CommandEntry (&table)[N], CommandCode code) {
  for (const CommandEntry& entry : table) {
    if (entry.code == code) return &entry;
  }
  return nullptr;
}

/// Why an unknown G/M code is refused: a fraction on a known integer command, or unknown.
template <size_t N>
GrblError unknown_command(const CommandEntry (&table)[N], CommandCode code) {
  if (code % 10 != 0 && find_command(table, static_cast<CommandCode>(code - code % 10)) != nullptr) {
    return GrblError::kCommandNeedsInteger;
  }
  return GrblError::kUnsupportedCommand;
}

template <size_t N>
bool is_listed(const uint16_t (&numbers)[N], double value) {
  for (uint16_t number : numbers) {
    if (floor(value) == number) return true;
  }
  return false;
}

// What follows a housekeeping M code is its parameters (M106 S255, M204 P500 T1000), not the line's
// words, so the fan's S never becomes the spindle speed. Such parameters are never G or M words: one
// there is a command the line would silently lose, so the line is refused (error:20), nothing run.
GrblError skip_housekeeping_parameters(Cursor& cursor, double code) {
  if (is_listed(kPrinterTextCodes, code)) return GrblError::kOk;  // the rest is text
  for (char letter = cursor.peek(); letter != 0; letter = cursor.peek()) {
    if (letter == 'G' || letter == 'M') return GrblError::kUnsupportedCommand;
    cursor.advance();
  }
  return GrblError::kOk;
}

// G59.1–G59.3 exist in LinuxCNC but not in Grbl: error:29, as Grbl answers.
GrblError add_g(GcodeBlock& block, CommandCode code) {
  if (code >= 591 && code <= 593) return GrblError::kUnsupportedCoordinateSystem;
  const CommandEntry* entry = find_command(kGCommands, code);
  if (entry == nullptr) return unknown_command(kGCommands, code);
  const uint16_t bit = static_cast<uint16_t>(1u << entry->group);
  if (block.g_groups_present & bit) return GrblError::kModalGroupViolation;
  block.g_groups_present |= bit;
  block.g[entry->group] = code;
  return GrblError::kOk;
}

GrblError add_m(GcodeBlock& block, CommandCode code, const ParserOptions& options) {
  const CommandEntry* entry = find_command(kMCommands, code);
  CommandEntry extruder{code, uint8_t(MGroup::kExtruder)};
  if (entry == nullptr && options.accept_printer_codes && (code == 820 || code == 830)) entry = &extruder;
  if (entry == nullptr) return unknown_command(kMCommands, code);
  const uint8_t bit = static_cast<uint8_t>(1u << entry->group);
  if (block.m_groups_present & bit) return GrblError::kModalGroupViolation;
  block.m_groups_present |= bit;
  block.m[entry->group] = code;
  return GrblError::kOk;
}

bool is_value_letter(char letter) {
  switch (letter) {
    case 'E':
    case 'F':
    case 'I':
    case 'J':
    case 'K':
    case 'L':
    case 'N':
    case 'P':
    case 'R':
    case 'S':
    case 'T':
    case 'X':
    case 'Y':
    case 'Z': return true;
    default: return false;
  }
}

// Grbl's value checks: F, N, P, S, T and L must not be negative (error:4), N at most 10 000 000
// (error:27), T at most 255 (error:38).
GrblError check_value(char letter, double value) {
  const bool must_be_positive =
      letter == 'F' || letter == 'N' || letter == 'P' || letter == 'S' || letter == 'T' || letter == 'L';
  if (must_be_positive && value < 0.0) return GrblError::kNegativeValue;
  if (letter == 'N' && value > 10000000.0) return GrblError::kInvalidLineNumber;  // Grbl's MAX_LINE_NUMBER
  if (letter == 'T' && value > 255.0) return GrblError::kToolNumberTooLarge;
  return GrblError::kOk;
}

// Each value letter once per line (error:25); unknown letters are error:20.
GrblError add_value(GcodeBlock& block, char letter, double value) {
  if (!is_value_letter(letter)) return GrblError::kUnsupportedCommand;
  const uint32_t bit = 1u << word_index(letter);
  if (block.words_present & bit) return GrblError::kRepeatedWord;
  const GrblError range = check_value(letter, value);
  if (range != GrblError::kOk) return range;
  block.words_present |= bit;
  block.values[word_index(letter)] = value;
  return GrblError::kOk;
}

/// A G/M number as a CommandCode (×10); false if it has more than one decimal or is out of range.
// G/M numbers with one decimal at most (G38.2, G28.1): anything finer is not a command Grbl knows.
bool to_command_code(double value, CommandCode& code) {
  if (value < 0.0 || value > 6000.0) return false;
  const double tenths = value * 10.0;
  const double rounded = floor(tenths + 0.5);
  if (fabs(tenths - rounded) > 1e-6) return false;
  code = static_cast<CommandCode>(rounded);
  return true;
}

}  // namespace

bool parse_number(const char* text, size_t length, double& value) {
  Cursor cursor(text, length);
  return read_number(cursor, value) && cursor.peek() == 0;
}

// Loop context. A line holding only "%" (a program delimiter) is accepted, as senders send it.
GrblError parse_line(const char* text, size_t length, GcodeBlock& out, const ParserOptions& options) {
  out = GcodeBlock{};
  Cursor cursor(text, length);
  if (cursor.peek() == '%') {
    cursor.advance();
    return cursor.peek() == 0 ? GrblError::kOk : GrblError::kExpectedCommandLetter;
  }
  for (char letter = cursor.peek(); letter != 0; letter = cursor.peek()) {
    // An E written against the number before it is that number's exponent (`X1e1`): Grbl reads
    // no exponents, so it refuses the line (error:20 for the E, error:2 if no number follows).
    const bool exponent = letter == 'E' && cursor.follows_number();
    cursor.advance();
    if (letter == '/') continue;  // block delete is not supported: the line runs
    if (letter < 'A' || letter > 'Z') return GrblError::kExpectedCommandLetter;
    double value = 0.0;
    if (!read_number(cursor, value)) return GrblError::kBadNumberFormat;
    if (exponent) return GrblError::kUnsupportedCommand;
    GrblError error = GrblError::kOk;
    if (letter == 'M' && options.accept_printer_codes && is_listed(kPrinterHousekeeping, value)) {
      out.printer_housekeeping = true;
      return skip_housekeeping_parameters(cursor, value);
    }
    if (letter == 'G' || letter == 'M') {
      CommandCode code = 0;
      if (!to_command_code(value, code)) return GrblError::kUnsupportedCommand;
      error = (letter == 'G') ? add_g(out, code) : add_m(out, code, options);
    } else {
      error = add_value(out, letter, value);
    }
    if (error != GrblError::kOk) return error;
  }
  return GrblError::kOk;
}

}  // namespace stepdance::gcode
