// The replay page: the live view's page (web/view/) and a run's recording in one HTML file.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace stepdance::cli {

/// One self-contained HTML document: the view page's HTML with its style sheet, replay.js,
/// `recording` (sim/view/replay_recorder.hpp) and app.js inline, nothing fetched from anywhere.
/// Throws std::runtime_error if a built-in file is missing. Context: host, end of a run.
std::string replay_page_html(const nlohmann::json& recording);

}  // namespace stepdance::cli
