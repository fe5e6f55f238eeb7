// Folding console echo.
#include "console_echo.hpp"

#include <iostream>

#include "board/host/sim_board.hpp"

namespace stepdance::cli {

void ConsoleEcho::line(const std::string& board, const std::string& text) {
  // A piece of a longer line (BoardConsole hands one on every kLineBytes) is shown, never
  // folded: 20 × 5,000 `x` without a newline once showed as one piece and "the same line 23 more
  // times", read as 5,794 of 100,000 bytes.
  const bool piece = text.size() >= sim::BoardConsole::kLineBytes;
  if (!piece && board == last_board_ && text == last_text_) {
    ++repeats_;
    return;
  }
  flush();
  before_print_();
  std::cout << "[" << board << "] " << text << "\n";
  last_board_ = board;
  last_text_ = text;
}

void ConsoleEcho::flush() {
  if (repeats_ == 0) return;
  before_print_();
  std::cout << "[" << last_board_ << "] … the same line " << repeats_ << " more time" << (repeats_ == 1 ? "" : "s")
            << "\n";
  repeats_ = 0;
}

}  // namespace stepdance::cli
