// Short explanations of the Grbl error numbers.
#include "stepdance/interfaces/gcode/grbl_error.hpp"

namespace stepdance::gcode {

// Short texts for logs and the simulator (Grbl itself sends only "error:N"); the numbers are Grbl
// 1.1's, listed in grbl_error.hpp.
const char* describe(GrblError error) {
  switch (error) {
    case GrblError::kOk: return "accepted";
    case GrblError::kExpectedCommandLetter: return "expected a word letter";
    case GrblError::kBadNumberFormat: return "missing or malformed number";
    case GrblError::kInvalidDollarStatement: return "unknown $ command";
    case GrblError::kNegativeValue: return "value must not be negative";
    case GrblError::kHomingDisabled: return "homing is not configured";
    case GrblError::kStepPulseTooShort: return "step pulse must be at least 3 microseconds";
    case GrblError::kSettingReadFail: return "stored settings unreadable, defaults restored";
    case GrblError::kNotIdle: return "command needs the machine idle";
    case GrblError::kLocked: return "locked: clear the alarm first ($X)";
    case GrblError::kSoftLimitNeedsHoming: return "soft limits need homing";
    case GrblError::kLineOverflow: return "line too long";
    case GrblError::kTravelExceeded: return "jog target outside machine travel";
    case GrblError::kInvalidJogCommand: return "invalid jog command";
    case GrblError::kUnsupportedCommand: return "unsupported command or word";
    case GrblError::kModalGroupViolation: return "two commands of one modal group";
    case GrblError::kUndefinedFeedRate: return "feed rate not set";
    case GrblError::kCommandNeedsInteger: return "command number must be an integer";
    case GrblError::kAxisCommandConflict: return "two commands want the axis words";
    case GrblError::kRepeatedWord: return "word repeated in one line";
    case GrblError::kNoAxisWords: return "command needs axis words";
    case GrblError::kInvalidLineNumber: return "line number out of range";
    case GrblError::kValueWordMissing: return "required value word missing";
    case GrblError::kUnsupportedCoordinateSystem: return "coordinate system not supported";
    case GrblError::kG53NeedsG0OrG1: return "G53 works only with G0 or G1";
    case GrblError::kAxisWordsUnused: return "axis words without a command using them";
    case GrblError::kNoInPlaneAxisWords: return "arc needs an end point in the plane";
    case GrblError::kInvalidTarget: return "arc end point invalid";
    case GrblError::kArcRadiusError: return "arc radius cannot reach the end point";
    case GrblError::kNoInPlaneOffsetWords: return "arc needs a centre offset in the plane";
    case GrblError::kUnusedValueWords: return "value words not used by any command";
    case GrblError::kG43DynamicAxisError: return "G43.1 needs a Z word and no other axis";
    case GrblError::kToolNumberTooLarge: return "tool number above 255";
  }
  return "unknown error";
}

}  // namespace stepdance::gcode
