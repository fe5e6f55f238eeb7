// VcdTokenizer: a chunk buffer, line counting byte by byte, tokens bounded in length.
#include "decode/vcd_tokenizer.hpp"

namespace stepdance::sim {

bool VcdTokenizer::fill() {
  if (pos_ < end_) return true;
  in_.read(chunk_.data(), static_cast<std::streamsize>(chunk_.size()));
  pos_ = 0;
  end_ = static_cast<std::size_t>(in_.gcount());
  if (end_ > 0) return true;
  cut_ = bytes_since_newline_;
  return false;
}

void VcdTokenizer::advance() {
  if (chunk_[pos_] == '\n') {
    ++newlines_;
    bytes_since_newline_ = false;
  } else {
    bytes_since_newline_ = true;
  }
  ++pos_;
}

bool VcdTokenizer::next(VcdToken& token) {
  while (fill() && is_space(chunk_[pos_])) advance();
  if (pos_ >= end_) return false;
  token.text.clear();
  token.line = newlines_ + 1;
  while (fill() && !is_space(chunk_[pos_])) {
    std::size_t stop = pos_;  // the token's bytes in this chunk (never a newline)
    while (stop < end_ && !is_space(chunk_[stop])) ++stop;
    if (token.text.size() + (stop - pos_) > kMaxTokenBytes) {
      too_long_ = true;
      too_long_line_ = token.line;
      return false;
    }
    token.text.append(chunk_.data() + pos_, stop - pos_);
    bytes_since_newline_ = true;
    pos_ = stop;
  }
  token.cut = pos_ >= end_ && cut_;  // ended by the end of a file whose last line has no newline
  return true;
}

void VcdTokenizer::skip_line() {
  while (fill() && chunk_[pos_] != '\n') advance();
}

std::size_t VcdTokenizer::line() const {
  if (too_long_) return too_long_line_;
  const std::size_t started = lines_started();
  return started == 0 ? 1 : started;
}

}  // namespace stepdance::sim
