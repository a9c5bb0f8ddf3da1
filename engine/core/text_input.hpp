// Reading a text input (a YAML profile or scene, a JSON fit or law file) whole, with the checks
// every reader needs before it parses: the path names a regular file (not a folder, a device such
// as /dev/zero, a pipe, a symlink loop) of at most kMaxTextInput bytes. InputError names the file
// and what it is; nothing is read without bound.
#pragma once
#include <cstddef>
#include <string>

namespace softpack {

/// The largest text input read [bytes]: far above any profile, scene, fit or law file.
inline constexpr std::size_t kMaxTextInput = std::size_t{64} << 20;

/// The whole text of the file at `path`; `what` names the kind of file expected ("a YAML file").
std::string read_text_input(const std::string& path, const std::string& what);

}  // namespace softpack
