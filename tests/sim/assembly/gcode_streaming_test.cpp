// Streaming a 5,000-line G-code spiral to the G-code Step-A-Sketch with both Grbl streaming
// styles: every line acknowledged in order, `?` answered within 2 ms while the planner is full,
// and the pen's drawing equal to the file's toolpath within one motor step.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "simulation_fixture.hpp"

namespace stepdance::sim::test {
namespace {

constexpr int kSegments = 5000;
constexpr double kCenterMm = 100.0;

struct Point {
  double x, y;
};

/// An Archimedean spiral from radius 5 to 50 mm in six turns: segments of 0.04 to 0.38 mm.
std::vector<Point> spiral() {
  std::vector<Point> points;
  for (int k = 0; k <= kSegments; ++k) {
    const double turns = 6.0 * k / kSegments;
    const double radius = 5.0 + 45.0 * k / kSegments;
    points.push_back(
        {kCenterMm + radius * std::cos(2 * M_PI * turns), kCenterMm + radius * std::sin(2 * M_PI * turns)});
  }
  return points;
}

std::string program(const std::vector<Point>& points) {
  std::ostringstream text;
  text.setf(std::ios::fixed);
  text.precision(4);
  text << "G21 G90 G94\nG0 Z4\nG0 X" << points[0].x << " Y" << points[0].y << "\nG1 Z-4 F3000\n";
  for (size_t k = 1; k < points.size(); ++k) text << "G1 X" << points[k].x << " Y" << points[k].y << "\n";
  text << "G0 Z4\n";
  return text.str();
}

/// Distance from p to the segment a–b.
double distance_to_segment(const Point& p, const Point& a, const Point& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length_sq = dx * dx + dy * dy;
  double t = length_sq > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / length_sq : 0.0;
  t = std::fmax(0.0, std::fmin(1.0, t));
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

/// Largest distance from any point of `from` to the polyline `to`; both run in the same
/// direction, so the search follows along `to` (a window around the last closest segment).
double farthest(const std::vector<Point>& from, const std::vector<Point>& to) {
  double worst = 0.0;
  size_t near = 0;
  for (const Point& p : from) {
    double best = 1e9;
    size_t best_index = near;
    const size_t begin = near > 200 ? near - 200 : 0;
    const size_t end = std::min(to.size() - 1, near + 400);
    for (size_t i = begin; i < end; ++i) {
      const double d = distance_to_segment(p, to[i], to[i + 1]);
      if (d < best) best = d, best_index = i;
    }
    near = best_index;
    worst = std::fmax(worst, best);
  }
  return worst;
}

class GcodeStreamingTest : public ::testing::TestWithParam<std::string> {};

TEST_P(GcodeStreamingTest, FiveThousandLinesAcknowledgedInOrderAndDrawnWithinOneStep) {
  const std::string flow = GetParam();
  const std::string out = test_output_dir("gcode_streaming_" + flow);
  const std::vector<Point> points = spiral();
  const std::string gcode = program(points);
  const std::string input_dir = out + "-input";  // create() empties `out`
  std::filesystem::create_directories(input_dir);
  const std::string gcode_path = input_dir + "/spiral.gcode";
  std::ofstream(gcode_path) << gcode;
  const std::string text = "duration_s = 60\n" + gcode_step_a_sketch_board() +
                           "[[host]]\nboard = \"driver\"\n"
                           "[[host.step]]\nwait = \"^Grbl\"\n"
                           "[[host.step]]\nstream_file = \"" +
                           gcode_path + "\"\nflow = \"" + flow +
                           "\"\npoll = \"?\"\npoll_every_s = 0.1\n"
                           "[output]\ndirectory = \"" +
                           out + "\"\nsvg = \"\"\npng = \"\"\nsummary = \"\"\n";
  auto simulation = create(parse(text, input_dir + "/scenario.toml"), "gcode_streaming_" + flow);
  simulation->finish();
  const HostClient* client = simulation->host_client("driver");
  ASSERT_NE(client, nullptr);
  ASSERT_TRUE(client->completed()) << client->failure();

  // Every line sent, in the file's order, and acknowledged with ok (no errors).
  std::istringstream file(gcode);
  std::vector<std::string> lines;
  for (std::string line; std::getline(file, line);) lines.push_back(line);
  ASSERT_GE(lines.size(), 5000u);
  size_t sent = 0, oks = 0, errors = 0, polls = 0, slow_replies = 0, full_polls = 0;
  const std::vector<HostClient::Entry>& transcript = client->transcript();
  for (size_t i = 0; i < transcript.size(); ++i) {
    const HostClient::Entry& entry = transcript[i];
    if (entry.from_host && entry.text == "?") {
      ++polls;
      // The status report is the next line starting with '<'; it must come within 2 ms.
      for (size_t j = i + 1; j < transcript.size(); ++j) {
        if (transcript[j].from_host || transcript[j].text.rfind("<", 0) != 0) continue;
        if (transcript[j].time - entry.time > 2 * kMillisecond) ++slow_replies;
        if (transcript[j].text.find("|Bf:") != std::string::npos &&
            std::stoi(transcript[j].text.substr(transcript[j].text.find("|Bf:") + 4)) < 8) {
          ++full_polls;
        }
        break;
      }
    } else if (entry.from_host) {
      ASSERT_LT(sent, lines.size());
      EXPECT_EQ(entry.text, lines[sent]) << "line " << sent + 1;
      ++sent;
    } else {
      oks += entry.text == "ok" ? 1 : 0;
      errors += entry.text.rfind("error", 0) == 0 ? 1 : 0;
    }
  }
  EXPECT_EQ(sent, lines.size());
  EXPECT_EQ(oks, lines.size());
  EXPECT_EQ(errors, 0u);
  EXPECT_GT(polls, 50u);
  EXPECT_GT(full_polls, polls / 2) << "the planner should be nearly full while streaming";
  EXPECT_EQ(slow_replies, 0u);

  // The drawing: one stroke, every pen point within one motor step (1/80 mm) plus the trace's
  // tolerance (0.01 mm) of the file's spiral, and every vertex of the spiral as close to the pen.
  ASSERT_EQ(simulation->machine()->strokes().size(), 1u);
  std::vector<Point> pen;
  for (const PenPoint& p : simulation->machine()->strokes()[0]) pen.push_back({p.x_mm, p.y_mm});
  const double bound_mm = 1.0 / 80.0 + 0.01;
  EXPECT_LE(farthest(pen, points), bound_mm);
  EXPECT_LE(farthest(points, pen), bound_mm);
  // No queue overflowed: nothing refused or dropped by the board.
  EXPECT_TRUE(simulation->board("driver")->faults().empty());
}

INSTANTIATE_TEST_SUITE_P(Flows, GcodeStreamingTest, ::testing::Values("ack", "character_counting"));

}  // namespace
}  // namespace stepdance::sim::test
