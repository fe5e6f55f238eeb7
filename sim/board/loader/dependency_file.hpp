// The make-style dependency files the compiler writes with -MD: every file it read.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace stepdance::sim {

/// The prerequisites of a dependency file's rules (`target: a.cpp b.h \` lines), in order, each
/// once, unescaped as GCC escapes them (`\ ` for a space, `\#` for '#', `$$` for '$'). The
/// targets themselves are left out. Context: any (pure).
std::vector<std::string> parse_dependency_text(std::string_view text);

/// parse_dependency_text of the file at `path`; false when it cannot be read. Context: host.
bool read_dependency_file(const std::string& path, std::vector<std::string>& files);

}  // namespace stepdance::sim
