// SVG writer: golden documents for two strokes, with and without pen-up travel.
#include <gtest/gtest.h>

#include <stdexcept>

#include "output/svg_writer.hpp"
#include "sim/output/test_files.hpp"

namespace stepdance::sim {
namespace {

DrawingStyle small_page() {
  DrawingStyle style;
  style.travel_width_mm = 100;
  style.travel_height_mm = 50;
  return style;
}

const std::vector<Stroke> kStrokes = {
    {{{0, 0}, {10, 5.25}, {20.0004, -0.0001}}, true},
    {{{20, 0}, {50, 25.5}}, false},
    {{{30, 40}}, true},
    {{}, true},
};

TEST(SvgWriter, TwoStrokesGolden) {
  EXPECT_EQ(svg_document(kStrokes, small_page()),
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"120mm\" height=\"70mm\" viewBox=\"0 0 120 70\">\n"
            "<rect width=\"120\" height=\"70\" fill=\"white\"/>\n"
            "<g transform=\"translate(10 10)\" fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n"
            "<g stroke=\"black\" stroke-width=\"0.5\">\n"
            "<polyline points=\"0,0 10,5.25 20,0\"/>\n"
            "<polyline points=\"30,40 30,40\"/>\n"
            "</g>\n"
            "</g>\n"
            "</svg>\n");
}

TEST(SvgWriter, PenUpTravelIsAGreyDashedGroupUnderTheInk) {
  DrawingStyle style = small_page();
  style.pen_up_travel = true;
  style.margin_mm = 2.5;
  style.pen_width_mm = 0.3;
  EXPECT_EQ(svg_document(kStrokes, style),
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"105mm\" height=\"55mm\" viewBox=\"0 0 105 55\">\n"
            "<rect width=\"105\" height=\"55\" fill=\"white\"/>\n"
            "<g transform=\"translate(2.5 2.5)\" fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n"
            "<g stroke=\"#999999\" stroke-width=\"0.2\" stroke-dasharray=\"2 2\">\n"
            "<polyline points=\"20,0 50,25.5\"/>\n"
            "</g>\n"
            "<g stroke=\"black\" stroke-width=\"0.3\">\n"
            "<polyline points=\"0,0 10,5.25 20,0\"/>\n"
            "<polyline points=\"30,40 30,40\"/>\n"
            "</g>\n"
            "</g>\n"
            "</svg>\n");
}

// Shaded strokes carry their own colour: the scale's ends are blue #0000cc and red #cc0000,
// its middle green #009900 (0.8 and 0.6 of full intensity).
TEST(SvgWriter, ShadedStrokesAreColouredOnTheScale) {
  DrawingStyle style = small_page();
  style.shade_low = 0.04;
  style.shade_high = 0.06;
  style.shade_name = "filament mm per toolpath mm";
  std::vector<Stroke> strokes = {{{{0, 0}, {1, 0}}, true, 0.04},
                                 {{{1, 0}, {2, 0}}, true, 0.05},
                                 {{{2, 0}, {3, 0}}, true, 0.07},
                                 {{{3, 0}, {4, 0}}, true, std::nullopt}};
  const std::string svg = svg_document(strokes, style);
  EXPECT_NE(svg.find("<polyline stroke=\"#0000cc\" points=\"0,0 1,0\"/>"), std::string::npos) << svg;
  EXPECT_NE(svg.find("<polyline stroke=\"#009900\" points=\"1,0 2,0\"/>"), std::string::npos) << svg;
  EXPECT_NE(svg.find("<polyline stroke=\"#cc0000\" points=\"2,0 3,0\"/>"), std::string::npos) << svg;
  EXPECT_NE(svg.find("<polyline points=\"3,0 4,0\"/>"), std::string::npos) << svg;
  EXPECT_NE(svg.find("<desc>Pen-down strokes coloured by filament mm per toolpath mm: blue 0.04, green 0.05, red 0.06"),
            std::string::npos)
      << svg;
}

TEST(SvgWriter, NoStrokesIsABlankPage) {
  EXPECT_EQ(svg_document({}, small_page()),
            "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"120mm\" height=\"70mm\" viewBox=\"0 0 120 70\">\n"
            "<rect width=\"120\" height=\"70\" fill=\"white\"/>\n"
            "<g transform=\"translate(10 10)\" fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n"
            "</g>\n"
            "</svg>\n");
}

TEST(SvgWriter, WritesTheDocumentToAFile) {
  const std::string path = test::temp_path("drawing.svg");
  write_svg(path, kStrokes, small_page());
  EXPECT_EQ(test::read_text(path), svg_document(kStrokes, small_page()));
  EXPECT_THROW(write_svg("/nonexistent-dir/drawing.svg", kStrokes, small_page()), std::runtime_error);
}

}  // namespace
}  // namespace stepdance::sim
