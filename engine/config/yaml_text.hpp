// Text helpers shared by the YAML loader (config/yaml_load.cpp) and ConfigNode's readers.
#pragma once
#include <yaml-cpp/mark.h>

#include <cstddef>
#include <string>

namespace softpack::yaml_text {

/// "file:line:col" of a mark ("file" for a null mark).
std::string at_mark(const std::string& file, const YAML::Mark& m);
/// Key path "path.key" ("key" at the top level).
std::string join_key(const std::string& path, const std::string& key);
/// Length of the UTF-8 sequence at text[i] and its code point, or 0 when it is not UTF-8
/// (truncated, overlong, a surrogate, beyond U+10FFFF).
std::size_t utf8_sequence(const std::string& text, std::size_t i, char32_t& cp);
/// YAML's printable characters (c-printable), plus or minus line breaks and tabs.
bool printable(char32_t cp, bool allow_breaks);

}  // namespace softpack::yaml_text
