// SVG writer: text assembled directly so the bytes depend only on the strokes and the style.
#include "output/svg_writer.hpp"

#include "output/number_format.hpp"
#include "output/text_file.hpp"

namespace stepdance::sim {
namespace {

constexpr int kDecimals = 3;

std::string number(double value) { return format_trimmed(value, kDecimals); }

/// "#rrggbb" of an sRGB colour.
std::string hex(const Rgb& colour) {
  static const char kDigits[] = "0123456789abcdef";
  std::string text = "#";
  for (double channel : {colour.r, colour.g, colour.b}) {
    const int value = static_cast<int>(channel * 255 + 0.5);
    text += kDigits[value / 16];
    text += kDigits[value % 16];
  }
  return text;
}

void append_polyline(std::string& out, const Stroke& stroke, const DrawingStyle& style) {
  out += "<polyline";
  if (stroke.shade) out += " stroke=\"" + hex(style.colour_of(stroke)) + "\"";
  out += " points=\"";
  for (size_t i = 0; i < stroke.points.size(); ++i) {
    if (i > 0) out += ' ';
    out += number(stroke.points[i].x) + "," + number(stroke.points[i].y);
  }
  if (stroke.points.size() == 1) out += " " + number(stroke.points[0].x) + "," + number(stroke.points[0].y);
  out += "\"/>\n";
}

void append_group(std::string& out, const std::vector<Stroke>& strokes, const DrawingStyle& style, bool pen_down,
                  const std::string& attributes) {
  bool any = false;
  for (const Stroke& stroke : strokes) any = any || (stroke.pen_down == pen_down && !stroke.points.empty());
  if (!any) return;
  out += "<g " + attributes + ">\n";
  for (const Stroke& stroke : strokes) {
    if (stroke.pen_down == pen_down && !stroke.points.empty()) append_polyline(out, stroke, style);
  }
  out += "</g>\n";
}

}  // namespace

std::string svg_document(const std::vector<Stroke>& strokes, const DrawingStyle& style) {
  const std::string width = number(style.page_width_mm());
  const std::string height = number(style.page_height_mm());
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + width + "mm\" height=\"" + height +
         "mm\" viewBox=\"0 0 " + width + " " + height + "\">\n";
  if (!style.shade_name.empty()) {
    out += "<desc>Pen-down strokes coloured by " + style.shade_name + ": blue " + format_trimmed(style.shade_low, 4) +
           ", green " + format_trimmed((style.shade_low + style.shade_high) / 2, 4) + ", red " +
           format_trimmed(style.shade_high, 4) + " (outside: the nearest end).</desc>\n";
  }
  out += "<rect width=\"" + width + "\" height=\"" + height + "\" fill=\"white\"/>\n";
  out += "<g transform=\"translate(" + number(style.margin_mm) + " " + number(style.margin_mm) +
         ")\" fill=\"none\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
  if (style.pen_up_travel) {
    append_group(out, strokes, style, false,
                 "stroke=\"#999999\" stroke-width=\"" + number(style.travel_line_width_mm) + "\" stroke-dasharray=\"" +
                     number(style.travel_dash_mm) + " " + number(style.travel_dash_mm) + "\"");
  }
  append_group(out, strokes, style, true, "stroke=\"black\" stroke-width=\"" + number(style.pen_width_mm) + "\"");
  out += "</g>\n</svg>\n";
  return out;
}

void write_svg(const std::string& path, const std::vector<Stroke>& strokes, const DrawingStyle& style) {
  write_text_file(path, svg_document(strokes, style));
}

}  // namespace stepdance::sim
