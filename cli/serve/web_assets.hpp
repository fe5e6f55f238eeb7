// The control page's files, built into the program (generated from cli/serve/web/ by CMake).
#pragma once

#include <string_view>

namespace stepdance::cli::serve {

struct WebAsset {
  std::string_view path;          ///< e.g. "/app.js"
  std::string_view content_type;  ///< e.g. "text/javascript; charset=utf-8"
  std::string_view body;
};

/// The file served at `path`, or null.
const WebAsset* find_web_asset(std::string_view path);

}  // namespace stepdance::cli::serve
