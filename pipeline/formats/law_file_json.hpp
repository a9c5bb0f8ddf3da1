// The law file's JSON as write_law_file writes it (formats/law_file.hpp describes the layout;
// law_file.cpp reads it back before anything is written, and reads files).
#pragma once
#include <nlohmann/json.hpp>

#include "formats/law_file.hpp"

namespace softpack::law_json {

inline constexpr const char* kFormat = "softpack-laws";
inline constexpr const char *kForce = "N", *kStiffness = "N/m", *kOne = "1", *kMetre = "m";

/// `f` as the file's JSON (NaN as null; nothing checked: law_file.cpp's reader does that).
nlohmann::ordered_json file(const LawFile& f);

}  // namespace softpack::law_json
