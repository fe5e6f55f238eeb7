// The size of a drawing's PNG and its limits: pure arithmetic, so the simulator library checks a
// page before a run without linking the PNG module (png_writer.hpp, cairo).
#pragma once

#include <cstdint>
#include <string>

#include "output/drawing.hpp"

namespace stepdance::sim {

/// Pixel size of the PNG of a page: round(page mm × px_per_mm) in each direction, at least 1.
struct PngSize {
  int width = 0;
  int height = 0;
};

/// The largest image write_png() makes: cairo's limit on a side, and 64 million pixels (256 MB
/// of image while it is drawn).
inline constexpr int kMaxPngSidePx = 32767;
inline constexpr int64_t kMaxPngPixels = 64000000;

/// Empty if the page's image at px_per_mm is within kMaxPngSidePx and kMaxPngPixels, else why
/// not: "the PNG would be 4,000,080 x 3,000,080 px; at most 32,767 px a side and 64,000,000 px".
/// Context: any (pure).
std::string png_size_problem(const DrawingStyle& style, double px_per_mm);

/// The largest resolution up to px_per_mm (> 0) at which the page's image fits those limits:
/// px_per_mm itself when it fits. Context: any (pure).
double fitting_px_per_mm(const DrawingStyle& style, double px_per_mm);

/// The image size write_png() produces. Throws std::invalid_argument if px_per_mm is not > 0
/// or png_size_problem() says it is too large.
PngSize png_size(const DrawingStyle& style, double px_per_mm);

}  // namespace stepdance::sim
