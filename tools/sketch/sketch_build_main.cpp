// stepdance-sketch-build: builds sketches exactly as `stepdance sim` does and reports each one.
//
// Usage: stepdance-sketch-build [--quiet] SKETCH...
//   SKETCH is an .ino file or a sketch folder. Prints "ok  SKETCH" or "FAIL SKETCH" per sketch,
//   followed (unless --quiet) by the compiler's messages for a failure. Exit status 0 if every
//   sketch built, 1 otherwise, 2 on a usage error. The sketch cache is the simulator's
//   (SketchBuilder::default_cache_dir()).
#include <cstdio>
#include <cstring>
#include <string>

#include "board/loader/sketch_builder.hpp"

int main(int argc, char** argv) {
  bool quiet = false;
  int first = 1;
  if (argc > 1 && std::strcmp(argv[1], "--quiet") == 0) {
    quiet = true;
    first = 2;
  }
  if (first >= argc) {
    std::fprintf(stderr, "usage: %s [--quiet] SKETCH...\n", argv[0]);
    return 2;
  }
  const stepdance::sim::SketchBuilder builder;
  int failures = 0;
  for (int i = first; i < argc; ++i) {
    const stepdance::sim::SketchBuild build = builder.build(argv[i]);
    std::printf("%s %s\n", build.ok ? "ok  " : "FAIL", argv[i]);
    if (!build.ok) {
      ++failures;
      if (!quiet) std::printf("%s\n", build.error.c_str());
    }
    std::fflush(stdout);
  }
  return failures == 0 ? 0 : 1;
}
