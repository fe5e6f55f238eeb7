// One G-code line of a 1,000-turn helical arc through a real GCodeInterface on the manual backend,
// for the loop-pass benchmark (bench/measure_target_loop.sh arc): the loop passes that validate
// the line and feed its chords to the planner are measured, the frames between them are not.
#pragma once

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "hal_manual.hpp"
#include "stepdance/core/byte_stream.hpp"
#include "stepdance/core/dance.hpp"
#include "stepdance/core/engine.hpp"
#include "stepdance/core/fault.hpp"
#include "stepdance/interfaces/gcode/gcode_interface.hpp"

namespace stepdance::workloads {

/// The sender: a fixed program, all of it readable at once (the link's receive buffer applies the
/// back-pressure); replies are counted by their `ok`s and `error`s, then dropped. Context: loop.
class ArcProgram final : public ByteStream {
 public:
  /// To (10, 10) with soft limits' travel all round, then 1,000 clockwise turns of radius 5 mm
  /// round (15, 10) while Z rises 10 mm: ceil(1000 x 2π / (2 acos(1 - 0.002 / 5))) = 111,069
  /// chords at Grbl's default $12 = 0.002 mm.
  static constexpr const char* kProgram =
      "G21 G90 G94 G17\n"
      "G0 X10 Y10 Z0\n"
      "G2 X10 Y10 Z10 I5 J0 P1000 F60000\n";
  size_t bytes_available() override { return strlen(kProgram) - next_; }
  int read_byte() override { return bytes_available() > 0 ? static_cast<uint8_t>(kProgram[next_++]) : -1; }
  size_t write_bytes(const uint8_t* data, size_t length) override {
    for (size_t i = 0; i < length; ++i) {
      const char c = static_cast<char>(data[i]);
      if (c == 'o' && previous_ == '\n') ++oks_;  // "ok" at the start of a line
      if (c == 'e' && previous_ == '\n') ++errors_;
      if (c == 'A' && previous_ == '\n') ++errors_;  // ALARM:N
      previous_ = c;
    }
    return length;
  }
  size_t write_space() override { return 4096; }
  uint32_t oks() const { return oks_; }
  uint32_t errors() const { return errors_; }

 private:
  size_t next_ = 0;
  char previous_ = '\n';
  uint32_t oks_ = 0;
  uint32_t errors_ = 0;
};

/// GCodeInterface alone (its outputs unconnected: the frame runs its interpolator only), with
/// soft limits on over 200 mm of travel and a loop pass every 25 frames (1 ms). The axes are fast
/// (1 m/s, 100 m/s² along the path, $11 = 0.1 mm) so the 111,069 chords take 0.3 ms each and the
/// run few frames; what a loop pass does per chord does not depend on the speed.
class ArcWorkload {
 public:
  ArcWorkload() {
    hal_manual::reset();
    engine().clear();
    clear_fault();
    gcode.begin(&program);
    for (uint32_t axis = 0; axis < 3; ++axis) {
      gcode.settings().set_from_sketch(110 + axis, 60000);   // mm/min
      gcode.settings().set_from_sketch(120 + axis, 100000);  // mm/s²
      gcode.settings().set_from_sketch(130 + axis, 200);     // mm of travel
    }
    gcode.settings().set_from_sketch(20, 1);        // soft limits
    gcode.settings().set_from_sketch(11, 0.1);      // junction deviation, mm
    gcode.interpolator().set_acceleration(100000);  // the path's own limit (2,000 mm/s² by default)
    dance_start();
  }
  /// The measured part: one loop pass, dance_loop()'s: the link, then the interpolator's own loop
  /// work (handing planned blocks to the frame).
  void loop_pass() { engine().run_loop(); }
  /// Unmeasured: one millisecond of frames (the board's clock moves, the kilohertz tick runs).
  void between_passes() { hal_manual::run_frames(25); }
  /// Done once all three lines are answered and the machine has stopped.
  bool done() { return program.oks() + program.errors() >= 3 && gcode.interpolator().is_idle(); }
  bool failed() const { return program.errors() != 0 || program.oks() != 3; }
  /// Lines answered `ok`.
  uint32_t units() const { return program.oks(); }

  ArcProgram program;
  GCodeInterface gcode;
};

}  // namespace stepdance::workloads
