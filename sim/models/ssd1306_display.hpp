// An SSD1306 OLED controller on I2C, modelled from its datasheet: control bytes, the command
// set a driver uses, display RAM and its addressing modes; a 128×32 panel shows pages 0..3.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "common/sim_time.hpp"
#include "models/i2c_bus.hpp"

namespace stepdance::sim {

/// The panel's picture at one time: 128 × 32 lit (true) or dark pixels, row-major.
struct OledImage {
  static constexpr int kWidth = 128;
  static constexpr int kHeight = 32;
  std::array<bool, kWidth * kHeight> lit{};
  bool at(int x, int y) const { return lit[static_cast<size_t>(y * kWidth + x)]; }
};

/// What the controller was told, for tests and reports.
struct OledCounters {
  uint64_t command_bytes = 0;
  uint64_t data_bytes = 0;
  uint64_t unknown_commands = 0;
};

/// Control byte (datasheet 8.1.5.2): Co = 0 → the rest of the transfer is commands (D/C# = 0)
/// or RAM data (D/C# = 1); Co = 1 → one byte of that kind, then another control byte.
/// RAM is 8 pages × 128 columns; a data byte is a column of 8 rows of the current page, bit 0
/// on top. Horizontal, vertical and page addressing advance the column/page pointers as the
/// datasheet's section 10.1.3–10.1.5 describe, within the 21h/22h windows.
///
/// The picture: row y of the panel is RAM row y (multiplex 32, no offset, start line 0, COM
/// pins 02h); with segment remap (A1h) and COM remap (C8h) — the configuration the SparkFun
/// board needs to be upright — column x is RAM column x; without either, that axis is mirrored.
/// Display off (AEh), charge pump off, or "entire display on" (A5h) and inversion (A7h) are
/// shown as a real panel would show them.
class Ssd1306Display : public I2cDevice {
 public:
  bool write(SimTime time, const uint8_t* data, size_t length) override;
  void read(SimTime time, uint8_t* data, size_t length) override;

  /// Takes a picture at each of these times (they are kept sorted); pictures() fills in as the
  /// run reaches them (the RAM as of that time), and finish() the ones after the last write.
  void set_snapshot_times(std::vector<SimTime> times);
  /// Takes the pictures still pending and the final one. Call once at the end of the run.
  void finish();
  /// (time, picture) for every snapshot time, in order; valid after finish().
  const std::vector<std::pair<SimTime, OledImage>>& snapshots() const { return snapshots_; }

  /// What the panel shows now.
  OledImage image() const;
  /// The text the panel shows, read back in the 21 × 4 grid of 6×8 cells of Stepdance's font
  /// (trailing blanks removed; a cell that is no glyph reads '?').
  std::vector<std::string> text_rows() const;
  static std::vector<std::string> text_rows(const OledImage& image);
  /// Every command byte received (with parameters), in order.
  const std::vector<uint8_t>& command_log() const { return command_log_; }
  const OledCounters& counters() const { return counters_; }
  bool display_on() const { return display_on_; }

 private:
  void command_byte(uint8_t byte);
  void run_command();
  void data_byte(uint8_t byte);
  void take_due_snapshots(SimTime time);

  std::array<uint8_t, 8 * 128> ram_{};
  // Command parser: the command and its parameters so far.
  std::vector<uint8_t> pending_;
  // Addressing.
  int mode_ = 2;  // page addressing after reset
  int column_ = 0, page_ = 0;
  int column_start_ = 0, column_end_ = 127, page_start_ = 0, page_end_ = 7;
  // Display state.
  bool display_on_ = false;
  bool charge_pump_ = false;
  bool inverted_ = false;
  bool all_on_ = false;
  bool segment_remap_ = false;
  bool com_remap_ = false;
  std::vector<uint8_t> command_log_;
  OledCounters counters_;
  std::vector<SimTime> snapshot_times_;
  std::vector<std::pair<SimTime, OledImage>> snapshots_;
};

}  // namespace stepdance::sim
