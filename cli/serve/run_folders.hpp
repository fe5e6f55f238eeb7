// The sketch server's run folders under the system's temporary folder: made per run, removed
// after it, and those of servers that died removed at start.
#pragma once

#include <string>

namespace stepdance::cli::serve {

/// A fresh folder stepdance-serve-<this process's id>-XXXXXX under the temporary folder.
/// Throws std::runtime_error when it cannot.
std::string make_run_folder();

/// Removes `folder` and everything in it, whatever permissions a run left on its contents.
/// True if it is gone.
bool remove_run_folder(const std::string& folder);

/// Removes the run folders of servers no longer running (stepdance-serve-<pid>-* whose process
/// is gone); returns how many. Context: at the server's start.
int remove_stale_run_folders();

}  // namespace stepdance::cli::serve
