// The prototype scanner: a small C++ lexer and a file-scope pass that recognises function definitions.
#include "board/loader/sketch_prototypes.hpp"

#include <algorithm>
#include <cctype>
#include <string>

namespace stepdance::sim {
namespace {

enum class TokenKind { kIdentifier, kNumber, kLiteral, kPunct, kDirective };

struct Token {
  TokenKind kind;
  std::size_t begin;
  std::size_t end;
};

bool is_identifier_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool is_identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Splits source text into tokens; comments and whitespace are dropped, each preprocessor
// directive (with its continuation lines) is one token.
class Lexer {
 public:
  explicit Lexer(std::string_view text) : text_(text) {}

  std::vector<Token> tokens() {
    std::vector<Token> out;
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        line_start_ = true;
        ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        ++pos_;
      } else if (starts_with("//")) {
        skip_line_comment();
      } else if (starts_with("/*")) {
        skip_block_comment();
      } else if (c == '#' && line_start_) {
        out.push_back(directive());
      } else {
        line_start_ = false;
        out.push_back(token());
      }
    }
    return out;
  }

 private:
  bool starts_with(std::string_view prefix) const { return text_.substr(pos_, prefix.size()) == prefix; }

  void skip_line_comment() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  }

  void skip_block_comment() {
    const std::size_t close = text_.find("*/", pos_ + 2);
    pos_ = close == std::string_view::npos ? text_.size() : close + 2;
  }

  // A directive runs to the first newline not escaped by a backslash.
  Token directive() {
    const std::size_t begin = pos_;
    while (pos_ < text_.size() && text_[pos_] != '\n') {
      if (text_[pos_] == '\\' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n') {
        pos_ += 2;
      } else if (starts_with("/*")) {
        skip_block_comment();
      } else if (starts_with("//")) {
        skip_line_comment();
      } else {
        ++pos_;
      }
    }
    return {TokenKind::kDirective, begin, pos_};
  }

  Token token() {
    const std::size_t begin = pos_;
    const char c = text_[pos_];
    if (is_identifier_start(c)) return identifier_or_prefixed_literal(begin);
    if (std::isdigit(static_cast<unsigned char>(c)) ||
        (c == '.' && pos_ + 1 < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_ + 1])))) {
      return number(begin);
    }
    if (c == '"' || c == '\'') {
      quoted(c);
      return {TokenKind::kLiteral, begin, pos_};
    }
    pos_ += (starts_with("::") || starts_with("->")) ? 2 : 1;
    return {TokenKind::kPunct, begin, pos_};
  }

  Token identifier_or_prefixed_literal(std::size_t begin) {
    while (pos_ < text_.size() && is_identifier_char(text_[pos_])) ++pos_;
    const std::string_view word = text_.substr(begin, pos_ - begin);
    if (pos_ < text_.size() && (text_[pos_] == '"' || text_[pos_] == '\'')) {
      static constexpr std::string_view kPrefixes[] = {"L", "u", "U", "u8", "R", "LR", "uR", "UR", "u8R"};
      if (std::find(std::begin(kPrefixes), std::end(kPrefixes), word) != std::end(kPrefixes)) {
        if (word.back() == 'R' && text_[pos_] == '"') {
          raw_string();
        } else {
          quoted(text_[pos_]);
        }
        return {TokenKind::kLiteral, begin, pos_};
      }
    }
    return {TokenKind::kIdentifier, begin, pos_};
  }

  // A pp-number: digits, letters, '.', digit separators and exponent signs.
  Token number(std::size_t begin) {
    ++pos_;
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      const char previous = text_[pos_ - 1];
      const bool exponent_sign =
          (c == '+' || c == '-') && (previous == 'e' || previous == 'E' || previous == 'p' || previous == 'P');
      const bool separator = c == '\'' && pos_ + 1 < text_.size() && is_identifier_char(text_[pos_ + 1]);
      if (!(is_identifier_char(c) || c == '.' || exponent_sign || separator)) break;
      ++pos_;
    }
    return {TokenKind::kNumber, begin, pos_};
  }

  // "..." or '...', with escapes; an unterminated literal ends at the line's end.
  void quoted(char quote) {
    ++pos_;
    while (pos_ < text_.size() && text_[pos_] != quote && text_[pos_] != '\n') {
      pos_ += (text_[pos_] == '\\' && pos_ + 1 < text_.size()) ? 2 : 1;
    }
    if (pos_ < text_.size() && text_[pos_] == quote) ++pos_;
  }

  // R"delimiter( ... )delimiter"
  void raw_string() {
    const std::size_t open = text_.find('(', pos_);
    if (open == std::string_view::npos) {
      pos_ = text_.size();
      return;
    }
    const std::string closing = ")" + std::string(text_.substr(pos_ + 1, open - pos_ - 1)) + "\"";
    const std::size_t close = text_.find(closing, open);
    pos_ = close == std::string_view::npos ? text_.size() : close + closing.size();
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  bool line_start_ = true;
};

