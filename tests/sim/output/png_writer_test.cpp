// PNG writer: image size, and pixel colours read back with cairo.
#include <gtest/gtest.h>

#include <cairo.h>

#include <cstdint>
#include <stdexcept>

#include "output/png_writer.hpp"
#include "sim/output/test_files.hpp"

namespace stepdance::sim {
namespace {

constexpr uint32_t kWhite = 0xFFFFFF;
constexpr uint32_t kBlack = 0x000000;
constexpr uint32_t kGrey = 0x999999;  // 0.6 of full scale

DrawingStyle small_page() {
  DrawingStyle style;
  style.travel_width_mm = 100;
  style.travel_height_mm = 50;
  style.pen_width_mm = 1;
  style.travel_line_width_mm = 0.5;
  return style;
}

// A horizontal line at y = 10 mm, a dot at (30, 40), a vertical pen-up move at x = 70 mm.
const std::vector<Stroke> kStrokes = {
    {{{10, 10}, {90, 10}}, true},
    {{{30, 40}}, true},
    {{{70, 20}, {70, 45}}, false},
};

// A PNG read back as 0xRRGGBB pixels.
class Image {
 public:
  explicit Image(const std::string& path) : surface_(cairo_image_surface_create_from_png(path.c_str())) {}
  ~Image() { cairo_surface_destroy(surface_); }
  Image(const Image&) = delete;
  Image& operator=(const Image&) = delete;

  bool ok() const { return cairo_surface_status(surface_) == CAIRO_STATUS_SUCCESS; }
  int width() const { return cairo_image_surface_get_width(surface_); }
  int height() const { return cairo_image_surface_get_height(surface_); }
  /// The colour at a machine position in mm, at 4 px/mm with a 10 mm margin.
  uint32_t at_mm(double x, double y) const {
    return pixel(static_cast<int>((x + 10) * 4), static_cast<int>((y + 10) * 4));
  }
  uint32_t pixel(int x, int y) const {
    const unsigned char* data = cairo_image_surface_get_data(surface_);
    const int stride = cairo_image_surface_get_stride(surface_);
    const uint32_t value = *reinterpret_cast<const uint32_t*>(data + y * stride + x * 4);
    return value & 0xFFFFFF;
  }

 private:
  cairo_surface_t* surface_;
};

TEST(PngWriter, SizeIsThePageTimesPixelsPerMm) {
  EXPECT_EQ(png_size(small_page(), 4).width, 480);
  EXPECT_EQ(png_size(small_page(), 4).height, 280);
  EXPECT_EQ(png_size(small_page(), 0.5).width, 60);
  EXPECT_EQ(png_size(small_page(), 0.001).height, 1);
  EXPECT_THROW(png_size(small_page(), 0), std::invalid_argument);
  EXPECT_THROW(png_size(small_page(), 1000), std::invalid_argument);
}

// A page's image is bounded (cairo's 32,767 px a side, and 64 Mpx): beyond that the size is
// refused with a reason, and fitting_px_per_mm gives the finest resolution that fits.
TEST(PngWriter, ALargePageIsRefusedOrFittedToTheLimits) {
  DrawingStyle square;
  square.travel_width_mm = square.travel_height_mm = 100000;  // 100,020 mm pages with the margins
  EXPECT_EQ(png_size_problem(square, 4),
            "the PNG would be 400,080 x 400,080 px; at most 32,767 px a side and 64,000,000 px");
  EXPECT_THROW(png_size(square, 4), std::invalid_argument);
  // 64,000,000 px over a 100,020 mm square: sqrt(64e6) = 8,000 px a side, 8,000 / 100,020 px/mm.
  const double square_fit = fitting_px_per_mm(square, 4);
  EXPECT_NEAR(square_fit, 8000.0 / 100020.0, 1e-6);
  const PngSize square_size = png_size(square, square_fit);
  EXPECT_LE(int64_t{square_size.width} * square_size.height, kMaxPngPixels);
  EXPECT_GE(square_size.width, 7990);
  DrawingStyle strip;
  strip.travel_width_mm = 1000000;  // 1,000,020 mm: the side limit binds first
  strip.travel_height_mm = 10;
  const PngSize strip_size = png_size(strip, fitting_px_per_mm(strip, 4));
  EXPECT_LE(strip_size.width, kMaxPngSidePx);
  EXPECT_GE(strip_size.width, kMaxPngSidePx - 40);
  EXPECT_EQ(fitting_px_per_mm(small_page(), 4), 4.0);  // a page that fits keeps its resolution
  EXPECT_EQ(png_size_problem(small_page(), 4), "");
}

TEST(PngWriter, PenDownStrokesAreBlackOnWhite) {
  const std::string path = test::temp_path("drawing.png");
  write_png(path, kStrokes, small_page(), 4);
  const Image image(path);
  ASSERT_TRUE(image.ok());
  EXPECT_EQ(image.width(), 480);
  EXPECT_EQ(image.height(), 280);
  EXPECT_EQ(image.pixel(0, 0), kWhite);
  EXPECT_EQ(image.pixel(479, 279), kWhite);
  EXPECT_EQ(image.at_mm(50, 10), kBlack);    // on the line
  EXPECT_EQ(image.at_mm(50, 9.75), kBlack);  // inside its 1 mm width
  EXPECT_EQ(image.at_mm(50, 11), kWhite);    // beyond it
  EXPECT_EQ(image.at_mm(30, 40), kBlack);    // the dot
  EXPECT_EQ(image.at_mm(70, 21), kWhite);    // pen-up travel is not drawn
}

TEST(PngWriter, PenUpTravelIsGreyAndDashed) {
  DrawingStyle style = small_page();
  style.pen_up_travel = true;
  const std::string path = test::temp_path("travel.png");
  write_png(path, kStrokes, style, 4);
  const Image image(path);
  ASSERT_TRUE(image.ok());
  EXPECT_EQ(image.at_mm(70, 21), kGrey);   // first dash: 20..22 mm
  EXPECT_EQ(image.at_mm(70, 23), kWhite);  // gap: 22..24 mm (less the round caps)
  EXPECT_EQ(image.at_mm(70, 25), kGrey);   // second dash
  EXPECT_EQ(image.at_mm(50, 10), kBlack);
}

TEST(PngWriter, UnwritablePathThrows) {
  EXPECT_THROW(write_png("/nonexistent-dir/drawing.png", kStrokes, small_page(), 4), std::runtime_error);
}

}  // namespace
}  // namespace stepdance::sim
