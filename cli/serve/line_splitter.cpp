// LineSplitter: bytes → lines, bounded.
#include "board_link.hpp"

namespace stepdance::cli::serve {

void LineSplitter::feed(std::string_view bytes, const std::function<void(std::string_view)>& line) {
  for (char c : bytes) {
    if (c == '\n') {
      if (!discarding_) {
        if (!partial_.empty() && partial_.back() == '\r') partial_.pop_back();
        line(partial_);
      }
      partial_.clear();
      discarding_ = false;
    } else if (discarding_) {
      continue;
    } else if (partial_.size() < max_bytes_) {
      partial_ += c;
    } else {
      ++overlong_;
      line(partial_);
      partial_.clear();
      discarding_ = true;
    }
  }
}

}  // namespace stepdance::cli::serve
