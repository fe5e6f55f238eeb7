// Names from a scenario that become paths in the output folder: board and device names (the
// SD card folder `<board>.sd`, an OLED's `<name>.png`) and the [output] and transcript file
// names. Checked when the file is read, so no output ever lands outside the output folder.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace stepdance::sim::scenario {

/// The longest name that becomes part of a file name, in bytes.
inline constexpr std::size_t kMaxFileNameBytes = 100;

/// Empty if `name` can be one part of a path (a file or folder name), else why not, as the end
/// of a sentence: "must not contain '/'", "must not be '.' or '..'", "must not contain control
/// characters", "must be at most 100 bytes". Context: any (pure).
std::string file_name_problem(std::string_view name);

/// Empty if `name` is a relative path that stays inside the folder it is relative to (not
/// absolute, no part is ".."), else why not, as the end of a sentence. An [output] file name and
/// a transcript name must be such a path. Context: any (pure).
std::string inside_path_problem(std::string_view name);

}  // namespace stepdance::sim::scenario
