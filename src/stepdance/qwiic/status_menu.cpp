// StatusMenu: knob events to cursor, edits and actions; items to text rows.
#include "stepdance/qwiic/status_menu.hpp"

#include "stepdance/core/text_writer.hpp"
#include "stepdance/hal/hal.hpp"

namespace stepdance {
namespace {
constexpr uint8_t kMenuRows = OledDisplay::kTextRows - 1;  // row 0 is the title
constexpr uint8_t kMaxDecimals = 6;
}  // namespace

// Loop context. The knob's count and clicks at begin() are the baseline, so turns made before the menu
// existed do not move its cursor.
Status StatusMenu::begin(OledDisplay* display, QwiicTwist* knob, const char* title) {
  if (display == nullptr) return Status::kBadArgument;
  display_ = display;
  knob_ = knob;
  title_ = title == nullptr ? "" : title;
  if (knob_ != nullptr) {
    seen_count_ = knob_->count();
    seen_clicks_ = knob_->clicks();
  }
  return register_in(Stage::kLoop);
}

// The cursor starts on the first selectable item (a parameter or an action); read-only values are
// skipped by the cursor.
Status StatusMenu::add(const Item& item) {
  if (item_count_ == kMaxItems) return Status::kFull;
  if (item.decimals > kMaxDecimals) return Status::kBadArgument;
  items_[item_count_] = item;
  if (selected_ == kMaxItems && selectable(item_count_)) selected_ = item_count_;
  ++item_count_;
  return Status::kOk;
}

Status StatusMenu::add_value(const char* label, Reader read, uint8_t decimals) {
  if (read == nullptr) return Status::kBadArgument;
  Item item;
  item.label = label;
  item.read = read;
  item.decimals = decimals;
  return add(item);
}

Status StatusMenu::add_value(const char* label, const volatile float* value, uint8_t decimals) {
  if (value == nullptr) return Status::kBadArgument;
  Item item;
  item.label = label;
  item.value = value;
  item.decimals = decimals;
  return add(item);
}

// Rejects a step that is not positive and a reversed range (the `!(…)` forms also reject NaN).
Status StatusMenu::add_parameter(const char* label, ControlParameter* parameter, float step, float minimum,
                                 float maximum, uint8_t decimals, Changed on_change) {
  if (parameter == nullptr || !(step > 0) || !(minimum <= maximum)) return Status::kBadArgument;
  Item item;
  item.kind = Kind::kParameter;
  item.label = label;
  item.parameter = parameter;
  item.value = parameter;
  item.step = step;
  item.minimum = minimum;
  item.maximum = maximum;
  item.decimals = decimals;
  item.changed = on_change;
  return add(item);
}

Status StatusMenu::add_action(const char* label, Action action) {
  if (action == nullptr) return Status::kBadArgument;
  Item item;
  item.kind = Kind::kAction;
  item.label = label;
  item.action = action;
  return add(item);
}

// 20 ms (50 Hz) at the fastest: a full text redraw is 4 rows of I2C traffic; 10 s at the slowest so
// values do not look frozen.
Status StatusMenu::set_refresh_ms(uint16_t refresh_ms) {
  if (refresh_ms < 20 || refresh_ms > 10000) return Status::kBadArgument;
  refresh_ms_ = refresh_ms;
  return Status::kOk;
}

// Redraws at once after a knob event (the cursor must follow the hand) and otherwise every refresh_ms_
// for the live values.
void StatusMenu::loop() {
  const bool changed = handle_knob();
  const uint32_t now_us = hal::micros_now();
  if (!changed && rendered_once_ && now_us - rendered_at_us_ < refresh_ms_ * 1000u) return;
  rendered_once_ = true;
  rendered_at_us_ = now_us;
  render();
}

// True if the knob did something.
// Differences of the knob's counters, not events, so no turn or click is lost between two passes.
// A turn moves the cursor, or edits the value when a click has entered edit mode.
bool StatusMenu::handle_knob() {
  if (knob_ == nullptr) return false;
  const int32_t detents = knob_->count() - seen_count_;
  const uint32_t clicks = knob_->clicks() - seen_clicks_;
  seen_count_ = knob_->count();
  seen_clicks_ = knob_->clicks();
  if (detents != 0) editing_ ? change_parameter(detents) : move_cursor(detents);
  for (uint32_t i = 0; i < clicks; ++i) click();
  return detents != 0 || clicks != 0;
}

// One selectable item per detent, skipping read-only rows; the cursor stops at the ends (no wrap).
void StatusMenu::move_cursor(int32_t detents) {
  if (selected_ == kMaxItems) return;
  const int32_t direction = detents > 0 ? 1 : -1;
  for (int32_t moved = 0; moved != detents; moved += direction) {
    int32_t next = selected_ + direction;
    while (next >= 0 && next < item_count_ && !selectable(static_cast<uint8_t>(next))) next += direction;
    if (next < 0 || next >= item_count_) return;  // stops at the ends
    selected_ = static_cast<uint8_t>(next);
  }
}

// value += detents × step, clamped to the item's range; the callback sees the value actually stored.
void StatusMenu::change_parameter(int32_t detents) {
  Item& item = items_[selected_];
  float value = *item.parameter + static_cast<float>(detents) * item.step;
  if (value < item.minimum) value = item.minimum;
  if (value > item.maximum) value = item.maximum;
  *item.parameter = value;
  if (item.changed != nullptr) item.changed(value);
}

void StatusMenu::click() {
  if (selected_ == kMaxItems) return;
  const Item& item = items_[selected_];
  if (item.kind == Kind::kParameter) {
    editing_ = !editing_;
  } else if (item.kind == Kind::kAction) {
    item.action();
  }
}

// Row format: a cursor mark ('>' selected, '*' editing), the label, then the value with its decimals;
// TextWriter truncates a long row at the display's 21 columns.
void StatusMenu::render_item(uint8_t index, char* row) const {
  const Item& item = items_[index];
  TextWriter line(row, OledDisplay::kTextColumns + 1);
  const bool under_cursor = index == selected_;
  line.character(under_cursor ? (editing_ ? '*' : '>') : ' ');
  line.text(item.label);
  if (item.kind == Kind::kAction) return;
  const float value = item.read != nullptr ? item.read() : *item.value;
  line.character(' ').fixed(value, item.decimals);
}

// The visible window scrolls just enough to keep the cursor on one of the rows below the title.
void StatusMenu::render() {
  // Keep the cursor in the window of kMenuRows rows.
  if (selected_ != kMaxItems) {
    if (selected_ < first_shown_) first_shown_ = selected_;
    if (selected_ >= first_shown_ + kMenuRows) first_shown_ = static_cast<uint8_t>(selected_ - kMenuRows + 1);
  }
  TextWriter title(rows_[0], sizeof rows_[0]);
  title.text(title_);
  for (uint8_t r = 0; r < kMenuRows; ++r) {
    const uint8_t index = static_cast<uint8_t>(first_shown_ + r);
    rows_[1 + r][0] = '\0';
    if (index < item_count_) render_item(index, rows_[1 + r]);
  }
  for (uint8_t r = 0; r < OledDisplay::kTextRows; ++r) display_->print_line(r, rows_[r]);
}

}  // namespace stepdance
