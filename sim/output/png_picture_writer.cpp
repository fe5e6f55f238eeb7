// PngPictureWriter: the PictureWriter hook filled by the cairo writers.
#include "output/png_picture_writer.hpp"

#include "output/png_writer.hpp"
#include "output/screen_png.hpp"

namespace stepdance::sim {

void PngPictureWriter::write_drawing(const std::string& path, const std::vector<Stroke>& strokes,
                                     const DrawingStyle& style, double px_per_mm) const {
  write_png(path, strokes, style, px_per_mm);
}

void PngPictureWriter::write_screen(const std::string& path, const std::vector<bool>& lit, int width, int height,
                                    int scale) const {
  write_screen_png(path, lit, width, height, scale);
}

std::shared_ptr<const PictureWriter> png_pictures() { return std::make_shared<PngPictureWriter>(); }

}  // namespace stepdance::sim
