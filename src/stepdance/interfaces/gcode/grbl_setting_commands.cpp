// The Grbl link's settings commands (`$N=v`, `$RST=`) and the settings kept in the board's store.
#include <string.h>

#include "stepdance/interfaces/gcode/grbl_protocol.hpp"
#include "stepdance/interfaces/gcode/grbl_settings_store.hpp"

namespace stepdance::gcode {

GrblError GrblProtocol::execute_setting_write(const char* text, size_t length) {
  const char* equals_sign = static_cast<const char*>(memchr(text, '=', length));
  if (equals_sign == nullptr) return GrblError::kInvalidDollarStatement;
  double number = 0.0;
  double value = 0.0;
  const size_t number_length = static_cast<size_t>(equals_sign - text);
  // A setting number is a whole number below 1000 (checked before any conversion: casting a
  // larger double to an integer would be undefined behaviour).
  if (!parse_number(text, number_length, number) || !(number >= 0.0 && number < 1000.0) ||
      number != static_cast<double>(static_cast<uint32_t>(number))) {
    return GrblError::kInvalidDollarStatement;
  }
  if (!parse_number(equals_sign + 1, length - number_length - 1, value)) return GrblError::kBadNumberFormat;
  const uint32_t setting = static_cast<uint32_t>(number);
  if (setting >= 100 && setting <= 102) {
    send_text("[MSG:steps/mm are set by the sketch's channels]");
    return GrblError::kInvalidDollarStatement;
  }
  const GrblError error = settings_.write(setting, value);
  if (error == GrblError::kOk) save_stored_settings();
  return error;
}

GrblError GrblProtocol::execute_restore(const char* text, size_t length) {
  if (length != 1 || (text[0] != '$' && text[0] != '#' && text[0] != '*')) return GrblError::kInvalidDollarStatement;
  if (text[0] != '#') {
    settings_.restore_defaults();
    save_stored_settings();
  }
  if (text[0] != '$') interpreter_.set_coordinate_data(CoordinateData{});
  send_text("[MSG:Restoring defaults]");
  reset_requested_ = true;  // as Grbl: a reset follows, so everything starts from the new values
  return GrblError::kOk;
}

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
