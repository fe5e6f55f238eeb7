// The Grbl link's settings commands (`$N=v`, `$RST=`) and the settings kept in the board's store.
#include "stepdance/interfaces/gcode/grbl_protocol.hpp"
#include "stepdance/interfaces/gcode/grbl_settings_store.hpp"

namespace stepdance::gcode {

namespace {

/// Reads a number as Grbl's read_float does: [+|-]digits[.digits], at least one digit, no
/// exponent. Returns the characters used (0: no number). Context: any.
size_t read_grbl_number(const char* text, size_t length, double& value) {
  size_t used = (length > 0 && (text[0] == '+' || text[0] == '-')) ? 1 : 0;
  const bool negative = used == 1 && text[0] == '-';
  double magnitude = 0.0;
  double scale = 1.0;
  bool point = false;
  int digits = 0;
  for (; used < length; ++used) {
    const char c = text[used];
    if (c == '.' && !point) {
      point = true;
    } else if (c >= '0' && c <= '9') {
      if (digits++ < 15) magnitude = magnitude * 10.0 + (c - '0');
      if (point && digits <= 15) scale *= 10.0;
      if (!point && digits > 15) magnitude *= 10.0;
    } else {
      break;
    }
  }
  value = (negative ? -magnitude : magnitude) / scale;
  return digits > 0 ? used : 0;
}

}  // namespace

// `$N=v` in Grbl 1.1h's order: a number (error:2), `=` (error:3), a value (error:2), nothing
// after it and N at most 255 (error:3); then the setting's own checks (GrblSettings::write).
GrblError GrblProtocol::execute_setting_write(const char* text, size_t length) {
  double number = 0.0;
  double value = 0.0;
  const size_t number_length = read_grbl_number(text, length, number);
  if (number_length == 0) return GrblError::kBadNumberFormat;
  if (number_length == length || text[number_length] != '=') return GrblError::kInvalidDollarStatement;
  const size_t value_start = number_length + 1;
  const size_t value_length = read_grbl_number(text + value_start, length - value_start, value);
  if (value_length == 0) return GrblError::kBadNumberFormat;
  if (value_start + value_length != length || number > 255.0) return GrblError::kInvalidDollarStatement;
  if (value < 0.0) return GrblError::kNegativeValue;
  if (number < 0.0) return GrblError::kInvalidDollarStatement;
  const uint32_t setting = static_cast<uint32_t>(number);  // Grbl truncates: `$1.5=` is `$1=`
  if (setting >= 100 && setting <= 102) {
    send_text("[MSG:steps/mm are set by the sketch's channels]");
    return GrblError::kInvalidDollarStatement;
  }
  const GrblError error = settings_.write(setting, value);
  if (error == GrblError::kOk) save_stored_settings();
  return error;
}

// $RST=$ restores the settings, $RST=# the coordinate data, $RST=* both; a reset follows as in Grbl.
GrblError GrblProtocol::execute_restore(const char* text, size_t length) {
  if (length != 1 || (text[0] != '$' && text[0] != '#' && text[0] != '*')) return GrblError::kInvalidDollarStatement;
  if (text[0] != '#') {
    settings_.restore_defaults();
    save_stored_settings();
  }
  if (text[0] != '$') interpreting_.interpreter().set_coordinate_data(CoordinateData{});
  send_text("[MSG:Restoring defaults]");
  reset_requested_ = true;  // as Grbl: a reset follows, so everything starts from the new values
  return GrblError::kOk;
}

// A store that cannot be read, or holds another version, falls back to the defaults and says so, rather
// than loading values of unknown meaning.
void GrblProtocol::load_stored_settings() {
  if (store_ == nullptr) return;
  uint8_t version = 0;
  switch (load_settings(*store_, settings_, version)) {
    case SettingsLoad::kLoaded:
    case SettingsLoad::kBlank:
    case SettingsLoad::kUnavailable: return;
    case SettingsLoad::kCorrupt:
      send_text("[MSG:Stored settings unreadable (bad checksum or data): defaults restored]");
      return;
    case SettingsLoad::kOtherVersion: {
      char storage[96];
      TextWriter line(storage, sizeof(storage));
      line.text("[MSG:Stored settings are version ").unsigned_number(version);
      line.text(", this firmware reads version ").unsigned_number(kSettingsStoreVersion);
      line.text(": defaults restored]");
      send_line(line);
      return;
    }
  }
}

// Every accepted $N=v is saved at once (as Grbl writes EEPROM); a board without a store still applies
// it until reset and says so.
void GrblProtocol::save_stored_settings() {
  if (store_ == nullptr) return;
  const Status saved = save_settings(*store_, settings_);
  if (saved == Status::kUnsupported) {
    send_text("[MSG:Setting applies until reset: this board has no settings store]");
  } else if (saved != Status::kOk) {
    send_text("[MSG:Setting applies until reset: the settings store refused the write]");
  }
}

}  // namespace stepdance::gcode
