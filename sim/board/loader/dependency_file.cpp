// parse_dependency_text: line continuations joined, then words split at unescaped blanks.
#include "board/loader/dependency_file.hpp"

#include <fstream>
#include <set>
#include <sstream>

namespace stepdance::sim {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/// The words of one logical line, unescaped, with whether each ends a target (a ':' after it).
struct Word {
  std::string text;
  bool target = false;
};

std::vector<Word> words_of(std::string_view line) {
  std::vector<Word> words;
  std::string word;
  const auto finish = [&words, &word](bool target) {
    if (!word.empty() || target) words.push_back({word, target});
    word.clear();
  };
  for (std::size_t at = 0; at < line.size(); ++at) {
    const char c = line[at];
    const char next = at + 1 < line.size() ? line[at + 1] : '\0';
    if (c == '\\' && (next == ' ' || next == '#' || next == '\\')) {
      word += next;
      ++at;
    } else if (c == '$' && next == '$') {
      word += '$';
      ++at;
    } else if (c == ':' && (next == '\0' || is_blank(next))) {
      finish(true);
    } else if (is_blank(c)) {
      finish(false);
    } else {
      word += c;
    }
  }
  finish(false);
  return words;
}

}  // namespace

std::vector<std::string> parse_dependency_text(std::string_view text) {
  std::vector<std::string> files;
  std::set<std::string> seen;
  std::string line;
  for (std::size_t at = 0; at <= text.size(); ++at) {
    const char c = at < text.size() ? text[at] : '\n';
    if (c == '\\' && at + 1 < text.size() && text[at + 1] == '\n') {
      line += ' ';  // a continuation joins the next line
      ++at;
      continue;
    }
    if (c != '\n') {
      line += c;
      continue;
    }
    // A rule: targets, then ':' and its prerequisites.
    bool after_colon = false;
    for (const Word& word : words_of(line)) {
      if (word.target) {
        after_colon = true;
        continue;
      }
      if (after_colon && seen.insert(word.text).second) files.push_back(word.text);
    }
    line.clear();
  }
  return files;
}

bool read_dependency_file(const std::string& path, std::vector<std::string>& files) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream text;
  text << in.rdbuf();
  files = parse_dependency_text(text.str());
  return true;
}

}  // namespace stepdance::sim
