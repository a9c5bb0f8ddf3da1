// Outputs are written atomically: to a temporary file in the same directory, then renamed, so
// an interrupted run never leaves a half-written file that make would trust.
#pragma once
#include <string>

namespace softpack {

/// Writes `content` to `path` via `path.tmp.<pid>` and rename(2). Throws InputError on failure.
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace softpack
