// PNG page size: pixels per side from millimetres, and the limits a PNG must keep.
#include "output/png_page.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace stepdance::sim {
namespace {

/// A side in pixels, at least 1; nan or beyond any limit stays as it is, for the check.
double side_px(double mm, double px_per_mm) {
  const double px = std::round(mm * px_per_mm);
  return px < 1 ? 1 : px;
}

std::string with_thousands(double value) {
  char digits[64];
  std::snprintf(digits, sizeof digits, "%.0f", value);
  std::string text = digits;
  for (std::size_t at = text.size(); at > 3; at -= 3) text.insert(at - 3, ",");
  return text;
}

}  // namespace

std::string png_size_problem(const DrawingStyle& style, double px_per_mm) {
  const double width = side_px(style.page_width_mm(), px_per_mm);
  const double height = side_px(style.page_height_mm(), px_per_mm);
  const bool fits = width <= kMaxPngSidePx && height <= kMaxPngSidePx && width * height <= kMaxPngPixels;
  if (fits) return {};
  return "the PNG would be " + with_thousands(width) + " x " + with_thousands(height) + " px; at most " +
         with_thousands(kMaxPngSidePx) + " px a side and " + with_thousands(static_cast<double>(kMaxPngPixels)) + " px";
}

double fitting_px_per_mm(const DrawingStyle& style, double px_per_mm) {
  const double width_mm = style.page_width_mm();
  const double height_mm = style.page_height_mm();
  double fitting = std::min({px_per_mm, kMaxPngSidePx / width_mm, kMaxPngSidePx / height_mm,
                             std::sqrt(static_cast<double>(kMaxPngPixels) / (width_mm * height_mm))});
  while (!png_size_problem(style, fitting).empty()) fitting *= 0.999;  // rounding up past a limit
  return fitting;
}

PngSize png_size(const DrawingStyle& style, double px_per_mm) {
  if (!(px_per_mm > 0)) throw std::invalid_argument("PNG px_per_mm must be > 0");
  if (const std::string problem = png_size_problem(style, px_per_mm); !problem.empty()) {
    throw std::invalid_argument(problem);
  }
  return PngSize{static_cast<int>(side_px(style.page_width_mm(), px_per_mm)),
                 static_cast<int>(side_px(style.page_height_mm(), px_per_mm))};
}

}  // namespace stepdance::sim
