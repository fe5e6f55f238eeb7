// Prints what sketches write on Serial, folding runs of identical lines into one count.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

namespace stepdance::cli {

/// Echoes `[board] line` to stdout. A line that repeats the previous one of the same board is
/// held back and counted; the count is printed (`[board] … 41 more times`) when a different
/// line comes or at flush(), so a sketch that reports every second does not flood the terminal.
/// The pieces of a line longer than BoardConsole::kLineBytes are all shown, in order.
class ConsoleEcho {
 public:
  /// `before_print` runs before anything is printed (e.g. to erase a progress bar).
  explicit ConsoleEcho(std::function<void()> before_print) : before_print_(std::move(before_print)) {}
  /// One line the sketch on `board` printed.
  void line(const std::string& board, const std::string& text);
  /// Prints a pending repeat count.
  void flush();

 private:
  std::function<void()> before_print_;
  std::string last_board_;
  std::string last_text_;
  uint64_t repeats_ = 0;
};

}  // namespace stepdance::cli
