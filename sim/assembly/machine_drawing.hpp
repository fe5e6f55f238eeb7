// The machine's drawing as the SVG and PNG show it: its pen-down polylines cut into shaded pieces,
// its pen-up moves, on the machine's page (a plotter's travel area, or the drawing's bounding box).
#pragma once

#include <vector>

#include "models/machine.hpp"
#include "output/drawing.hpp"
#include "scenario/scenario.hpp"

namespace stepdance::sim {

/// Fills `strokes` with `machine`'s drawing as it stands, on the page of `config`'s kind, and
/// returns its style (page size, shade scale, whether pen-up moves show). Context: host.
DrawingStyle machine_drawing(const Machine& machine, const scenario::MachineConfig& config, bool pen_up_travel,
                             std::vector<Stroke>& strokes);

}  // namespace stepdance::sim
