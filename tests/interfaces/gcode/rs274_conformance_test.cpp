// Toolpath conformance: our interpreter's motions equal LinuxCNC's standalone rs274 interpreter's.
#include <gtest/gtest.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "stepdance/interfaces/gcode/arc_geometry.hpp"
#include "stepdance/interfaces/gcode/gcode_interpreter.hpp"
#include "stepdance/interfaces/gcode/gcode_parser.hpp"

namespace stepdance::gcode {
namespace {

namespace fs = std::filesystem;

constexpr double kToleranceMm = 0.001;
constexpr double kArcToleranceMm = 0.002;
constexpr double kPi = 3.14159265358979323846;

/// One motion as rs274 reported it, converted to machine millimetres.
struct ReferenceMotion {
  bool arc = false;
  double end_mm[3] = {};
  double end_a = 0.0;        // the A axis (where a printer file's E words go)
  double center_0_mm = 0.0;  // arcs: centre in the plane's first and second axes
  double center_1_mm = 0.0;
  int rotation = 0;  // arcs: turns, negative clockwise
  int axis_0 = 0;
  int axis_1 = 1;
};

/// Reads rs274's canonical-machining-function trace, tracking units, plane and offsets.
class CanonReader {
 public:
  void read_line(const std::string& line) {
    const size_t open = line.find('(');
    if (open == std::string::npos) return;
    const std::string name = line.substr(line.find_last_of(' ', open) + 1, open - line.find_last_of(' ', open) - 1);
    std::vector<double> args = numbers(line.substr(open + 1));
    if (name == "USE_LENGTH_UNITS") {
      mm_per_unit_ = line.find("INCHES") != std::string::npos ? 25.4 : 1.0;
    } else if (name == "SELECT_PLANE") {
      plane_ = line.find("_XZ") != std::string::npos ? 1 : (line.find("_YZ") != std::string::npos ? 2 : 0);
    } else if (name == "SET_G5X_OFFSET") {
      for (int axis = 0; axis < 3; ++axis) g5x_mm_[axis] = args[1 + axis] * mm_per_unit_;
    } else if (name == "SET_G92_OFFSET") {
      for (int axis = 0; axis < 3; ++axis) g92_mm_[axis] = args[axis] * mm_per_unit_;
    } else if (name == "STRAIGHT_TRAVERSE" || name == "STRAIGHT_FEED") {
      ReferenceMotion motion;
      for (int axis = 0; axis < 3; ++axis) motion.end_mm[axis] = machine_mm(axis, args[axis]);
      motion.end_a = args[3];
      // LinuxCNC reports a G0/G1 without axis words (and G28's intermediate point when none is
      // given) as a move to where the tool already is; Grbl makes no motion of it. Such moves
      // draw nothing, so they are left out.
      if (!goes_nowhere(motion)) motions.push_back(motion);
    } else if (name == "ARC_FEED") {
      motions.push_back(arc(args));
    }
  }

  std::vector<ReferenceMotion> motions;

 private:
  static std::vector<double> numbers(const std::string& text) {
    std::vector<double> values;
    const char* cursor = text.c_str();
    while (*cursor != '\0') {
      char* end = nullptr;
      const double value = strtod(cursor, &end);
      if (end == cursor) {
        ++cursor;
      } else {
        values.push_back(value);
        cursor = end;
      }
    }
    return values;
  }

  bool goes_nowhere(const ReferenceMotion& motion) const {
    const ReferenceMotion start = motions.empty() ? ReferenceMotion{} : motions.back();  // rs274 starts at 0
    return motion.end_a == start.end_a && std::equal(motion.end_mm, motion.end_mm + 3, start.end_mm);
  }

  double machine_mm(int axis, double program_units) const {
    return program_units * mm_per_unit_ + g5x_mm_[axis] + g92_mm_[axis];
  }

