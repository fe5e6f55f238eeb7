// SimulatedBoardLink: wall-clock pacing, console exchange and drawing updates.
#include "simulated_board_link.hpp"

#include <algorithm>
#include <stdexcept>

namespace stepdance::cli::serve {
namespace {

using SteadyClock = std::chrono::steady_clock;
/// Simulated time between exchanges with the page: 1 ms, about a USB full-speed frame.
constexpr sim::SimTime kExchangeNs = sim::kMillisecond;
/// Wall time one tick may spend simulating, so the server stays responsive when the run is slow.
constexpr std::chrono::milliseconds kMaxTickWork{20};
/// Farther behind than this, the run gives up catching up and goes on from now (slower than real time).
constexpr sim::SimTime kMaxLagNs = 200 * sim::kMillisecond;

nlohmann::json point_json(const sim::PenPoint& point) { return nlohmann::json::array({point.x_mm, point.y_mm}); }

}  // namespace

SimulatedBoardLink::SimulatedBoardLink(boost::asio::io_context& io, sim::Simulation& simulation,
                                       const std::string& board, double speed)
    : timer_(io), simulation_(simulation), board_(simulation.board(board)), board_name_(board), speed_(speed) {
  if (board_ == nullptr) throw std::runtime_error("--board: no board named '" + board + "'");
  board_->console().on_bytes([this](const uint8_t* data, size_t length) {
    lines_.feed(std::string_view(reinterpret_cast<const char*>(data), length), [this](std::string_view line) {
      if (on_line_) on_line_(line);
    });
  });
  wall_start_ = SteadyClock::now();
  next_drawing_ = wall_start_;
  sim_start_ = simulation_.now();
  schedule();
}

void SimulatedBoardLink::send(const std::string& bytes) { to_board_ += bytes; }

void SimulatedBoardLink::stop() {
  stopped_ = true;
  timer_.cancel();
  if (!to_board_.empty()) board_->console().send(to_board_);
  to_board_.clear();
  board_->console().on_bytes(nullptr);
}

void SimulatedBoardLink::schedule() {
  timer_.expires_after(kTickPeriod);
  timer_.async_wait([this](const boost::system::error_code& error) {
    if (!error && !stopped_) tick();
  });
}

void SimulatedBoardLink::tick() {
  const auto now = SteadyClock::now();
  const double elapsed_s = std::chrono::duration<double>(now - wall_start_).count();
  const sim::SimTime target = std::min(sim_start_ + sim::from_seconds(elapsed_s * speed_), simulation_.duration());
  while (simulation_.now() < target && SteadyClock::now() - now < kMaxTickWork) {
    if (!to_board_.empty()) board_->console().send(to_board_);
    to_board_.clear();
    simulation_.run_until(simulation_.now() + kExchangeNs);
  }
  if (!to_board_.empty()) board_->console().send(to_board_);  // the next step reads it
  to_board_.clear();
  if (target - simulation_.now() > kMaxLagNs) {  // too slow for real time: go on from here
    wall_start_ = SteadyClock::now();
    sim_start_ = simulation_.now();
  }
  if (now >= next_drawing_ && on_drawing_ && simulation_.machine() != nullptr) {
    next_drawing_ = now + kDrawingPeriod;
    on_drawing_(drawing_update());
  }
  schedule();
}

nlohmann::json SimulatedBoardLink::drawing_update() {
  const sim::Machine& machine = *simulation_.machine();
  const std::vector<sim::Polyline>& strokes = machine.strokes();
  nlohmann::json chunks = nlohmann::json::array();
  size_t budget = kMaxPointsPerUpdate;
  while (strokes_sent_ < strokes.size() && budget > 0) {
    const sim::Polyline& stroke = strokes[strokes_sent_];
    const size_t from = points_sent_ > 0 ? points_sent_ - 1 : 0;  // the last point may have moved
    const size_t to = std::min(stroke.size(), from + budget);
    nlohmann::json points = nlohmann::json::array();
    for (size_t i = from; i < to; ++i) points.push_back(point_json(stroke[i]));
    chunks.push_back({{"index", strokes_sent_}, {"from", from}, {"points", std::move(points)}});
    budget -= std::min(budget, to - from);
    points_sent_ = to;
    if (to < stroke.size() || strokes_sent_ + 1 == strokes.size()) break;  // more later / still growing
    ++strokes_sent_;
    points_sent_ = 0;
  }
  return {{"drawing",
           {{"pen", point_json(machine.pen_position())},
            {"down", machine.pen_down()},
            {"t", sim::to_seconds(simulation_.now())},
            {"strokes", std::move(chunks)}}}};
}

nlohmann::json SimulatedBoardLink::machine_description() const {
  nlohmann::json machine = {{"board", board_name_}, {"simulated", true}};
  if (const sim::Machine* model = simulation_.machine(); model != nullptr && model->travel() != nullptr) {
    const sim::TravelArea& area = model->travel()->area();
    machine["area_mm"] = {area.x_min_mm, area.x_max_mm, area.y_min_mm, area.y_max_mm};
  }
  return {{"machine", machine}};
}

}  // namespace stepdance::cli::serve
