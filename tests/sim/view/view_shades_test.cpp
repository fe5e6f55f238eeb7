// ViewSession on the Clay Texturizer (a shaded drawing): the page's pieces and colours are the SVG's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "../assembly/simulation_fixture.hpp"
#include "view/view_session.hpp"

namespace stepdance::sim::view {
namespace {

using nlohmann::json;

struct Piece {
  std::vector<PenPoint> points;
  std::string colour;  ///< "#rrggbb", or empty for black
};

/// The documented colour of a shade on the scale [low, high] (docs/simulator.md: blue (0, 0, 0.8)
/// at low, dark green (0, 0.6, 0) in the middle, red (0.8, 0, 0) at high, straight between,
/// clamped), written out here from the docs rather than taken from the SVG writer.
std::string documented_colour(double shade, double low, double high) {
  double t = high > low ? (shade - low) / (high - low) : 0.5;
  t = std::clamp(t, 0.0, 1.0);
  double r = 0, g = 0, b = 0;
  if (t < 0.5) {
    g = 0.6 * (2 * t);
    b = 0.8 * (1 - 2 * t);
  } else {
    g = 0.6 * (1 - (2 * t - 1));
    r = 0.8 * (2 * t - 1);
  }
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", static_cast<int>(r * 255 + 0.5), static_cast<int>(g * 255 + 0.5),
                static_cast<int>(b * 255 + 0.5));
  return text;
}

/// The pen-down polylines of an SVG in order, with their stroke colour (our writer's layout).
std::vector<Piece> svg_pieces(const std::string& svg) {
  std::vector<Piece> pieces;
  const std::regex polyline(R"re(<polyline( stroke="(#[0-9a-f]{6})")? points="([^"]*)"/>)re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), polyline); it != std::sregex_iterator(); ++it) {
    Piece piece;
    piece.colour = (*it)[2];
    std::istringstream points((*it)[3].str());
    std::string pair;
    while (points >> pair) {
      const size_t comma = pair.find(',');
      piece.points.push_back({std::stod(pair.substr(0, comma)), std::stod(pair.substr(comma + 1))});
    }
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

bool same_point(const PenPoint& a, const PenPoint& b) {
  // The SVG rounds to 0.001 mm, here and in the first point the offset is taken from.
  return std::hypot(a.x_mm - b.x_mm, a.y_mm - b.y_mm) <= 0.002;
}

TEST(ViewShades, AShadedDrawingArrivesInTheSvgsPiecesAndColours) {
  std::ifstream file(test::source_path("examples/ClayTexturizer/scenario.toml"));
  std::stringstream text;
  text << file.rdbuf();
  auto simulation = test::create(test::parse(text.str(), test::source_path("examples/ClayTexturizer/scenario.toml")),
                                 "view_shades", false);
  ASSERT_NE(simulation, nullptr);
  RunControl control;
  ViewSession session(*simulation, control);
  const json hello = json::parse(session.hello());
  EXPECT_NE(hello["machine"]["shade_name"], "");

  // The page's side: points and shade starts per stroke (protocol: keep `from` points and the
  // shades before them, append the rest), and the last scale.
  std::vector<std::vector<PenPoint>> strokes;
  std::vector<std::vector<std::pair<size_t, double>>> shades;
  json scale;
  const auto apply = [&](const json& update) {
    for (const json& part : update.value("strokes", json::array())) {  // version 2: absent when none
      const size_t i = part["i"], from = part["from"];
      if (strokes.size() <= i) strokes.resize(i + 1), shades.resize(i + 1);
      strokes[i].resize(from);
      for (const json& point : part["points"]) strokes[i].push_back({point[0], point[1]});
      shades[i].erase(
          std::remove_if(shades[i].begin(), shades[i].end(), [from](const auto& start) { return start.first >= from; }),
          shades[i].end());
      if (part.contains("shades")) {
        for (const json& start : part["shades"]) shades[i].emplace_back(start[0], start[1]);
      }
    }
    if (update.contains("shade_scale")) scale = update["shade_scale"];
  };
  const SimTime end = simulation->duration();
  for (SimTime t = 0; t < end; t += 20 * kMillisecond) {
    simulation->run_until(std::min(end, t + 20 * kMillisecond));
    apply(json::parse(session.update_now()));
  }
  do {
    apply(json::parse(session.update_now()));
  } while (session.strokes_behind());
  ASSERT_TRUE(scale.is_array());

  // Pieces as the page draws them: from each shade start to the next one's point.
  std::vector<Piece> page;
  size_t shaded = 0;
  for (size_t i = 0; i < strokes.size(); ++i) {
    if (shades[i].empty()) {
      page.push_back({strokes[i], ""});
      continue;
    }
    EXPECT_EQ(shades[i].front().first, 0u) << "stroke " << i << " starts unshaded";
    for (size_t j = 0; j < shades[i].size(); ++j) {
      const size_t from = shades[i][j].first;
      const size_t to = j + 1 < shades[i].size() ? shades[i][j + 1].first + 1 : strokes[i].size();
      page.push_back({{strokes[i].begin() + from, strokes[i].begin() + to},
                      documented_colour(shades[i][j].second, scale[0], scale[1])});
      ++shaded;
    }
  }
  const std::vector<Piece> svg = svg_pieces(simulation->drawing_svg());
  EXPECT_GT(shaded, 10u);  // the texturizer's extrusion changes along its strokes
  ASSERT_EQ(page.size(), svg.size());
  // The cartesian machine has no fixed page: the SVG moves the drawing so its bounding box starts
  // at the origin. The page keeps machine mm; the offset is the first point's (exact in both).
  const PenPoint offset{page[0].points.front().x_mm - svg[0].points.front().x_mm,
                        page[0].points.front().y_mm - svg[0].points.front().y_mm};
  const auto moved = [&offset](const PenPoint& point) {
    return PenPoint{point.x_mm - offset.x_mm, point.y_mm - offset.y_mm};
  };
  for (size_t k = 0; k < svg.size(); ++k) {
    EXPECT_EQ(page[k].colour, svg[k].colour) << "piece " << k;
    ASSERT_FALSE(page[k].points.empty()) << "piece " << k;
    EXPECT_TRUE(same_point(moved(page[k].points.front()), svg[k].points.front())) << "piece " << k;
    EXPECT_TRUE(same_point(moved(page[k].points.back()), svg[k].points.back())) << "piece " << k;
  }
}

}  // namespace
}  // namespace stepdance::sim::view
