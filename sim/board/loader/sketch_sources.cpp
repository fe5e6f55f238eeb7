// Sketch folders: which files belong to a sketch, and the IDE's concatenation of its .ino files.
#include "board/loader/sketch_sources.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "board/loader/sketch_prototypes.hpp"

namespace stepdance::sim {
namespace {

namespace fs = std::filesystem;

bool has_extension(const fs::path& path, std::initializer_list<const char*> extensions) {
  const std::string ext = path.extension().string();
  return std::any_of(extensions.begin(), extensions.end(), [&ext](const char* e) { return ext == e; });
}

// Regular files directly in `folder` (and, when `recurse`, below it), sorted by path.
std::vector<fs::path> files_in(const fs::path& folder, bool recurse) {
  std::vector<fs::path> files;
  std::error_code error;
  if (recurse) {
    for (const auto& entry : fs::recursive_directory_iterator(folder, error)) {
      if (entry.is_regular_file(error)) files.push_back(entry.path());
    }
  } else {
    for (const auto& entry : fs::directory_iterator(folder, error)) {
      if (entry.is_regular_file(error)) files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

void add_sources(const std::vector<fs::path>& files, SketchSources& sources, bool with_code) {
  for (const fs::path& file : files) {
    if (has_extension(file, {".h", ".hpp", ".hh"})) sources.headers.push_back(file.string());
    if (!with_code) continue;
    if (has_extension(file, {".cpp", ".cc", ".cxx"})) sources.cpp_files.push_back(file.string());
    if (has_extension(file, {".c"})) sources.c_files.push_back(file.string());
  }
}

// `path` quoted for a #line directive.
std::string quoted_path(const std::string& path) {
  std::string out = "\"";
  for (const char c : path) {
    if (c == '\\' || c == '"') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string line_directive(std::size_t line, const std::string& path) {
  return "#line " + std::to_string(line) + " " + quoted_path(path) + "\n";
}

// The text with each default argument's characters turned into spaces (newlines kept).
std::string without_default_arguments(std::string text, const SketchScan& scan) {
  for (const SketchFunction& function : scan.functions) {
    for (const auto& [begin, end] : function.default_arguments) {
      for (std::size_t i = begin; i < end; ++i) {
        if (text[i] != '\n') text[i] = ' ';
      }
    }
  }
  return text;
}

// The prototype block: each prototype under its own conditions and #line.
std::string prototypes(const std::vector<InoFile>& inos, const std::vector<SketchScan>& scans) {
  std::string out;
  for (std::size_t file = 0; file < inos.size(); ++file) {
    for (const SketchFunction& function : scans[file].functions) {
      for (const std::vector<std::string>& conditional : function.conditions) {
        for (const std::string& line : conditional) out += line + "\n";
      }
      out += line_directive(function.line, inos[file].path) + function.prototype + "\n";
      for (std::size_t i = 0; i < function.conditions.size(); ++i) out += "#endif\n";
    }
  }
  return out;
}

}  // namespace

bool find_sketch_sources(const std::string& path, SketchSources& sources, std::string& error) {
  std::error_code ec;
  fs::path main = fs::absolute(path, ec);
  if (fs::is_directory(main, ec)) main /= main.filename().string() + ".ino";
  if (!fs::is_regular_file(main, ec)) {
    error = path + ": sketch not found";
    return false;
  }
  sources = {};
  sources.folder = main.parent_path().string();
  sources.inos.push_back(main.string());
  const bool ide_folder = main.stem() == main.parent_path().filename();
  const std::vector<fs::path> beside = files_in(main.parent_path(), false);
  for (const fs::path& file : beside) {
    if (ide_folder && has_extension(file, {".ino"}) && file != main) sources.inos.push_back(file.string());
  }
  add_sources(beside, sources, ide_folder);
  if (fs::is_directory(main.parent_path() / "src", ec))
    add_sources(files_in(main.parent_path() / "src", true), sources, ide_folder);
  return true;
}

std::string assemble_sketch(const std::vector<InoFile>& inos) {
  std::vector<SketchScan> scans;
  scans.reserve(inos.size());
  for (const InoFile& ino : inos) scans.push_back(scan_sketch_functions(ino.text));
  const auto first_with_functions =
      std::find_if(scans.begin(), scans.end(), [](const SketchScan& scan) { return !scan.functions.empty(); });
  const std::size_t insertion_file = static_cast<std::size_t>(first_with_functions - scans.begin());

  std::string out = "#include <Arduino.h>\n";
  for (std::size_t file = 0; file < inos.size(); ++file) {
    std::string text = without_default_arguments(inos[file].text, scans[file]);
    if (!text.empty() && text.back() != '\n') text += '\n';
    out += line_directive(1, inos[file].path);
    if (file != insertion_file) {
      out += text;
      continue;
    }
    const SketchScan& scan = scans[file];
    out += text.substr(0, scan.insertion_offset);
    if (scan.insertion_column > 0) out += "\n";  // mid-line: the prototypes start a line of their own
    out += prototypes(inos, scans);
    out += line_directive(scan.insertion_line, inos[file].path);
    out += std::string(scan.insertion_column, ' ') + text.substr(scan.insertion_offset);
  }
  return out;
}

bool assemble_sketch_files(const SketchSources& sources, std::string& text, std::string& error) {
  std::vector<InoFile> inos;
  for (const std::string& path : sources.inos) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
      error = path + ": cannot read the sketch file";
      return false;
    }
    std::ostringstream content;
    content << in.rdbuf();
    inos.push_back({path, content.str()});
  }
  text = assemble_sketch(inos);
  return true;
}

}  // namespace stepdance::sim
