// A sketch folder as the Arduino IDE sees it, and the one C++ file the IDE makes of its .ino files.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace stepdance::sim {

/// The files that make up one sketch.
struct SketchSources {
  std::string folder;                  ///< absolute path of the sketch's folder
  std::vector<std::string> inos;       ///< the main .ino first, then the others alphabetically
  std::vector<std::string> cpp_files;  ///< .cpp/.cc/.cxx beside it and under src/, sorted
  std::vector<std::string> c_files;    ///< .c beside it and under src/, sorted
  std::vector<std::string> headers;    ///< .h/.hpp/.hh beside it and under src/, sorted (for hashing)
};

/// Finds the sources of the sketch at `path` (an .ino file, or a folder holding <folder>.ino).
/// When the .ino is named after its folder (`Blink/Blink.ino`), the folder is an IDE sketch:
/// every .ino in it is part of the sketch and every C/C++ file beside it or under its src/
/// folder is compiled with it. Any other .ino is a sketch on its own, with only its headers.
/// Returns false and sets `error` if there is no such sketch. Context: loop (reads the disk).
bool find_sketch_sources(const std::string& path, SketchSources& sources, std::string& error);

/// One .ino's name (used in #line directives and so in compiler messages) and text.
struct InoFile {
  std::string path;
  std::string text;
};

/// The translation unit the Arduino IDE builds from a sketch's .ino files, in order: Arduino.h
/// included, then each file under a #line directive so messages name the .ino and its lines,
/// with a prototype for every function defined at file scope inserted (under that function's
/// #if conditions, each with its own #line) before the first function definition. Default
/// arguments move from the definitions (blanked, so columns stay put) to the prototypes.
/// Context: any thread (pure function).
std::string assemble_sketch(const std::vector<InoFile>& inos);

/// Reads the .ino files of `sources` and assembles them. Returns false and sets `error` if one
/// cannot be read. Context: loop (reads the disk).
bool assemble_sketch_files(const SketchSources& sources, std::string& text, std::string& error);

}  // namespace stepdance::sim
