// PNG writer: a cairo RGB24 image surface scaled to millimetres, saved with cairo's PNG encoder.
#include "output/png_writer.hpp"

#include <cairo.h>

#include <memory>
#include <stdexcept>

namespace stepdance::sim {
namespace {

constexpr double kTravelGrey = 0.6;

struct SurfaceDeleter {
  void operator()(cairo_surface_t* surface) const { cairo_surface_destroy(surface); }
};
struct ContextDeleter {
  void operator()(cairo_t* context) const { cairo_destroy(context); }
};

void trace(cairo_t* cr, const Stroke& stroke) {
  cairo_move_to(cr, stroke.points[0].x, stroke.points[0].y);
  if (stroke.points.size() == 1) cairo_line_to(cr, stroke.points[0].x, stroke.points[0].y);  // a dot
  for (size_t i = 1; i < stroke.points.size(); ++i) cairo_line_to(cr, stroke.points[i].x, stroke.points[i].y);
}

void draw_strokes(cairo_t* cr, const std::vector<Stroke>& strokes, const DrawingStyle& style, bool pen_down) {
  for (const Stroke& stroke : strokes) {
    if (stroke.pen_down != pen_down || stroke.points.empty()) continue;
    if (pen_down) {
      const Rgb colour = style.colour_of(stroke);
      cairo_set_source_rgb(cr, colour.r, colour.g, colour.b);
    }
    trace(cr, stroke);
    cairo_stroke(cr);
  }
}

}  // namespace

void write_png(const std::string& path, const std::vector<Stroke>& strokes, const DrawingStyle& style,
               double px_per_mm) {
  const PngSize size = png_size(style, px_per_mm);
  std::unique_ptr<cairo_surface_t, SurfaceDeleter> surface(
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, size.width, size.height));
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(path + ": cannot create a " + std::to_string(size.width) + "x" +
                             std::to_string(size.height) + " image");
  }
  std::unique_ptr<cairo_t, ContextDeleter> context(cairo_create(surface.get()));
  cairo_t* cr = context.get();
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_scale(cr, px_per_mm, px_per_mm);
  cairo_translate(cr, style.margin_mm, style.margin_mm);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  if (style.pen_up_travel) {
    const double dash[] = {style.travel_dash_mm, style.travel_dash_mm};
    cairo_set_source_rgb(cr, kTravelGrey, kTravelGrey, kTravelGrey);
    cairo_set_line_width(cr, style.travel_line_width_mm);
    cairo_set_dash(cr, dash, 2, 0);
    draw_strokes(cr, strokes, style, false);
    cairo_set_dash(cr, nullptr, 0, 0);
  }
  cairo_set_line_width(cr, style.pen_width_mm);
  draw_strokes(cr, strokes, style, true);
  cairo_surface_flush(surface.get());
  if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(path + ": drawing failed: " + cairo_status_to_string(cairo_status(cr)));
  }
  const cairo_status_t written = cairo_surface_write_to_png(surface.get(), path.c_str());
  if (written != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(path + ": cannot write PNG: " + cairo_status_to_string(written));
  }
}

}  // namespace stepdance::sim
