// [output]: where the run's files go and which of them to write.
#include <filesystem>

#include "scenario/file_names.hpp"
#include "scenario/parse_context.hpp"

namespace stepdance::sim::scenario {

namespace {

/// A file name inside the output directory ("" = do not write; absolute names stay).
std::string output_file(const std::string& directory, const std::string& name) {
  if (name.empty()) return {};
  const std::filesystem::path given(name);
  return (given.is_absolute() ? given : std::filesystem::path(directory) / given).lexically_normal().string();
}

/// `vcd_ports`, and the refusal of a `vcd` that names none (it would be written empty).
void read_vcd_ports(TableReader& reader, const std::string& vcd, OutputConfig& output, ParseContext& context) {
  if (const toml::array* ports = reader.array("vcd_ports")) {
    for (const toml::node& item : *ports) {
      if (const auto* text = item.as_string()) {
        if (const auto line_ref = parse_port_line(text->get(), "vcd_ports", line_of(item), context)) {
          output.vcd_ports.push_back(*line_ref);
        }
      } else {
        context.reporter.error(line_of(item), "'vcd_ports' must hold strings like \"board:OUT_A\", not " +
                                                  std::string(type_phrase(item)));
      }
    }
  }
  // A VCD of no ports would be written, and empty: say what it needs instead.
  if (!vcd.empty() && output.vcd_ports.empty()) {
    reader.error("vcd", "'vcd' (\"" + vcd + "\") records the ports 'vcd_ports' lists, and it lists none: add "
                        "e.g. vcd_ports = [\"board:OUT_A\"] (or use --vcd FILE, which records every port)");
  }
}

}  // namespace

void read_output(TableReader& top, ParseContext& context) {
  OutputConfig& output = context.scenario.output;
  std::string directory = "sim-out";
  std::string svg = "drawing.svg";
  std::string png = "drawing.png";
  std::string vcd;
  std::string csv;
  std::string html;
  std::string summary = "summary.json";
  if (const toml::table* table = top.table("output")) {
    TableReader reader(*table, "[output]", context.reporter);
    if (const auto value = reader.string("directory")) {
      if (value->empty()) {
        reader.error("directory", "'directory' must not be empty (use \".\" for the scenario's folder)");
      } else {
        directory = *value;
      }
    }
    for (const auto& [key, target] : {std::pair<const char*, std::string*>{"svg", &svg},
                                {"png", &png},
                                {"vcd", &vcd},
                                {"csv", &csv},
                                {"html", &html},
                                {"summary", &summary}}) {
      const auto value = reader.string(key);
      if (!value) continue;
      if (const std::string problem = inside_path_problem(*value); !value->empty() && !problem.empty()) {
        reader.error(key, "'" + std::string(key) + "' (\"" + *value + "\") " + problem);
        continue;
      }
      *target = *value;
      output.lines[key] = reader.line_of(key);
    }
    if (const auto px = reader.number("png_px_per_mm", NumberRange{0, 100, true, "px/mm"})) output.png_px_per_mm = *px;
    if (const auto travel = reader.boolean("pen_up_travel")) output.pen_up_travel = *travel;
    if (const auto interval = reader.number("csv_interval_ms", ranges::kCsvIntervalMs)) {
      output.csv_interval_ms = *interval;
    }
    read_vcd_ports(reader, vcd, output, context);
    reader.finish();
  }
  output.directory = context.resolve(directory);
  output.svg = output_file(output.directory, svg);
  output.png = output_file(output.directory, png);
  output.vcd = output_file(output.directory, vcd);
  output.csv = output_file(output.directory, csv);
  output.html = output_file(output.directory, html);
  output.summary = output_file(output.directory, summary);
}

}  // namespace stepdance::sim::scenario
