// Renders a monochrome screen (the simulated OLED) to a PNG with cairo.
#pragma once

#include <string>
#include <vector>

namespace stepdance::sim {

/// Draws width × height pixels (row-major, true = lit) as squares of `scale` px with a one-pixel
/// gap, lit pixels light blue-white on a black panel with a `scale`-pixel border, into an RGB
/// PNG at `path`. Throws std::invalid_argument for an empty picture or scale outside 1..32 and
/// std::runtime_error("path: …") if writing fails.
void write_screen_png(const std::string& path, const std::vector<bool>& lit, int width, int height, int scale);

}  // namespace stepdance::sim
