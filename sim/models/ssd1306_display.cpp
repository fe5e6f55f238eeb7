// Ssd1306Display: command decoding, RAM addressing, the picture and the text read back from it.
#include "models/ssd1306_display.hpp"

#include <algorithm>

#include "stepdance/qwiic/font_5x7.hpp"

namespace stepdance::sim {
namespace {

constexpr int kColumns = 128;
constexpr int kCellWidth = 6;
constexpr int kTextColumns = 21;

// Bytes a command takes after its first byte (datasheet section 9, command table).
int parameter_count(uint8_t command) {
  switch (command) {
    case 0x81:
    case 0x20:
    case 0xA8:
    case 0xD3:
    case 0xD5:
    case 0xD9:
    case 0xDA:
    case 0xDB:
    case 0x8D: return 1;
    case 0x21:
    case 0x22:
    case 0xA3: return 2;
    case 0x29:
    case 0x2A: return 5;
    case 0x26:
    case 0x27: return 6;
    default: return 0;
  }
}

}  // namespace

bool Ssd1306Display::write(SimTime time, const uint8_t* data, size_t length) {
  take_due_snapshots(time);
  size_t i = 0;
  while (i < length) {
    const uint8_t control = data[i++];
    const bool continuation = (control & 0x80) != 0;
    const bool is_data = (control & 0x40) != 0;
    if ((control & 0x3F) != 0) return false;  // the low six bits of a control byte must be 0
    const size_t end = continuation ? std::min(length, i + 1) : length;
    for (; i < end; ++i) is_data ? data_byte(data[i]) : command_byte(data[i]);
  }
  return true;
}

// Reads are not modelled (our driver never reads the display): the bus sees an idle line.
void Ssd1306Display::read(SimTime, uint8_t* data, size_t length) { std::fill(data, data + length, 0xFF); }

void Ssd1306Display::command_byte(uint8_t byte) {
  ++counters_.command_bytes;
  command_log_.push_back(byte);
  pending_.push_back(byte);
  if (static_cast<int>(pending_.size()) > parameter_count(pending_[0])) {
    run_command();
    pending_.clear();
  }
}

void Ssd1306Display::run_command() {
  const uint8_t c = pending_[0];
  if (c <= 0x0F) {
    column_ = (column_ & 0xF0) | c;
  } else if (c <= 0x1F) {
    column_ = (column_ & 0x0F) | ((c & 0x0F) << 4);
  } else if (c == 0x20) {
    mode_ = pending_[1] & 0x03;
  } else if (c == 0x21) {
    column_start_ = column_ = pending_[1] & 0x7F;
    column_end_ = pending_[2] & 0x7F;
  } else if (c == 0x22) {
    page_start_ = page_ = pending_[1] & 0x07;
    page_end_ = pending_[2] & 0x07;
  } else if (c >= 0xB0 && c <= 0xB7) {
    page_ = c & 0x07;
  } else if (c == 0xAE || c == 0xAF) {
    display_on_ = c == 0xAF;
  } else if (c == 0xA4 || c == 0xA5) {
    all_on_ = c == 0xA5;
  } else if (c == 0xA6 || c == 0xA7) {
    inverted_ = c == 0xA7;
  } else if (c == 0xA0 || c == 0xA1) {
    segment_remap_ = c == 0xA1;
  } else if (c == 0xC0 || c == 0xC8) {
    com_remap_ = c == 0xC8;
  } else if (c == 0x8D) {
    charge_pump_ = (pending_[1] & 0x04) != 0;
  } else if ((c >= 0x40 && c <= 0x7F) || parameter_count(c) > 0 || c == 0x2E || c == 0x2F || c == 0xE3) {
    // start line, contrast, timing, multiplex, scrolling, NOP: no effect on the modelled picture
  } else {
    ++counters_.unknown_commands;
  }
}

void Ssd1306Display::data_byte(uint8_t byte) {
  ++counters_.data_bytes;
  ram_[static_cast<size_t>(page_ * kColumns + column_)] = byte;
  if (mode_ == 1) {  // vertical: down the pages, then the next column
    if (++page_ > page_end_) {
      page_ = page_start_;
      if (++column_ > column_end_) column_ = column_start_;
    }
    return;
  }
  if (mode_ == 0) {  // horizontal: along the columns, then the next page
    if (++column_ > column_end_) {
      column_ = column_start_;
      if (++page_ > page_end_) page_ = page_start_;
    }
    return;
  }
  if (++column_ > 127) column_ = 0;  // page addressing: the column wraps within the page
}

OledImage Ssd1306Display::image() const {
  OledImage picture;
  const bool powered = display_on_ && charge_pump_;
  for (int y = 0; y < OledImage::kHeight; ++y) {
    for (int x = 0; x < OledImage::kWidth; ++x) {
      const int ram_x = segment_remap_ ? x : kColumns - 1 - x;
      const int ram_y = com_remap_ ? y : OledImage::kHeight - 1 - y;
      bool lit = (ram_[static_cast<size_t>((ram_y / 8) * kColumns + ram_x)] >> (ram_y % 8)) & 1u;
      if (all_on_) lit = true;
      if (inverted_) lit = !lit;
      picture.lit[static_cast<size_t>(y * OledImage::kWidth + x)] = powered && lit;
    }
  }
  return picture;
}

std::vector<std::string> Ssd1306Display::text_rows() const { return text_rows(image()); }

std::vector<std::string> Ssd1306Display::text_rows(const OledImage& image) {
  std::vector<std::string> rows;
  for (int row = 0; row < OledImage::kHeight / 8; ++row) {
    std::string text;
    for (int cell = 0; cell < kTextColumns; ++cell) {
      uint8_t columns[kCellWidth] = {};
      for (int i = 0; i < kCellWidth; ++i) {
        for (int bit = 0; bit < 8; ++bit) {
          if (image.at(cell * kCellWidth + i, row * 8 + bit))
            columns[i] = static_cast<uint8_t>(columns[i] | (1u << bit));
        }
      }
      char found = '?';
      for (char c = font5x7::kFirst; columns[5] == 0; ++c) {
        if (std::equal(columns, columns + font5x7::kColumns, font5x7::glyph(c))) {
          found = c;
          break;
        }
        if (c == font5x7::kLast) break;
      }
      text += found;
    }
    text.erase(text.find_last_not_of(' ') + 1);
    rows.push_back(text);
  }
  return rows;
}

void Ssd1306Display::set_snapshot_times(std::vector<SimTime> times) {
  std::sort(times.begin(), times.end());
  snapshot_times_ = std::move(times);
}

void Ssd1306Display::take_due_snapshots(SimTime time) {
  while (snapshots_.size() < snapshot_times_.size() && snapshot_times_[snapshots_.size()] <= time) {
    snapshots_.emplace_back(snapshot_times_[snapshots_.size()], image());
  }
}

void Ssd1306Display::finish() { take_due_snapshots(INT64_MAX); }

}  // namespace stepdance::sim
