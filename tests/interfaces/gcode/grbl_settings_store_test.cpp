// The settings store's format: layout, checksum, and what happens to blank, corrupt, foreign data.
#include "stepdance/interfaces/gcode/grbl_settings_store.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "support/memory_store.hpp"

namespace stepdance::gcode {
namespace {

using test_support::MemoryStore;

TEST(GrblSettingsStore, ChecksumIsCrc16CcittFalse) {
  // The published check value of CRC-16/CCITT-FALSE: "123456789" → 0x29B1.
  const uint8_t text[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  EXPECT_EQ(crc16_ccitt(text, sizeof(text)), 0x29B1);
}

TEST(GrblSettingsStore, SavedImageHasTheDocumentedLayout) {
  GrblSettings settings;
  ASSERT_EQ(settings.write(110, 7200.0), GrblError::kOk);
  MemoryStore store;
  ASSERT_EQ(save_settings(store, settings), Status::kOk);
  const std::vector<uint8_t>& bytes = store.bytes();
  // "SDGS", version 1, one entry: number 110, then 7200.0 as a little-endian IEEE-754 double
  // (7200 = 1.7578125 × 2^12: exponent 1023 + 12 = 0x40B, fraction 0xC2 << 44 → 0x40BC200000000000).
  const std::vector<uint8_t> expected = {'S', 'D', 'G', 'S', 1, 1, 110, 0, 0, 0, 0, 0, 0x20, 0xBC, 0x40};
  EXPECT_EQ(std::vector<uint8_t>(bytes.begin(), bytes.begin() + 15), expected);
  const uint16_t crc = crc16_ccitt(expected.data(), expected.size());
  EXPECT_EQ(bytes[15], crc & 0xFF);
  EXPECT_EQ(bytes[16], crc >> 8);
  EXPECT_EQ(bytes[17], 0xFF);  // nothing written beyond the checksum
}

TEST(GrblSettingsStore, LoadAppliesOnlyTheStoredSettings) {
  GrblSettings written;
  written.write(110, 7200.0);
  written.write(12, 0.005);
  MemoryStore store;
  save_settings(store, written);
  GrblSettings read;
  uint8_t version = 0;
  EXPECT_EQ(load_settings(store, read, version), SettingsLoad::kLoaded);
  EXPECT_EQ(version, kSettingsStoreVersion);
  EXPECT_EQ(read.value(110), 7200.0);
  EXPECT_EQ(read.value(12), 0.005);
  EXPECT_TRUE(read.find(110)->host_set);
  EXPECT_EQ(read.value(111), 5000.0);
  EXPECT_FALSE(read.find(111)->host_set);
}

TEST(GrblSettingsStore, BlankCorruptForeignAndMissingStoresLeaveTheSettingsAlone) {
  GrblSettings settings;
  uint8_t version = 0;
  MemoryStore erased;
  EXPECT_EQ(load_settings(erased, settings, version), SettingsLoad::kBlank);
  MemoryStore zeroed;
  std::fill(zeroed.bytes().begin(), zeroed.bytes().end(), 0);
  EXPECT_EQ(load_settings(zeroed, settings, version), SettingsLoad::kBlank);

  GrblSettings written;
  written.write(110, 7200.0);
  MemoryStore store;
  save_settings(store, written);
  std::vector<uint8_t> good = store.bytes();
  store.bytes()[0] = 'X';
  EXPECT_EQ(load_settings(store, settings, version), SettingsLoad::kCorrupt);
  store.bytes() = good;
  store.bytes()[15] ^= 1;  // the checksum itself
  EXPECT_EQ(load_settings(store, settings, version), SettingsLoad::kCorrupt);
  store.bytes() = good;
  store.bytes()[5] = 200;  // more entries than settings exist
  EXPECT_EQ(load_settings(store, settings, version), SettingsLoad::kCorrupt);
  // A well-signed entry for a setting the host may not write ($100, the sketch's steps/mm).
  store.bytes() = good;
  store.bytes()[6] = 100;
  const uint16_t crc = crc16_ccitt(store.bytes().data(), 15);
  store.bytes()[15] = static_cast<uint8_t>(crc & 0xFF);
  store.bytes()[16] = static_cast<uint8_t>(crc >> 8);
  EXPECT_EQ(load_settings(store, settings, version), SettingsLoad::kCorrupt);
  store.bytes() = good;
  store.bytes()[4] = 7;
  EXPECT_EQ(load_settings(store, settings, version), SettingsLoad::kOtherVersion);
  EXPECT_EQ(version, 7);
  EXPECT_EQ(settings.value(110), 5000.0);  // none of it applied

  MemoryStore tiny(16);
  EXPECT_EQ(load_settings(tiny, settings, version), SettingsLoad::kUnavailable);
  EXPECT_EQ(save_settings(tiny, written), Status::kUnsupported);
}

TEST(GrblSettingsStore, EveryWritableSettingFits) {
  GrblSettings all;
  ASSERT_EQ(all.write(22, 1.0), GrblError::kOk);  // homing on first, or `$20` is refused (error:10)
  int writable = 0;
  for (int i = 0; i < GrblSettings::kCount; ++i) {
    const GrblSetting& setting = all.at(i);
    if (!setting.writable) continue;
    ASSERT_EQ(all.write(setting.number, setting.integer ? 3.0 : 2.5), GrblError::kOk) << +setting.number;
    ++writable;
  }
  MemoryStore store(kSettingsStoreMaxBytes);
  ASSERT_EQ(save_settings(store, all), Status::kOk);
  GrblSettings read;
  uint8_t version = 0;
  ASSERT_EQ(load_settings(store, read, version), SettingsLoad::kLoaded);
  for (int i = 0; i < GrblSettings::kCount; ++i) EXPECT_EQ(read.at(i).value, all.at(i).value) << i;
  EXPECT_EQ(writable, 31);  // 34 settings less $100–$102
}

}  // namespace
}  // namespace stepdance::gcode
