// Outputs are written atomically: to a temporary file in the same directory, then renamed, so
// an interrupted run never leaves a half-written file that make would trust.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace softpack {

/// The temporary a writer fills next to `final_path` and renames into place ("<final>.tmp.<pid>":
/// only the writing process uses it, and make's recipes clear what a killed one left), its
/// folder created. InputError names `final_path` when the folder cannot be made.
std::string temporary_path_for(const std::string& final_path);

/// Writes `content` to `path` via `path.tmp.<pid>` and rename(2). Throws InputError on failure.
void write_file_atomically(const std::string& path, const std::string& content);

/// Writes several files as one output: every temporary first, then the renames, so that a
/// failure (a full disk) leaves none of them new, rather than some. InputError names the file.
void write_files_atomically(const std::vector<std::pair<std::string, std::string>>& files);

/// The whole text of a file, "" when it does not exist or cannot be read.
std::string read_text_file(const std::string& path);

}  // namespace softpack
