// Reading a JSON input (the fit file, the law file): whole and bounded (core/text_input.hpp),
// parsed strictly. A key given twice in one object is refused: nlohmann-json keeps the last of
// them silently, so `{"a": 1, "a": 2}` would mean whatever the later line says.
#pragma once
#include <nlohmann/json.hpp>

#include <string>

namespace softpack {

/// The JSON of the file at `path`; `what` names the kind of file ("a fit file"). InputError names
/// the file: not readable as text (core/text_input.hpp), not JSON, a number beyond a double, a key
/// twice in one object.
nlohmann::json read_json_input(const std::string& path, const std::string& what);

}  // namespace softpack
