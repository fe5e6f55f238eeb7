#!/usr/bin/env bash
# Prints the whole-line comment density of the .cpp files under the given folders (default src/):
# per folder holding .cpp files, then the total, and fails with --min X if the total is below X.
# Usage: scripts/comment-density.sh [--min X] [FOLDER…]     scripts/comment-density.sh --self-test
#
# What counts (headers, .hpp, are not counted: the figure is about function bodies):
# - density = comment lines / non-blank lines;
# - a non-blank line has a character other than white space;
# - a comment line is a non-blank line with nothing outside comments: a `//` line, a `/* … */`
#   line, the first, inner and last lines of a block comment (` * text`, ` */`), and a line with two
#   comments (`/* a */ // b`);
# - a line with any code is not one, even with a comment after the code (`x = 1;  // why`), or
#   with code after a block comment's end (`*/ int x;`);
# - the comment markers inside string and character literals (raw strings too) are code, and a
#   digit separator (1'000) is no character literal; a `//` comment whose line ends in a
#   backslash goes on over the next line, as the compiler reads it.
# Preprocessor lines are code. Needs python3 (scripts/setup.sh installs it).
set -euo pipefail
cd "$(dirname "$0")/.."
exec python3 - "$@" <<'PYTHON'
import os
import sys

IDENT = set("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_")


def classify(text):
    """Returns (non_blank, comment) line counts of C++ source text."""
    state = "code"        # code, block, line, string, char, raw
    raw_end = ""
    non_blank = comment = 0
    prev = ""             # previous character in code, for raw strings and digit separators
    number = False        # inside a token that began with a digit
    for line in text.split("\n"):
        has_code = has_comment = False
        if state in ("block", "line"):
            has_comment = line.strip() != ""
        i, n = 0, len(line)
        while i < n:
            c = line[i]
            if state == "block":
                has_comment = True
                if line.startswith("*/", i):
                    state, i = "code", i + 2
                    continue
                i += 1
            elif state == "line":
                has_comment = True
                i = n
            elif state in ("string", "char"):
                has_code = True
                if c == "\\":
                    i += 2
                    continue
                if c == ('"' if state == "string" else "'"):
                    state = "code"
                i += 1
            elif state == "raw":
                has_code = True
                end = line.find(raw_end, i)
                if end < 0:
                    i = n
                else:
                    state, i = "code", end + len(raw_end)
            else:
                if c.isspace():
                    prev, number = c, False
                    i += 1
                    continue
                if line.startswith("//", i):
                    state, has_comment = "line", True
                    i = n
                    continue
                if line.startswith("/*", i):
                    state, has_comment = "block", True
                    i += 2
                    continue
                has_code = True
                if c == '"':
                    if prev == "R" and (i < 2 or line[i - 2] not in IDENT or line[i - 3:i - 1] == "u8"
                                        or line[i - 2] in "uUL"):
                        paren = line.find("(", i)
                        raw_end = ")" + line[i + 1:paren] + '"'
                        state, i = "raw", paren + 1
                        continue
                    state = "string"
                elif c == "'" and not number:
                    state = "char"
                if c in IDENT and prev not in IDENT and not number:
                    number = c.isdigit()
                elif c not in IDENT and c not in "'.":
                    number = False
                prev = c
                i += 1
        if state == "line":
            state = "line" if line.endswith("\\") else "code"
        prev, number = "\n", False
        if line.strip():
            non_blank += 1
            if has_comment and not has_code:
                comment += 1
    return non_blank, comment


SELF_TEST = r'''// c1
#include <a.h>

/* c2 */
/* c3
 * c4
 */
int x = 1;  // code with a comment after it
const char* s = "// not a comment /* nor this";
const char* r = R"x(/* raw )" // still raw )x";
int y = 1'000;  /* a digit separator: no character literal */
char q = '"';
/* a */ int z;
int w; /* a block that
   runs on: c6 (c5 is the block's last line above) */
/* two comments on one line */ // c7
// c8, which goes on \
   over this line: c9
'''


def self_test():
    got = classify(SELF_TEST)
    want = (17, 9)
    if got != want:
        print(f"comment-density self-test: FAILED: non-blank, comment = {got}, want {want}")
        return 1
    print(f"comment-density self-test: passed (non-blank {want[0]}, comment {want[1]})")
    return 0


def main(argv):
    minimum = None
    folders = []
    while argv:
        arg = argv.pop(0)
        if arg == "--self-test":
            return self_test()
        if arg == "--min":
            try:
                minimum = float(argv.pop(0))
            except (IndexError, ValueError):
                print("comment-density: --min needs a number, e.g. --min 0.10", file=sys.stderr)
                return 2
        else:
            folders.append(arg.rstrip("/") or "/")
    folders = folders or ["src"]
    per_folder = {}
    for folder in folders:
        if not os.path.isdir(folder):
            print(f"comment-density: no folder {folder}", file=sys.stderr)
            return 2
        for root, _, names in os.walk(folder):
            for name in sorted(names):
                if not name.endswith(".cpp"):
                    continue
                with open(os.path.join(root, name), encoding="utf-8", errors="replace") as source:
                    counts = classify(source.read())
                files, non_blank, comment = per_folder.get(root, (0, 0, 0))
                per_folder[root] = (files + 1, non_blank + counts[0], comment + counts[1])
    print(f"{'folder (.cpp files)':<44} {'files':>5} {'non-blank':>9} {'comment':>7} {'density':>7}")
    total = [0, 0, 0]
    for root in sorted(per_folder):
        files, non_blank, comment = per_folder[root]
        total = [total[0] + files, total[1] + non_blank, total[2] + comment]
        print(f"{root:<44} {files:>5} {non_blank:>9} {comment:>7} {comment / max(non_blank, 1):>7.3f}")
    density = total[2] / max(total[1], 1)
    label = "total " + " ".join(folders)
    print(f"{label:<44} {total[0]:>5} {total[1]:>9} {total[2]:>7} {density:>7.3f}")
    if minimum is not None and density < minimum:
        print(f"comment-density: {density:.3f} is below the minimum {minimum}")
        return 1
    return 0


sys.exit(main(sys.argv[1:]))
PYTHON
