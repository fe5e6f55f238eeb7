# The simulator library's dependencies in the WebAssembly build. Debian's nlohmann-json3-dev and
# libtomlplusplus-dev are headers the wasm compiler can read too, but their CMake packages (and
# toml++'s shared library) are the host's: this exposes the two header folders alone, and toml++
# header-only. RE2 has no wasm build here: the scenario reader uses line_pattern_ecmascript.cpp.
set(web_include_dir ${PROJECT_BINARY_DIR}/web-include)
file(MAKE_DIRECTORY ${web_include_dir})
foreach(header_dir nlohmann toml++)
  if(NOT EXISTS /usr/include/${header_dir})
    message(FATAL_ERROR "/usr/include/${header_dir} is missing: run scripts/setup.sh")
  endif()
  file(CREATE_LINK /usr/include/${header_dir} ${web_include_dir}/${header_dir} SYMBOLIC)
endforeach()

add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED)
target_include_directories(nlohmann_json::nlohmann_json SYSTEM INTERFACE ${web_include_dir})
add_library(tomlplusplus::tomlplusplus INTERFACE IMPORTED)
target_include_directories(tomlplusplus::tomlplusplus SYSTEM INTERFACE ${web_include_dir})
target_compile_definitions(tomlplusplus::tomlplusplus INTERFACE TOML_HEADER_ONLY=1)
# toml++ reports parse errors by exception, caught in the scenario reader: that library alone is
# compiled with exceptions. Elsewhere emscripten's JavaScript-based exceptions would put a
# trampoline through JavaScript around every call that may unwind, the simulation's hot path
# included.
target_compile_options(tomlplusplus::tomlplusplus INTERFACE -fexceptions)
add_library(PkgConfig::RE2 INTERFACE IMPORTED)
