// write_screen_png: one filled square per lit pixel.
#include "output/screen_png.hpp"

#include <cairo.h>

#include <memory>
#include <stdexcept>

namespace stepdance::sim {
namespace {

struct SurfaceDeleter {
  void operator()(cairo_surface_t* surface) const { cairo_surface_destroy(surface); }
};
struct ContextDeleter {
  void operator()(cairo_t* context) const { cairo_destroy(context); }
};

}  // namespace

void write_screen_png(const std::string& path, const std::vector<bool>& lit, int width, int height, int scale) {
  if (width <= 0 || height <= 0 || lit.size() != static_cast<size_t>(width) * static_cast<size_t>(height)) {
    throw std::invalid_argument(path + ": the picture's size does not match its pixels");
  }
  if (scale < 1 || scale > 32) throw std::invalid_argument(path + ": scale must be 1..32");
  const int border = scale;
  std::unique_ptr<cairo_surface_t, SurfaceDeleter> surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, width * scale + 2 * border, height * scale + 2 * border));
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error(path + ": cannot create the image");
  std::unique_ptr<cairo_t, ContextDeleter> context(cairo_create(surface.get()));
  cairo_t* cr = context.get();
  cairo_set_source_rgb(cr, 0.02, 0.02, 0.05);
  cairo_paint(cr);
  cairo_set_source_rgb(cr, 0.75, 0.9, 1.0);
  const double gap = scale >= 3 ? 1 : 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (!lit[static_cast<size_t>(y * width + x)]) continue;
      cairo_rectangle(cr, border + x * scale, border + y * scale, scale - gap, scale - gap);
    }
  }
  cairo_fill(cr);
  cairo_surface_flush(surface.get());
  if (cairo_surface_write_to_png(surface.get(), path.c_str()) != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(path + ": cannot write the PNG");
  }
}

}  // namespace stepdance::sim
