// StatusMenu: a status screen and a menu on the OLED, driven by the Twist knob.
#pragma once

#include <stdint.h>

#include "stepdance/core/block.hpp"
#include "stepdance/core/status.hpp"
#include "stepdance/core/units.hpp"
#include "stepdance/qwiic/oled_display.hpp"
#include "stepdance/qwiic/qwiic_twist.hpp"

namespace stepdance {

/// Row 0 shows the title (the module's name); rows 1..3 show a window onto a list of items in
/// the order they were added:
///   - values: a label and a live number (a variable or a function: CPU load, a position …),
///   - parameters: a ControlParameter the knob changes in steps between limits,
///   - actions: a label whose click runs a function (pen up, home, start recording …).
/// Turning the knob moves the cursor ('>') over parameters and actions (values are skipped);
/// a click on a parameter starts editing it ('*'): turns then change it by `step` per detent,
/// and another click ends editing; a click on an action runs it. Rows are re-rendered every
/// refresh interval (default 100 ms) and at once after a turn or click; the display sends only
/// rows whose text changed. Everything runs in the loop.
class StatusMenu : public Block {
 public:
  const char* type_name() const override { return "StatusMenu"; }
  using Reader = float (*)();
  using Action = void (*)();
  using Changed = void (*)(float value);
  static constexpr uint8_t kMaxItems = 12;

  /// Uses `display` (begun by the caller) and `knob` (begun, or null for a status screen without
  /// a menu); `title` must outlive the menu. Registers in the loop stage. Context: loop.
  Status begin(OledDisplay* display, QwiicTwist* knob, const char* title);
  /// A live value: `label` and read() with `decimals` places (0..6). kFull past kMaxItems.
  /// Context: loop.
  Status add_value(const char* label, Reader read, uint8_t decimals);
  /// A live value read from a variable. Context: loop.
  Status add_value(const char* label, const volatile float* value, uint8_t decimals);
  /// An editable parameter: each detent adds `step` (world units of the parameter), clamped to
  /// [minimum, maximum]; on_change (may be null) runs after every change. kBadArgument if
  /// minimum > maximum or step ≤ 0. Context: loop.
  Status add_parameter(const char* label, ControlParameter* parameter, float step, float minimum, float maximum,
                       uint8_t decimals, Changed on_change = nullptr);
  /// An action run by a click. Context: loop.
  Status add_action(const char* label, Action action);
  /// How often live values are redrawn (20..10000 ms). Context: loop.
  Status set_refresh_ms(uint16_t refresh_ms);

  /// The item under the cursor (its index in add order), or kMaxItems if none can be selected.
  uint8_t selected() const { return selected_; }
  bool editing() const { return editing_; }
  /// Text of screen row `row` as last rendered (21 characters). Context: loop.
  const char* row_text(uint8_t row) const { return row < OledDisplay::kTextRows ? rows_[row] : ""; }

  void loop() override;

 private:
  enum class Kind : uint8_t { kValue, kParameter, kAction };
  struct Item {
    Kind kind = Kind::kValue;
    const char* label = "";
    Reader read = nullptr;
    const volatile float* value = nullptr;
    ControlParameter* parameter = nullptr;
    float step = 0;
    float minimum = 0;
    float maximum = 0;
    uint8_t decimals = 0;
    Action action = nullptr;
    Changed changed = nullptr;
  };
  Status add(const Item& item);
  bool selectable(uint8_t index) const { return items_[index].kind != Kind::kValue; }
  bool handle_knob();
  void move_cursor(int32_t detents);
  void change_parameter(int32_t detents);
  void click();
  void render();
  void render_item(uint8_t index, char* row) const;

  OledDisplay* display_ = nullptr;
  QwiicTwist* knob_ = nullptr;
  const char* title_ = "";
  Item items_[kMaxItems];
  uint8_t item_count_ = 0;
  uint8_t selected_ = kMaxItems;
  uint8_t first_shown_ = 0;
  bool editing_ = false;
  int32_t seen_count_ = 0;
  uint32_t seen_clicks_ = 0;
  uint16_t refresh_ms_ = 100;
  uint32_t rendered_at_us_ = 0;
  bool rendered_once_ = false;
  char rows_[OledDisplay::kTextRows][OledDisplay::kTextColumns + 1] = {};
};

}  // namespace stepdance
