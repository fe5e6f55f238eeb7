// The output hook for pictures (the pen drawing, device screens): the simulator library writes
// none itself; a front end that links the PNG module (png_picture_writer.hpp, cairo) hands one
// to the simulation (SimulationOptions::pictures).
#pragma once

#include <string>
#include <vector>

#include "output/drawing.hpp"

namespace stepdance::sim {

/// Writes pictures into files. Context: the end of a run (loop).
class PictureWriter {
 public:
  virtual ~PictureWriter() = default;
  /// The pen drawing at px_per_mm pixels per mm (within png_page.hpp's limits). Throws
  /// std::invalid_argument for a bad size and std::runtime_error("path: …") if writing fails.
  virtual void write_drawing(const std::string& path, const std::vector<Stroke>& strokes, const DrawingStyle& style,
                             double px_per_mm) const = 0;
  /// A monochrome screen of width × height pixels (row-major, true = lit), each `scale` px.
  /// Throws as write_drawing() does.
  virtual void write_screen(const std::string& path, const std::vector<bool>& lit, int width, int height,
                            int scale) const = 0;
};

}  // namespace stepdance::sim
