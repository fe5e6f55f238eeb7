// Folding console echo.
#include "console_echo.hpp"

#include <iostream>

namespace stepdance::cli {

void ConsoleEcho::line(const std::string& board, const std::string& text) {
  if (board == last_board_ && text == last_text_) {
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
