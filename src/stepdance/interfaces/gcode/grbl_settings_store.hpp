// The Grbl settings the host wrote, kept in the board's non-volatile store across resets.
#pragma once

#include <stddef.h>
#include <stdint.h>

#include "stepdance/core/nonvolatile_store.hpp"
#include "stepdance/interfaces/gcode/grbl_settings.hpp"

namespace stepdance::gcode {

/// Layout at offset 0 of the store (all numbers little-endian):
///   "SDGS" magic, version (1 byte), entry count (1 byte),
///   entries of 9 bytes: setting number (1 byte), value (IEEE-754 double, 8 bytes),
///   CRC-16/CCITT-FALSE (2 bytes) of everything before it.
/// Only settings the host wrote are stored; the others keep Grbl's or the sketch's default.
constexpr uint8_t kSettingsStoreVersion = 1;
constexpr size_t kSettingsStoreMaxBytes = 4 + 2 + GrblSettings::kCount * 9 + 2;

/// What load_settings() found.
enum class SettingsLoad : uint8_t {
  kLoaded,        ///< a valid store: its settings applied
  kBlank,         ///< erased or never written: defaults, nothing to say
  kCorrupt,       ///< wrong magic, bad checksum or an impossible entry: defaults
  kOtherVersion,  ///< written by another firmware version: defaults
  kUnavailable,   ///< no store on this board (or too small): defaults, nothing persists
};

/// Applies the stored settings (all or none) to `settings`; `found_version` receives the
/// store's version byte. Context: loop.
SettingsLoad load_settings(NonvolatileStore& store, GrblSettings& settings, uint8_t& found_version);
/// Writes the host-set settings. kUnsupported if the store is too small. Context: loop, idle only
/// (a flash write may hold interrupts off).
Status save_settings(NonvolatileStore& store, const GrblSettings& settings);
/// CRC-16/CCITT-FALSE (polynomial 0x1021, initial 0xFFFF, no reflection). Context: any.
uint16_t crc16_ccitt(const uint8_t* data, size_t length);

}  // namespace stepdance::gcode
