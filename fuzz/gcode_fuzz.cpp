// libFuzzer target: arbitrary bytes as G-code lines through the parser, interpreter and arc splitter.
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "stepdance/interfaces/gcode/arc_geometry.hpp"
#include "stepdance/interfaces/gcode/gcode_interpreter.hpp"
#include "stepdance/interfaces/gcode/gcode_parser.hpp"

namespace {

using namespace stepdance::gcode;

/// Checks every motion the interpreter asks for: finite, arcs with a sane chord split.
struct CheckingSink final : GcodeSink {
  void on_motion(const Motion& motion) override {
    for (int axis = 0; axis < kAxisCount; ++axis) {
      if (!isfinite(motion.start_mm[axis]) || !isfinite(motion.end_mm[axis])) abort();
    }
    if (motion.kind != MotionKind::kArc) return;
    if (!isfinite(motion.radius_mm) || !isfinite(motion.sweep_rad) || motion.radius_mm <= 0.0) abort();
    ArcSegmenter chords(motion, 0.002);
    if (chords.segment_count() < 1 || chords.segment_count() > ArcSegmenter::kMaxSegments) abort();
    double point[kAxisCount];
    chords.point_mm(1, point);
    chords.point_mm(chords.segment_count(), point);
    for (double value : point) {
      if (!isfinite(value)) abort();
    }
  }
  void on_dwell(double seconds) override {
    if (!isfinite(seconds) || seconds < 0.0) abort();
  }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  GcodeInterpreter interpreter;
  CheckingSink sink;
  const char* text = reinterpret_cast<const char*>(data);
  size_t line_start = 0;
  for (size_t i = 0; i <= size; ++i) {
    if (i < size && data[i] != '\n') continue;
    GcodeBlock block;
    if (parse_line(text + line_start, i - line_start, block) == GrblError::kOk) {
      (void)interpreter.execute(block, sink);
    }
    line_start = i + 1;
  }
  return 0;
}
