// stepdance-sketch-prep: writes the C++ file the Arduino IDE would make of a sketch's .ino files.
//
// Usage: stepdance-sketch-prep SKETCH OUTPUT.cpp
//   SKETCH is an .ino file or a sketch folder. Prints the sketch's other C and C++ sources (the
//   ones to compile beside OUTPUT.cpp), one per line. Used by scripts/build-teensy.sh, which
//   compiles this file with the host compiler on its own.
#include <cstdio>
#include <fstream>
#include <string>

#include "board/loader/sketch_sources.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s SKETCH OUTPUT.cpp\n", argv[0]);
    return 2;
  }
  stepdance::sim::SketchSources sources;
  std::string text;
  std::string error;
  if (!stepdance::sim::find_sketch_sources(argv[1], sources, error) ||
      !stepdance::sim::assemble_sketch_files(sources, text, error)) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  std::ofstream out(argv[2], std::ios::binary);
  out << text;
  if (!out.flush()) {
    std::fprintf(stderr, "%s: cannot write\n", argv[2]);
    return 1;
  }
  for (const std::string& file : sources.cpp_files) std::printf("%s\n", file.c_str());
  for (const std::string& file : sources.c_files) std::printf("%s\n", file.c_str());
  return 0;
}
