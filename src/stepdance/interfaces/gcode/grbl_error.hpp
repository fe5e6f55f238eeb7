// Grbl 1.1 error numbers, the contract G-code senders read from `error:N` replies.
#pragma once

#include <stdint.h>

namespace stepdance::gcode {

/// Result of parsing or executing one line. The numbers are Grbl 1.1's, so senders that show
/// Grbl's own error table explain our replies correctly. kOk (0) means the line was accepted.
enum class GrblError : uint8_t {
  kOk = 0,
  kExpectedCommandLetter = 1,         ///< a word without a letter, or a character that is not one
  kBadNumberFormat = 2,               ///< a letter without a number, or a malformed number
  kInvalidDollarStatement = 3,        ///< a `$` system command we do not know
  kNegativeValue = 4,                 ///< F, N, P, S, T or L given a negative value
  kHomingDisabled = 5,                ///< `$H` while `$22` is off or the sketch has no homing
  kStepPulseTooShort = 6,             ///< `$0` below Grbl's minimum of 3 µs
  kSettingReadFail = 7,               ///< stored settings could not be read (defaults restored)
  kNotIdle = 8,                       ///< `$` command that needs the machine idle
  kLocked = 9,                        ///< G-code refused while in alarm or jogging
  kSoftLimitNeedsHoming = 10,         ///< soft limits enabled without homing
  kLineOverflow = 11,                 ///< line longer than the line buffer
  kTravelExceeded = 15,               ///< jog target outside the machine's travel
  kInvalidJogCommand = 16,            ///< `$J=` line with a forbidden word or without axis words
  kUnsupportedCommand = 20,           ///< G or M code (or word letter) we do not support
  kModalGroupViolation = 21,          ///< two words of one modal group in one line
  kUndefinedFeedRate = 22,            ///< feed motion without a feed rate
  kCommandNeedsInteger = 23,          ///< a G or M number with a fraction where none is defined
  kAxisCommandConflict = 24,          ///< two commands in one line both want the axis words
  kRepeatedWord = 25,                 ///< the same value word twice in one line
  kNoAxisWords = 26,                  ///< a command that needs axis words got none
  kInvalidLineNumber = 27,            ///< N outside 0..10,000,000
  kValueWordMissing = 28,             ///< a command's required value word (P, L, ...) is absent
  kUnsupportedCoordinateSystem = 29,  ///< G59.1, G59.2, G59.3
  kG53NeedsG0OrG1 = 30,               ///< G53 with a motion mode other than G0/G1
  kAxisWordsUnused = 31,              ///< axis words in a line with no command that uses them
  kNoInPlaneAxisWords = 32,           ///< G2/G3 without an end point in the selected plane
  kInvalidTarget = 33,                ///< arc end point not on the arc, or equal to the start (R form)
  kArcRadiusError = 34,               ///< R form: the radius cannot reach the end point
  kNoInPlaneOffsetWords = 35,         ///< G2/G3 IJK form without an offset in the selected plane
  kUnusedValueWords = 36,             ///< value words that no command in the line used
  kG43DynamicAxisError = 37,          ///< G43.1 without exactly one Z word
  kToolNumberTooLarge = 38,           ///< T beyond 255
};

/// Grbl's number for the error, as sent in `error:N`. Context: any.
inline uint8_t grbl_number(GrblError error) { return static_cast<uint8_t>(error); }

/// A one-line explanation in our words (never null), for logs and `[MSG:]` lines. Context: any.
const char* describe(GrblError error);

}  // namespace stepdance::gcode