// Words that may be followed by '(' without being the function's name.
bool is_non_name_word(std::string_view word) {
  static constexpr std::string_view kWords[] = {
      "__attribute__", "__declspec", "alignas",    "decltype", "sizeof", "alignof", "noexcept",
      "throw",         "operator",   "if",         "while",    "for",    "switch",  "return",
      "static_assert", "typeof",     "__typeof__", "_Pragma",  "asm",    "__asm__", "catch"};
  return std::find(std::begin(kWords), std::end(kWords), word) != std::end(kWords);
}

// The directive's keyword: "if", "ifdef", "else", "endif", ... ("" if none).
std::string_view directive_keyword(std::string_view directive) {
  std::size_t i = 1;
  while (i < directive.size() && (directive[i] == ' ' || directive[i] == '\t')) ++i;
  std::size_t end = i;
  while (end < directive.size() && is_identifier_char(directive[end])) ++end;
  return directive.substr(i, end - i);
}

// A directive on one line: continuation backslash-newlines become spaces.
std::string one_line(std::string_view directive) {
  std::string out;
  for (std::size_t i = 0; i < directive.size(); ++i) {
    if (directive[i] == '\\' && i + 1 < directive.size() && directive[i + 1] == '\n') {
      out += ' ';
      ++i;
    } else {
      out += directive[i];
    }
  }
  return out;
}

class FileScopePass {
 public:
  FileScopePass(std::string_view text, std::vector<Token> tokens) : text_(text), tokens_(std::move(tokens)) {}

  SketchScan run() {
    for (std::size_t i = 0; i < tokens_.size(); ++i) {
      const Token& token = tokens_[i];
      if (token.kind == TokenKind::kDirective) {
        directive(token);
      } else if (is(token, "{")) {
        i = open_brace(i);
      } else if (is(token, ";") || is(token, "}")) {  // a stray '}' ends whatever came before
        statement_.clear();
      } else {
        if (statement_.empty()) statement_conditions_ = conditions_;
        statement_.push_back(i);
      }
    }
    return std::move(scan_);
  }

 private:
  std::string_view text(const Token& token) const { return text_.substr(token.begin, token.end - token.begin); }
  bool is(const Token& token, std::string_view spelling) const {
    return token.kind == TokenKind::kPunct && text(token) == spelling;
  }
  std::string_view word(std::size_t statement_index) const { return text(tokens_[statement_[statement_index]]); }

  struct OpenConditional {
    std::vector<std::string> lines;  // opening directive, then #elif/#else met so far
    std::size_t offset;              // where the opening directive starts
  };

  void directive(const Token& token) {
    const std::string_view keyword = directive_keyword(text(token));
    if (keyword == "if" || keyword == "ifdef" || keyword == "ifndef") {
      conditions_.push_back({{one_line(text(token))}, token.begin});
    } else if ((keyword == "elif" || keyword == "else") && !conditions_.empty()) {
      conditions_.back().lines.push_back(one_line(text(token)));
    } else if (keyword == "endif" && !conditions_.empty()) {
      conditions_.pop_back();
    }
  }

  // Index of the brace matching tokens_[open] (or the last token if unbalanced).
  std::size_t matching(std::size_t open, std::string_view opening, std::string_view closing) const {
    int depth = 0;
    for (std::size_t i = open; i < tokens_.size(); ++i) {
      if (is(tokens_[i], opening)) ++depth;
      if (is(tokens_[i], closing) && --depth == 0) return i;
    }
    return tokens_.size() - 1;
  }

  // A '{' at file scope: a function body (recorded, skipped, statement ends) or another block
  // (skipped; the statement goes on, as in `struct S {...} s;`, except after a namespace or an
  // extern "C" block, which end without ';').
  std::size_t open_brace(std::size_t index) {
    const std::size_t close = matching(index, "{", "}");
    if (function_definition()) {
      statement_.clear();
    } else if (!statement_.empty() && (word(0) == "namespace" || word(0) == "extern")) {
      statement_.clear();
    } else {
      if (statement_.empty()) statement_conditions_ = conditions_;
      statement_.push_back(index);  // the block stands for itself: `{` `}`
      statement_.push_back(close);
    }
    // Directives inside the skipped block still open and close conditionals.
    for (std::size_t i = index; i <= close; ++i) {
      if (tokens_[i].kind == TokenKind::kDirective) directive(tokens_[i]);
    }
    return close;
  }

  // Index in statement_ just past a leading `template <...>` header (0 if none).
  std::size_t after_template_header() const {
    if (statement_.empty() || word(0) != "template" || statement_.size() < 2 || word(1) != "<") return 0;
    int depth = 0;
    for (std::size_t i = 1; i < statement_.size(); ++i) {
      if (word(i) == "<") ++depth;
      if (word(i) == ">" && --depth == 0) return i + 1;
    }
    return statement_.size();
  }

  // Index in statement_ of the ')' matching the '(' at `open`.
  std::size_t matching_paren(std::size_t open) const {
    int depth = 0;
    for (std::size_t i = open; i < statement_.size(); ++i) {
      if (word(i) == "(") ++depth;
      if (word(i) == ")" && --depth == 0) return i;
    }
    return statement_.size();
  }

