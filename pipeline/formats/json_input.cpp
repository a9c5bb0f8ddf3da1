#include "formats/json_input.hpp"

#include <fmt/format.h>

#include <set>
#include <vector>

#include "core/error.hpp"
#include "core/text_input.hpp"

namespace softpack {

nlohmann::json read_json_input(const std::string& path, const std::string& what) {
  using json = nlohmann::json;
  const std::string text = read_text_input(path, what);
  std::vector<std::set<std::string>> keys;  // of each object being read, innermost last
  const json::parser_callback_t strict = [&](int, json::parse_event_t event, json& parsed) {
    if (event == json::parse_event_t::object_start) keys.emplace_back();
    if (event == json::parse_event_t::object_end && !keys.empty()) keys.pop_back();
    if (event == json::parse_event_t::key && !keys.empty() && !keys.back().insert(parsed.get<std::string>()).second)
      throw InputError(fmt::format("{}: the key \"{}\" is given twice in one object; allowed: each key once", path,
                                   parsed.get<std::string>()));
    return true;
  };
  try {
    return json::parse(text, strict);
  } catch (const json::exception& e) {  // parse_error; out_of_range for a number beyond a double (1e999)
    throw InputError(fmt::format("{}: not a JSON file: {}", path, e.what()));
  }
}

}  // namespace softpack
