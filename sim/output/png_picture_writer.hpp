// The PNG module: pictures written as PNG files with cairo (linked by the command line and the
// tests, not by the simulator library).
#pragma once

#include <memory>

#include "output/picture_writer.hpp"

namespace stepdance::sim {

/// Writes the drawing with write_png() and screens with write_screen_png().
class PngPictureWriter : public PictureWriter {
 public:
  void write_drawing(const std::string& path, const std::vector<Stroke>& strokes, const DrawingStyle& style,
                     double px_per_mm) const override;
  void write_screen(const std::string& path, const std::vector<bool>& lit, int width, int height,
                    int scale) const override;
};

/// The writer a front end hands to SimulationOptions::pictures.
std::shared_ptr<const PictureWriter> png_pictures();

}  // namespace stepdance::sim
