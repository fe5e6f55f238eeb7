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
        context.reporter.error(
            line_of(item), "'vcd_ports' must hold strings like \"board:OUT_A\", not " + std::string(type_phrase(item)));
      }
    }
  }
  // A VCD of no ports would be written, and empty: say what it needs instead.
  if (!vcd.empty() && output.vcd_ports.empty()) {
    reader.error("vcd", "'vcd' (\"" + vcd +
                            "\") records the ports 'vcd_ports' lists, and it lists none: add "
                            "e.g. vcd_ports = [\"board:OUT_A\"] (or use --vcd FILE, which records every port)");
  }
}

/// The names [output] gives: its folder, and each file in it ("" = not written).
struct OutputNames {
  std::string directory = "sim-out";
  std::string svg = "drawing.svg";
  std::string png = "drawing.png";
  std::string vcd;
  std::string csv;
  std::string html;
  std::string summary = "summary.json";
};

/// directory, and each file key: a path inside the output folder (its line kept in output.lines).
void read_file_names(TableReader& reader, OutputNames& names, OutputConfig& output) {
  if (const auto value = reader.string("directory")) {
    if (value->empty()) {
      reader.error("directory", "'directory' must not be empty (use \".\" for the scenario's folder)");
    } else {
      names.directory = *value;
    }
  }
  for (const auto& [key, target] : {std::pair<const char*, std::string*>{"svg", &names.svg},
                                    {"png", &names.png},
                                    {"vcd", &names.vcd},
                                    {"csv", &names.csv},
                                    {"html", &names.html},
                                    {"summary", &names.summary}}) {
    const auto value = reader.string(key);
    if (!value) continue;
    if (const std::string problem = inside_path_problem(*value); !value->empty() && !problem.empty()) {
      reader.error(key, "'" + std::string(key) + "' (\"" + *value + "\") " + problem);
      continue;
    }
    *target = *value;
    output.lines[key] = reader.line_of(key);
  }
}

/// The [output] table: the names, the drawing and CSV settings, and the VCD's ports.
void read_output_table(const toml::table& table, OutputNames& names, ParseContext& context) {
  OutputConfig& output = context.scenario.output;
  TableReader reader(table, "[output]", context.reporter);
  read_file_names(reader, names, output);
  if (const auto px = reader.number("png_px_per_mm", NumberRange{0, 100, true, "px/mm"})) output.png_px_per_mm = *px;
  if (const auto travel = reader.boolean("pen_up_travel")) output.pen_up_travel = *travel;
  if (const auto interval = reader.number("csv_interval_ms", ranges::kCsvIntervalMs)) {
    output.csv_interval_ms = *interval;
  }
  read_vcd_ports(reader, names.vcd, output, context);
  reader.finish();
}

}  // namespace

void read_output(TableReader& top, ParseContext& context) {
  OutputConfig& output = context.scenario.output;
  OutputNames names;
  if (const toml::table* table = top.table("output")) read_output_table(*table, names, context);
  output.directory = context.resolve(names.directory);
  output.svg = output_file(output.directory, names.svg);
  output.png = output_file(output.directory, names.png);
  output.vcd = output_file(output.directory, names.vcd);
  output.csv = output_file(output.directory, names.csv);
  output.html = output_file(output.directory, names.html);
  output.summary = output_file(output.directory, names.summary);
}

}  // namespace stepdance::sim::scenario
