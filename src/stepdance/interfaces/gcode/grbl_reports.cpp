// The Grbl link's reports: welcome, status `<…>`, `$$`, `$#`, `$G`, `$I`.
#include "stepdance/interfaces/gcode/grbl_protocol.hpp"

namespace stepdance::gcode {
namespace {

constexpr double kMmPerInch = 25.4;
// Grbl 1.1's refresh counts: `WCO:` every 30 reports while moving and 10 at rest, and at once
// after the offset changes; `Ov:` every 20 / 10, and never in the same report as `WCO:`.
constexpr uint8_t kWcoEveryReportsBusy = 30;
constexpr uint8_t kWcoEveryReportsIdle = 10;
constexpr uint8_t kOverridesEveryReportsBusy = 20;
constexpr uint8_t kOverridesEveryReportsIdle = 10;

const char* state_name(MotionState state, bool hold_complete) {
  switch (state) {
    case MotionState::kRun: return "Run";
    case MotionState::kHolding: return hold_complete ? "Hold:0" : "Hold:1";
    case MotionState::kJog: return "Jog";
    case MotionState::kIdle: break;
  }
  return "Idle";
}

}  // namespace

// Three decimals in mm, four in inches ($13), as Grbl prints positions.
void GrblProtocol::append_axes(TextWriter& line, const double* values_mm, int count) {
  const bool inches = settings_.report_inches();
  for (int axis = 0; axis < count; ++axis) {
    if (axis > 0) line.character(',');
    line.fixed(inches ? values_mm[axis] / kMmPerInch : values_mm[axis], inches ? 4 : 3);
  }
}

// Senders detect Grbl by this line (blank line first, as Grbl's reset prints it).
void GrblProtocol::report_welcome() {
  send_text("");
  send_text("Grbl 1.1h ['$' for help]");
}

// Grbl 1.1's status report: <State|MPos or WPos|Bf|FS|WCO|Ov>. Alarm and Check win over the motion
// state, as in Grbl.
void GrblProtocol::report_status() {
  char storage[160];
  TextWriter line(storage, sizeof(storage));
  const MotionState state = machine_->motion_state();
  line.character('<');
  if (alarm_ != 0) {
    line.text("Alarm");
  } else if (interpreting_.check_mode()) {
    line.text("Check");
  } else {
    line.text(state_name(state, machine_->hold_complete()));
  }
  double offset[kOffsetAxisCount];
  for (int axis = 0; axis < kOffsetAxisCount; ++axis) offset[axis] = interpreter().work_offset_mm(axis);
  append_position(line, offset);
  append_buffer_and_feed(line);
  append_offsets_and_overrides(line, offset, state != MotionState::kIdle);
  send_line(line.character('>'));
}

// $10 bit 0 chooses MPos (machine) or WPos (work = machine − WCO); senders compute the other from WCO.
void GrblProtocol::append_position(TextWriter& line, const double (&offset)[kOffsetAxisCount]) {
  double position[kAxisCount];
  machine_->position_mm(position);
  if (settings_.report_machine_position()) {
    line.text("|MPos:");
  } else {
    for (int axis = 0; axis < kOffsetAxisCount; ++axis) position[axis] -= offset[axis];
    line.text("|WPos:");
  }
  append_axes(line, position, kOffsetAxisCount);
}

// Bf: (with $10 bit 1) is free planner blocks and free receive bytes, which character-counting senders
// use for pacing; FS: the current feed and the programmed spindle speed (0 when M5).
void GrblProtocol::append_buffer_and_feed(TextWriter& line) {
  if (settings_.report_buffer_state()) {
    line.text("|Bf:")
        .unsigned_number(machine_->queue_slots_free())
        .character(',')
        .unsigned_number(static_cast<uint32_t>(receiver_.bytes_free()));
  }
  const double feed = machine_->feed_now_mm_per_min();
  const double speed = interpreter().modal().spindle == 50 ? 0.0 : interpreter().modal().spindle_speed;
  line.text("|FS:").fixed(settings_.report_inches() ? feed / kMmPerInch : feed, 0).character(',').fixed(speed, 0);
}

// `WCO:` and `Ov:` at Grbl's refresh counts (see the constants above).
void GrblProtocol::append_offsets_and_overrides(TextWriter& line, const double (&offset)[kOffsetAxisCount], bool busy) {
  for (int axis = 0; axis < kOffsetAxisCount; ++axis) {
    if (offset[axis] != last_wco_mm_[axis]) reports_until_wco_ = 0;  // changed: report it now
  }
  if (reports_until_wco_ > 0) {
    --reports_until_wco_;
  } else {
    line.text("|WCO:");
    append_axes(line, offset, kOffsetAxisCount);
    for (int axis = 0; axis < kOffsetAxisCount; ++axis) last_wco_mm_[axis] = offset[axis];
    reports_until_wco_ = (busy ? kWcoEveryReportsBusy : kWcoEveryReportsIdle) - 1;
    if (reports_until_overrides_ == 0) reports_until_overrides_ = 1;  // Ov: in the next report
  }
  if (reports_until_overrides_ > 0) {
    --reports_until_overrides_;
  } else {
    line.text("|Ov:").unsigned_number(feed_override_percent_).character(',');
    line.unsigned_number(rapid_override_percent_).character(',').unsigned_number(spindle_override_percent_);
    reports_until_overrides_ = (busy ? kOverridesEveryReportsBusy : kOverridesEveryReportsIdle) - 1;
  }
}

// $$: every setting in Grbl's order; $100–$102 show the sketch's channels' steps/mm, the true figures.
void GrblProtocol::report_settings() {
  for (int i = 0; i < GrblSettings::kCount; ++i) {
    const GrblSetting& setting = settings_.at(i);
    double value = setting.value;
    if (setting.number >= 100 && setting.number <= 102) value = machine_->steps_per_mm(setting.number - 100);
    char storage[32];
    TextWriter line(storage, sizeof(storage));
    line.character('$').unsigned_number(setting.number).character('=');
    line.fixed(value, setting.integer ? 0 : 3);
    send_line(line);
  }
}

// $#: the coordinate systems, G28/G30 positions, G92 and tool length offsets; no probe here, so
// PRB is zero and unsuccessful.
void GrblProtocol::report_parameters() {
  static const char* const kSystems[CoordinateData::kSystemCount] = {"G54", "G55", "G56", "G57", "G58", "G59"};
  const CoordinateData& data = interpreter().coordinate_data();
  char storage[64];
  TextWriter line(storage, sizeof(storage));
  for (int system = 0; system < CoordinateData::kSystemCount; ++system) {
    line.clear();
    line.character('[').text(kSystems[system]).character(':');
    append_axes(line, data.system_offset_mm[system], kOffsetAxisCount);
    send_line(line.character(']'));
  }
  line.clear();
  line.text("[G28:");
  append_axes(line, data.g28_position_mm, kOffsetAxisCount);
  send_line(line.character(']'));
  line.clear();
  line.text("[G30:");
  append_axes(line, data.g30_position_mm, kOffsetAxisCount);
  send_line(line.character(']'));
  line.clear();
  line.text("[G92:");
  append_axes(line, interpreter().g92_offset_mm(), kOffsetAxisCount);
  send_line(line.character(']'));
  line.clear();
  line.text("[TLO:");
  append_axes(line, &interpreter().modal().tool_length_offset_mm, 1);
  send_line(line.character(']'));
  send_text("[PRB:0.000,0.000,0.000:0]");
}

// $G: the modal state as Grbl prints it; F keeps one decimal in inches.
void GrblProtocol::report_parser_state() {
  const ModalState& modal = interpreter().modal();
  char storage[96];
  TextWriter line(storage, sizeof(storage));
  line.text("[GC:G").unsigned_number(modal.motion / 10u);
  line.text(" G").unsigned_number(54u + modal.coordinate_system);
  line.text(" G").unsigned_number(modal.plane / 10u);
  line.text(modal.inches ? " G20" : " G21");
  line.text(modal.absolute ? " G90" : " G91");
  line.text(modal.inverse_time ? " G93" : " G94");
  line.text(" M").unsigned_number(modal.spindle / 10u);
  line.text(" M").unsigned_number(modal.coolant / 10u);
  line.text(" T").unsigned_number(modal.tool);
  const double feed = modal.inches ? modal.feed_mm_per_min / kMmPerInch : modal.feed_mm_per_min;
  line.text(" F").fixed(feed, modal.inches ? 1 : 0);
  line.text(" S").fixed(modal.spindle_speed, 0);
  send_line(line.character(']'));
}

void GrblProtocol::report_build_info() {
  send_text("[VER:1.1h.20190830:Stepdance]");
  char storage[32];
  TextWriter line(storage, sizeof(storage));
  // No Grbl build options apply; then planner blocks and receive-buffer bytes, honestly.
  line.text("[OPT:,").unsigned_number(machine_->queue_slots_total()).character(',');
  line.unsigned_number(static_cast<uint32_t>(GrblReceiver::kBufferBytes)).character(']');
  send_line(line);
}

}  // namespace stepdance::gcode