  // Finds the function's name: the first `identifier (` outside parentheses, with no '=' at
  // that level before it. Returns statement_.size() if there is none.
  std::size_t name_index(std::size_t first) const {
    int depth = 0;
    for (std::size_t i = first; i + 1 < statement_.size(); ++i) {
      const std::string_view w = word(i);
      if (w == "(" || w == "[") ++depth;
      if (w == ")" || w == "]") --depth;
      if (depth == 0 && w == "=") return statement_.size();
      if (depth == 0 && tokens_[statement_[i]].kind == TokenKind::kIdentifier && word(i + 1) == "(") {
        if (!is_non_name_word(w)) return i;
        i = matching_paren(i + 1);  // skip decltype(...), __attribute__((...)), ...
      }
    }
    return statement_.size();
  }

  bool function_definition() {
    if (statement_.empty()) return false;
    const std::size_t first = after_template_header();
    if (first >= statement_.size() || (first == 2 && word(1) == "<" && word(2) == ">")) return false;
    const std::size_t name = name_index(first);
    if (name >= statement_.size() || name == first) return false;  // no return type: a macro
    const std::string_view before = word(name - 1);
    if (before == "::" || before == "." || before == "->" || before == "~") return false;
    const std::size_t close = matching_paren(name + 1);
    if (close >= statement_.size()) return false;
    for (std::size_t i = close + 1; i < statement_.size(); ++i) {
      const std::string_view w = word(i);
      if (w == "=" || w == ":" || w == ";" || w == "try" || w == "{") return false;
    }
    record(name, close);
    return true;
  }

  void record(std::size_t name, std::size_t close) {
    SketchFunction function;
    function.name = std::string(word(name));
    function.line = line_of(tokens_[statement_[name]].begin);
    for (const OpenConditional& open : statement_conditions_) function.conditions.push_back(open.lines);
    function.default_arguments = default_arguments(name + 1, close);
    function.prototype = joined(0, statement_.size()) + ";";
    if (scan_.functions.empty()) set_insertion_point();
    scan_.functions.push_back(std::move(function));
  }

  // "= value" ranges among the parameters between the parentheses at open and close.
  std::vector<std::pair<std::size_t, std::size_t>> default_arguments(std::size_t open, std::size_t close) const {
    std::vector<std::pair<std::size_t, std::size_t>> ranges;
    int depth = 0;
    std::size_t start = 0;
    bool in_default = false;
    for (std::size_t i = open + 1; i <= close; ++i) {
      const std::string_view w = word(i);
      const bool ends = depth == 0 && (w == "," || i == close);
      if (in_default && ends) {
        ranges.emplace_back(start, tokens_[statement_[i - 1]].end);
        in_default = false;
      }
      if (w == "(" || w == "[" || w == "{") ++depth;
      if (w == ")" || w == "]" || w == "}") --depth;
      if (depth == 0 && w == "=" && !in_default) {
        in_default = true;
        start = tokens_[statement_[i]].begin;
      }
    }
    return ranges;
  }

  // Tokens statement_[from, to) as one line; spaces only where tokens need them to read well.
  std::string joined(std::size_t from, std::size_t to) const {
    std::string out;
    for (std::size_t i = from; i < to; ++i) {
      const std::string_view w = word(i);
      if (i > from) {
        const std::string_view previous = word(i - 1);
        const bool tight = previous == "(" || previous == "[" || previous == "::" || previous == "~" || w == "(" ||
                           w == ")" || w == "[" || w == "]" || w == "," || w == "::";
        if (!tight) out += ' ';
      }
      out += w;
    }
    return out;
  }

  void set_insertion_point() {
    const std::size_t first =
        statement_conditions_.empty() ? tokens_[statement_[0]].begin : statement_conditions_.front().offset;
    std::size_t line_start = first;
    while (line_start > 0 && text_[line_start - 1] != '\n') --line_start;
    const bool blanks_before =
        text_.substr(line_start, first - line_start).find_first_not_of(" \t\r\f\v") == std::string_view::npos;
    scan_.insertion_offset = blanks_before ? line_start : first;
    scan_.insertion_column = blanks_before ? 0 : first - line_start;
    scan_.insertion_line = line_of(scan_.insertion_offset);
  }

  std::size_t line_of(std::size_t offset) const {
    return 1 + static_cast<std::size_t>(std::count(text_.begin(), text_.begin() + static_cast<long>(offset), '\n'));
  }

  std::string_view text_;
  std::vector<Token> tokens_;
  std::vector<std::size_t> statement_;  // token indices of the file-scope statement so far
  std::vector<OpenConditional> conditions_;
  std::vector<OpenConditional> statement_conditions_;  // conditions_ when statement_ began
  SketchScan scan_;
};

}  // namespace

SketchScan scan_sketch_functions(std::string_view text) { return FileScopePass(text, Lexer(text).tokens()).run(); }

}  // namespace stepdance::sim
