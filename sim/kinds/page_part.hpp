// A device's or a machine's own part of the live view's messages: what a kind shows on the page,
// given by the kind, so that the view (sim/view/) names no kind and no model.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace stepdance::sim {

/// One part of an `update` message (docs/simulator.md, "The view protocol"). `field` is the
/// update's key and the page's part type: the page draws each field its own way ("screens": an
/// OLED picture, "arms": a linkage, "table": a turntable) and shows a field it does not know as
/// text next to its device. A device's part is one entry of the array `field` and names the
/// device in its "device" key; a machine's part is the object `field` itself. The view sends a
/// part again only when its value changes. A field is never one of the update's own keys (`type`,
/// `t_s`, `run`, `pen`, `strokes`, `shade_scale`, `travel`, `motors`, `boards`, `console`).
struct PagePart {
  std::string field;
  nlohmann::json value;
};

using PageParts = std::vector<PagePart>;

}  // namespace stepdance::sim