  ReferenceMotion arc(const std::vector<double>& args) const {
    // ARC_FEED(first_end, second_end, first_centre, second_centre, rotation, normal_end, ...)
    // with (first, second, normal) = XY Z, ZX Y or YZ X.
    static constexpr int kAxes[3][3] = {{0, 1, 2}, {2, 0, 1}, {1, 2, 0}};
    const int* axes = kAxes[plane_];
    ReferenceMotion motion;
    motion.arc = true;
    motion.axis_0 = axes[0];
    motion.axis_1 = axes[1];
    motion.end_mm[axes[0]] = machine_mm(axes[0], args[0]);
    motion.end_mm[axes[1]] = machine_mm(axes[1], args[1]);
    motion.center_0_mm = machine_mm(axes[0], args[2]);
    motion.center_1_mm = machine_mm(axes[1], args[3]);
    motion.rotation = static_cast<int>(args[4]);
    motion.end_mm[axes[2]] = machine_mm(axes[2], args[5]);
    motion.end_a = args[6];
    return motion;
  }

  double mm_per_unit_ = 1.0;
  int plane_ = 0;
  double g5x_mm_[3] = {};
  double g92_mm_[3] = {};
};

struct CollectingSink final : GcodeSink {
  std::vector<Motion> motions;
  void on_motion(const Motion& motion) override {
    if (motion.kind != MotionKind::kArc && std::equal(motion.start_mm, motion.start_mm + kAxisCount, motion.end_mm)) {
      return;  // goes nowhere (as in the reference, see CanonReader)
    }
    motions.push_back(motion);
  }
  void on_dwell(double) override {}
};

std::vector<ReferenceMotion> run_rs274(const fs::path& program) {
  static int runs = 0;
  const fs::path scratch =
      fs::temp_directory_path() / ("stepdance-rs274-" + std::to_string(getpid()) + "-" + std::to_string(++runs));
  fs::create_directories(scratch);
  // rs274 keeps its tool table in $HOME/.tool.mmap: each run gets its own HOME, or two tests
  // running at once truncate each other's table and one of them sees no motion.
  const std::string command =
      "cd '" + scratch.string() + "' && HOME='" + scratch.string() + "' rs274 -g '" + program.string() + "' 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  CanonReader reader;
  if (pipe != nullptr) {
    char buffer[512];
    while (fgets(buffer, sizeof(buffer), pipe) != nullptr) reader.read_line(buffer);
    pclose(pipe);
  }
  fs::remove_all(scratch);
  return reader.motions;
}

std::vector<Motion> run_ours(const fs::path& program) {
  std::ifstream in(program);
  GcodeInterpreter interpreter;
  CollectingSink sink;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    GcodeBlock block;
    GrblError error = parse_line(line.data(), line.size(), block);
    if (error == GrblError::kOk) error = interpreter.execute(block, sink);
    EXPECT_EQ(error, GrblError::kOk) << program.filename() << ":" << number << ": " << line << ": " << describe(error);
  }
  return sink.motions;
}

void expect_same_arc(const Motion& ours, const ReferenceMotion& reference, const std::string& where) {
  EXPECT_EQ(ours.plane_axis_0, reference.axis_0) << where;
  EXPECT_NEAR(ours.center_0_mm, reference.center_0_mm, kToleranceMm) << where;
  EXPECT_NEAR(ours.center_1_mm, reference.center_1_mm, kToleranceMm) << where;
  EXPECT_EQ(ours.sweep_rad < 0.0, reference.rotation < 0) << where;
  // LinuxCNC's rotation counts the turns begun (±1 up to a full circle, ±P for a P-turn arc).
  const double turns = fabs(ours.sweep_rad) / (2.0 * kPi);
  EXPECT_EQ(static_cast<int>(ceil(turns - 1e-9)), abs(reference.rotation)) << where;
  // Every chord end lies on the reference circle within the arc tolerance.
  const double radius = hypot(ours.start_mm[reference.axis_0] - reference.center_0_mm,
                              ours.start_mm[reference.axis_1] - reference.center_1_mm);
  ArcSegmenter chords(ours, kArcToleranceMm);
  for (uint32_t k = 1; k <= chords.segment_count(); ++k) {
    double point[kAxisCount];
    chords.point_mm(k, point);
    const double distance =
        hypot(point[reference.axis_0] - reference.center_0_mm, point[reference.axis_1] - reference.center_1_mm);
    EXPECT_NEAR(distance, radius, kArcToleranceMm) << where << " chord " << k;
  }
}

/// LinuxCNC has no extruder and its M100–M199 are user programs, so for rs274 a 3D-printer file
/// is copied with comments dropped, its housekeeping lines (M-codes from M10 up, except M30)
/// left out and every E word renamed A: rs274 then moves an A axis wherever we move E, so the
/// two motion lists stay aligned (only X, Y and Z are compared). Our interpreter reads the
/// original file.
fs::path printer_reference_copy(const fs::path& program, const fs::path& folder) {
  std::ifstream in(program);
  const fs::path copy = folder / (program.stem().string() + ".ngc");
  std::ofstream out(copy);
  std::string line;
  while (std::getline(in, line)) {
    line = line.substr(0, line.find(';'));
    bool housekeeping = false;
    for (size_t i = 0; i < line.size(); ++i) {
      if (line[i] == 'M' || line[i] == 'm') {
        const int code = atoi(line.c_str() + i + 1);
        housekeeping = housekeeping || (code >= 10 && code != 30);
      }
      if (line[i] == 'E' || line[i] == 'e') line[i] = 'A';
    }
    out << (housekeeping ? "" : line) << "\n";
  }
  out << "M2\n";
  return copy;
}

void expect_same_toolpath(const fs::path& program, bool printer_file = false) {
  const fs::path scratch = fs::temp_directory_path() / ("stepdance-printer-" + std::to_string(getpid()));
  fs::create_directories(scratch);
  const std::vector<ReferenceMotion> reference =
      run_rs274(printer_file ? printer_reference_copy(program, scratch) : program);
  fs::remove_all(scratch);
  const std::vector<Motion> ours = run_ours(program);
  ASSERT_FALSE(reference.empty()) << "rs274 (Debian linuxcnc-uspace) produced no motion for " << program;
  ASSERT_EQ(ours.size(), reference.size()) << program;
  for (size_t i = 0; i < ours.size(); ++i) {
    const std::string where = program.filename().string() + " motion " + std::to_string(i + 1);
    EXPECT_EQ(ours[i].kind == MotionKind::kArc, reference[i].arc) << where;
    for (int axis = 0; axis < 3; ++axis) {
      EXPECT_NEAR(ours[i].end_mm[axis], reference[i].end_mm[axis], kToleranceMm) << where << " axis " << axis;
    }
    if (reference[i].arc && ours[i].kind == MotionKind::kArc) expect_same_arc(ours[i], reference[i], where);
  }
}

TEST(Rs274Conformance, EveryProgramMatchesLinuxCncInterpreter) {
  ASSERT_EQ(system("command -v rs274 >/dev/null 2>&1"), 0) << "rs274 missing: run scripts/setup.sh";
  const fs::path folder = fs::path(STEPDANCE_SOURCE_DIR) / "tests/interfaces/gcode/conformance";
  int programs = 0;
  int slicer_outputs = 0;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(folder)) {
    const bool printer_file = entry.path().extension() == ".gcode";  // slicer output (prusaslicer/)
    if (entry.path().extension() != ".ngc" && !printer_file) continue;
    SCOPED_TRACE(entry.path().filename().string());
    expect_same_toolpath(entry.path(), printer_file);
    ++programs;
    slicer_outputs += printer_file;
  }
  EXPECT_GE(programs, 5);
  EXPECT_GE(slicer_outputs, 1);  // prusaslicer/prism.gcode at least
}

TEST(Rs274Conformance, EveryExampleProgramMatchesLinuxCncInterpreter) {
  ASSERT_EQ(system("command -v rs274 >/dev/null 2>&1"), 0) << "rs274 missing: run scripts/setup.sh";
  int programs = 0;
  for (const fs::directory_entry& entry :
       fs::recursive_directory_iterator(fs::path(STEPDANCE_SOURCE_DIR) / "examples")) {
    if (entry.path().extension() != ".gcode") continue;
    SCOPED_TRACE(entry.path().string());
    expect_same_toolpath(entry.path());
    ++programs;
  }
  EXPECT_GE(programs, 1);  // examples/GCodeStepASketch/star.gcode at least
}

}  // namespace
}  // namespace stepdance::gcode
