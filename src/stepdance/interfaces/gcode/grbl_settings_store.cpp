// Settings store: serialise the host-set Grbl settings with a magic, a version and a checksum.
#include "stepdance/interfaces/gcode/grbl_settings_store.hpp"

#include <string.h>

namespace stepdance::gcode {
namespace {

constexpr uint8_t kMagic[4] = {'S', 'D', 'G', 'S'};
constexpr size_t kHeaderBytes = 6;
constexpr size_t kEntryBytes = 9;
constexpr size_t kCrcBytes = 2;

void put_double(uint8_t* out, double value) {
  uint64_t bits = 0;
  memcpy(&bits, &value, sizeof(bits));
  for (int i = 0; i < 8; ++i) out[i] = static_cast<uint8_t>(bits >> (8 * i));
}

double get_double(const uint8_t* in) {
  uint64_t bits = 0;
  for (int i = 0; i < 8; ++i) bits |= static_cast<uint64_t>(in[i]) << (8 * i);
  double value = 0.0;
  memcpy(&value, &bits, sizeof(value));
  return value;
}

bool all_equal(const uint8_t* data, size_t length, uint8_t byte) {
  for (size_t i = 0; i < length; ++i) {
    if (data[i] != byte) return false;
  }
  return true;
}

}  // namespace

// CRC-16/CCITT-FALSE (polynomial 0x1021, initial 0xFFFF, no reflection): catches a half-written or
// worn EEPROM image.
uint16_t crc16_ccitt(const uint8_t* data, size_t length) {
  uint16_t crc = 0xFFFF;
  for (size_t i = 0; i < length; ++i) {
    crc = static_cast<uint16_t>(crc ^ (static_cast<uint16_t>(data[i]) << 8));
    for (int bit = 0; bit < 8; ++bit) {
      crc = (crc & 0x8000u) != 0 ? static_cast<uint16_t>((crc << 1) ^ 0x1021u) : static_cast<uint16_t>(crc << 1);
    }
  }
  return crc;
}

// Image: "SDGS", version, count, then count × (setting number, IEEE-754 double little-endian), then
// the CRC. Erased (all 0xFF) or zeroed storage is blank, not corrupt. Only host-set settings are
// stored, so defaults changed in a new firmware still apply to settings the host never wrote.
SettingsLoad load_settings(NonvolatileStore& store, GrblSettings& settings, uint8_t& found_version) {
  found_version = 0;
  if (store.size_bytes() < kSettingsStoreMaxBytes) return SettingsLoad::kUnavailable;
  uint8_t image[kSettingsStoreMaxBytes];
  if (store.read(0, image, kHeaderBytes) != Status::kOk) return SettingsLoad::kUnavailable;
  if (all_equal(image, kHeaderBytes, 0xFF) || all_equal(image, kHeaderBytes, 0x00)) return SettingsLoad::kBlank;
  if (memcmp(image, kMagic, sizeof(kMagic)) != 0) return SettingsLoad::kCorrupt;
  found_version = image[4];
  if (found_version != kSettingsStoreVersion) return SettingsLoad::kOtherVersion;
  const size_t count = image[5];
  if (count > static_cast<size_t>(GrblSettings::kCount)) return SettingsLoad::kCorrupt;
  const size_t body = kHeaderBytes + count * kEntryBytes;
  if (store.read(kHeaderBytes, image + kHeaderBytes, body - kHeaderBytes + kCrcBytes) != Status::kOk) {
    return SettingsLoad::kUnavailable;
  }
  const uint16_t stored_crc = static_cast<uint16_t>(image[body] | (image[body + 1] << 8));
  if (crc16_ccitt(image, body) != stored_crc) return SettingsLoad::kCorrupt;
  GrblSettings loaded = settings;  // all or nothing
  for (size_t i = 0; i < count; ++i) {
    const uint8_t* entry = image + kHeaderBytes + i * kEntryBytes;
    if (loaded.load(entry[0], get_double(entry + 1)) != GrblError::kOk) return SettingsLoad::kCorrupt;
  }
  settings = loaded;
  return SettingsLoad::kLoaded;
}

// Rewrites the whole image in one write: the CRC guards against a power cut in the middle of it.
Status save_settings(NonvolatileStore& store, const GrblSettings& settings) {
  if (store.size_bytes() < kSettingsStoreMaxBytes) return Status::kUnsupported;
  uint8_t image[kSettingsStoreMaxBytes];
  memcpy(image, kMagic, sizeof(kMagic));
  image[4] = kSettingsStoreVersion;
  size_t count = 0;
  for (int i = 0; i < GrblSettings::kCount; ++i) {
    const GrblSetting& setting = settings.at(i);
    if (!setting.host_set) continue;
    uint8_t* entry = image + kHeaderBytes + count * kEntryBytes;
    entry[0] = setting.number;
    put_double(entry + 1, setting.value);
    ++count;
  }
  image[5] = static_cast<uint8_t>(count);
  const size_t body = kHeaderBytes + count * kEntryBytes;
  const uint16_t crc = crc16_ccitt(image, body);
  image[body] = static_cast<uint8_t>(crc & 0xFF);
  image[body + 1] = static_cast<uint8_t>(crc >> 8);
  return store.write(0, image, body + kCrcBytes);
}

}  // namespace stepdance::gcode
