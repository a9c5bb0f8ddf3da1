// "Did you mean ...?": the suggestion of the messages that refuse an unknown key or name.
#pragma once
#include <string>
#include <vector>

namespace softpack {

/// The closest of `candidates` to `word` (Levenshtein), or "" when none is close.
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace softpack
