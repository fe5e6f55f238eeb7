# stepdance_embed_text(input output symbol): writes a header holding a text file as a C++ string
# constant (stepdance::workloads::<symbol>), so host and target benchmarks replay a recorded stream
# without a file system. CMake re-runs, and rewrites the header, when the file changes.
function(stepdance_embed_text input output symbol)
  file(READ "${input}" text)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${input}")
  file(CONFIGURE OUTPUT "${output}" @ONLY CONTENT
"// Generated from ${input} by cmake/embed_text.cmake: do not edit.
#pragma once
namespace stepdance::workloads {
inline constexpr char ${symbol}[] = R\"embedded(${text})embedded\";
}  // namespace stepdance::workloads
")
endfunction()
