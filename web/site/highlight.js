// A small syntax highlighter for the sketches shown in the page (C++ as Arduino sketches use it):
// comments, strings, characters, numbers, preprocessor lines and keywords, as spans.
"use strict";

const CPP_KEYWORDS = new Set(("alignas auto bool break case char class const constexpr continue default delete do " +
  "double else enum extern false float for if inline int long namespace new nullptr private protected public " +
  "return short signed sizeof static static_cast struct switch template this true typedef typename uint8_t " +
  "uint16_t uint32_t uint64_t int8_t int16_t int32_t int64_t size_t union unsigned using virtual void volatile while").split(" "));

// One alternative per token kind; the first that matches at a position wins.
const CPP_TOKENS = /(\/\/[^\n]*|\/\*[\s\S]*?\*\/)|("(?:\\.|[^"\\\n])*"|'(?:\\.|[^'\\\n])*')|(^[ \t]*#[^\n]*)|(\b(?:0x[0-9a-fA-F]+|\d+\.?\d*(?:[eE][-+]?\d+)?)[uUlLfF]*\b)|([A-Za-z_]\w*)/gm;

/// Fills element `pre` with `source`, its tokens as spans of class tok-<kind>.
function highlightCpp(pre, source) {
  pre.textContent = "";
  let at = 0;
  const text = (s) => pre.appendChild(document.createTextNode(s));
  const span = (kind, s) => {
    const element = document.createElement("span");
    element.className = "tok-" + kind;
    element.textContent = s;
    pre.appendChild(element);
  };
  for (const match of source.matchAll(CPP_TOKENS)) {
    if (match.index > at) text(source.slice(at, match.index));
    const [token, comment, string, preprocessor, number, word] = match;
    if (comment) span("comment", token);
    else if (string) span("string", token);
    else if (preprocessor) span("preprocessor", token);
    else if (number) span("number", token);
    else if (word && CPP_KEYWORDS.has(word)) span("keyword", token);
    else text(token);
    at = match.index + token.length;
  }
  if (at < source.length) text(source.slice(at));
}
