// The run as a page following the view protocol keeps it: each update's parts merged in order.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace stepdance::sim::view::page_test {

/// What a page knows after the updates it was given (docs/simulator.md, "The view protocol",
/// version 2): an update's parts replace the page's, keyed parts (motors by board and port,
/// boards by name, screens and arms by device) one by one; strokes keep `from` points and
/// append; console text is appended. Written from the protocol's text, not from ViewSession.
struct PageModel {
  double t_s = -1;
  nlohmann::json run, pen, table, shade_scale, travel;
  std::map<std::string, nlohmann::json> motors, boards, screens, arms;
  std::vector<std::vector<std::pair<double, double>>> strokes;
  std::map<std::string, std::string> console;

  void apply(const nlohmann::json& update) {
    t_s = update.at("t_s").get<double>();
    for (const char* key : {"run", "pen", "table", "shade_scale", "travel"}) {
      if (update.contains(key)) part(key) = update[key];
    }
    for (const nlohmann::json& motor : update.value("motors", nlohmann::json::array())) {
      motors[motor["board"].get<std::string>() + " " + motor["port"].get<std::string>()] = motor;
    }
    for (const nlohmann::json& board : update.value("boards", nlohmann::json::array())) boards[board["name"]] = board;
    for (const nlohmann::json& screen : update.value("screens", nlohmann::json::array()))
      screens[screen["device"]] = screen;
    for (const nlohmann::json& arm : update.value("arms", nlohmann::json::array())) arms[arm["device"]] = arm;
    for (const nlohmann::json& stroke : update.value("strokes", nlohmann::json::array())) {
      const size_t index = stroke["i"];
      if (strokes.size() <= index) strokes.resize(index + 1);
      strokes[index].resize(stroke["from"].get<size_t>());
      for (const nlohmann::json& point : stroke["points"]) strokes[index].emplace_back(point[0], point[1]);
    }
    for (const nlohmann::json& output : update.value("console", nlohmann::json::array())) {
      console[output["board"]] += output["text"].get<std::string>();
    }
  }

  /// Everything but the console (which a new page never gets again), t_s and the motors' rates
  /// (a rate is over the time since the page's previous update, which a new page does not have).
  bool same_state(const PageModel& other) const {
    return run == other.run && pen == other.pen && table == other.table && shade_scale == other.shade_scale &&
           travel == other.travel && steps() == other.steps() && boards == other.boards && screens == other.screens &&
           arms == other.arms && strokes == other.strokes;
  }
  std::map<std::string, int64_t> steps() const {
    std::map<std::string, int64_t> result;
    for (const auto& [key, motor] : motors) result[key] = motor["steps"];
    return result;
  }

 private:
  nlohmann::json& part(const std::string& key) {
    if (key == "run") return run;
    if (key == "pen") return pen;
    if (key == "table") return table;
    if (key == "travel") return travel;
    return shade_scale;
  }
};

}  // namespace stepdance::sim::view::page_test
