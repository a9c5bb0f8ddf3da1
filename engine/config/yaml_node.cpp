#include "config/yaml_node.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

#include "config/yaml_text.hpp"
#include "core/error.hpp"
#include "core/integer_text.hpp"

namespace softpack {

using namespace yaml_text;

ConfigNode::ConfigNode(YAML::Node node, std::string path, std::shared_ptr<const std::string> file)
    : node_(std::move(node)), path_(std::move(path)), file_(std::move(file)) {}

ConfigNode ConfigNode::child(const YAML::Node& node, const std::string& path) const {
  return ConfigNode(node, path, file_);
}

std::string ConfigNode::where() const {
  const YAML::Mark m = node_.Mark();
  std::string out = *file_;
  if (!m.is_null()) out += fmt::format(":{}:{}", m.line + 1, m.column + 1);
  return out + ": " + (path_.empty() ? std::string("(top level)") : path_);
}

void ConfigNode::fail(const std::string& what) const { throw InputError(where() + ": " + what); }

bool ConfigNode::has(const std::string& key) const { return node_.IsMap() && node_[key].IsDefined(); }

ConfigNode ConfigNode::at(const std::string& key) const {
  if (!node_.IsMap()) fail("expected a map of keys");
  const YAML::Node n = node_[key];
  if (!n.IsDefined() || n.IsNull()) fail(fmt::format("missing required key '{}'", key));
  return child(n, path_.empty() ? key : path_ + "." + key);
}

std::optional<ConfigNode> ConfigNode::find(const std::string& key) const {
  if (!has(key) || node_[key].IsNull()) return std::nullopt;
  return at(key);
}

std::string ConfigNode::key_text(const YAML::Node& key) const {
  // load_string refuses other keys; this guards nodes built otherwise.
  if (!key.IsScalar()) child(key, path_).fail("a key must be text, like 'name:', not a list or a map");
  return key.Scalar();
}

std::vector<std::string> ConfigNode::keys() const {
  std::vector<std::string> out;
  if (node_.IsMap())
    for (const auto& kv : node_) out.push_back(key_text(kv.first));
  return out;
}

void ConfigNode::allow_only(const std::vector<std::string>& allowed) const {
  if (!node_.IsMap()) fail("expected a map of keys");
  for (const auto& kv : node_) {
    const std::string key = key_text(kv.first);
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
    const std::string guess = closest_match(key, allowed);
    const ConfigNode bad = child(kv.first, path_.empty() ? key : path_ + "." + key);
    bad.fail(fmt::format("unknown key{}; allowed: {}", guess.empty() ? "" : "; did you mean '" + guess + "'?", list));
  }
}

std::vector<ConfigNode> ConfigNode::items() const {
  if (!node_.IsSequence()) fail("expected a list");
  std::vector<ConfigNode> out;
  for (std::size_t k = 0; k < node_.size(); ++k) out.push_back(child(node_[k], fmt::format("{}[{}]", path_, k)));
  return out;
}

namespace {

// The form of a number's text: decimal ([-+] digits [. digits] [e [-+] digits], or [-+] . digits
// [e ...]; no leading zero before other digits), or why not.
enum class NumberText { decimal, leading_zero, hexadecimal, other };
NumberText number_form(const std::string& t) {
  std::size_t i = 0;
  const auto digits = [&] {
    const std::size_t from = i;
    while (i < t.size() && t[i] >= '0' && t[i] <= '9') ++i;
    return i - from;
  };
  if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
  const std::size_t int_start = i;
  const std::size_t int_digits = digits();
  if (int_digits >= 1 && i < t.size() && (t[i] == 'x' || t[i] == 'X')) return NumberText::hexadecimal;
  const bool leading_zero = int_digits > 1 && t[int_start] == '0';
  std::size_t frac_digits = 0;
  if (i < t.size() && t[i] == '.') ++i, frac_digits = digits();
  if (int_digits == 0 && frac_digits == 0) return NumberText::other;
  if (i < t.size() && (t[i] == 'e' || t[i] == 'E')) {
    ++i;
    if (i < t.size() && (t[i] == '+' || t[i] == '-')) ++i;
    if (digits() == 0) return NumberText::other;
  }
  if (i != t.size()) return NumberText::other;
  return leading_zero ? NumberText::leading_zero : NumberText::decimal;
}

}  // namespace

double ConfigNode::number() const {
  if (!node_.IsScalar()) fail("expected a number");
  const std::string text = node_.Scalar();
  // One reading of a number for every reader (YAML 1.1 and 1.2, Python's and ours): decimal
  // digits, an optional point and exponent; no leading zero (YAML 1.1 reads 0175 as octal), no
  // hexadecimal, no value the file itself calls text.
  const std::string& tag = node_.Tag();
  if (tag == "tag:yaml.org,2002:str" || tag == "!!str")
    fail(fmt::format("'{}' is tagged !!str, a text, where a number is expected; remove the tag", text));
  const NumberText form = number_form(text);
  if (form == NumberText::leading_zero)
    fail(fmt::format("'{}': a number with a leading zero is not allowed (YAML 1.1 readers read it as octal); write it "
                     "without the zero",
                     text));
  if (form == NumberText::hexadecimal) fail(fmt::format("'{}': only decimal numbers are allowed, like 1.5e6 (no hexadecimal)", text));
  try {
    std::size_t used = 0;
    if (form != NumberText::decimal) throw std::invalid_argument(text);
    const double v = std::stod(text, &used);
    if (used != text.size()) throw std::invalid_argument(text);
    if (!std::isfinite(v)) fail(fmt::format("'{}' is not a finite number", text));
    return v;
  } catch (const std::out_of_range&) {
    fail(fmt::format("'{}' is out of the range of numbers (about 1e-308 to 1e308 in magnitude)", text));
  } catch (const std::logic_error&) {
    fail(fmt::format("expected a number, got '{}'", text));
  }
}

long ConfigNode::integer() const {
  if (!node_.IsScalar()) fail("expected an integer");
  const std::string& text = node_.Scalar();
  const IntegerText v = parse_integer(text);
  if (v.status == IntegerText::Status::ok) return v.value;
  if (v.status == IntegerText::Status::out_of_range)
    fail(fmt::format("'{}' is out of the range of integers (at most {} in magnitude)", text, std::numeric_limits<long>::max()));
  number();  // text that is no number at all: "expected a number, got '...'"
  fail(fmt::format("expected an integer, got '{}' (decimal digits, like 3: no point, exponent, '+' or leading zero)", text));
}

bool ConfigNode::boolean() const {
  if (node_.IsScalar()) {
    const std::string t = node_.Scalar();
    if (t == "true") return true;
    if (t == "false") return false;
  }
  fail("expected true or false");
}

std::string ConfigNode::string() const {
  if (!node_.IsScalar()) fail("expected a text value");
  const std::string& text = node_.Scalar();
  // Names and choices end up in messages, HDF5 provenance and JSON reports: one line of text.
  for (std::size_t i = 0; i < text.size();) {
    char32_t cp = 0;
    const std::size_t n = utf8_sequence(text, i, cp);
    if (n == 0 || !printable(cp, false))
      fail(fmt::format("text with a control character or a line break is not allowed (at character {})", i + 1));
    i += n;
  }
  return text;
}

Vec3 ConfigNode::vec3() const {
  if (!node_.IsSequence() || node_.size() != 3) fail("expected a list of 3 numbers, like [0, 0, 1]");
  const auto v = items();
  return {v[0].number(), v[1].number(), v[2].number()};
}

std::string ConfigNode::choice(const std::vector<std::string>& allowed) const {
  const std::string v = string();
  if (std::find(allowed.begin(), allowed.end(), v) != allowed.end()) return v;
  std::string list;
  for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
  const std::string guess = closest_match(v, allowed);
  fail(fmt::format("'{}' is not allowed{}; allowed: {}", v, guess.empty() ? "" : "; did you mean '" + guess + "'?", list));
}

InputError ConfigNode::locate(const InputError& error) const {
  const std::string message = error.what();
  if (message.rfind(*file_, 0) == 0) return error;  // placed already
  // The key path: the message up to the first ": ", made of names, dots and [indices].
  const std::size_t colon = message.find(": ");
  const std::string path = colon == std::string::npos ? "" : message.substr(0, colon);
  const bool is_path = !path.empty() && path.find_first_not_of(
                                            "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-.[]") == std::string::npos;
  if (!is_path) return InputError(*file_ + ": " + message);
  YAML::Node node = node_;
  YAML::Mark mark = node_.Mark();
  std::size_t at = 0;
  while (at < path.size()) {
    const std::size_t end = std::min(path.find_first_of(".[", at), path.size());
    if (end > at) {  // a key
      const std::string key = path.substr(at, end - at);
      const YAML::Node& here = node;  // const: operator[] must not add the key
      if (!here.IsMap() || !here[key].IsDefined()) break;
      node.reset(here[key]);
    } else if (path[at] == '[') {  // an index
      const std::size_t close = path.find(']', at);
      if (close == std::string::npos || !node.IsSequence()) break;
      const std::size_t k = std::strtoul(path.c_str() + at + 1, nullptr, 10);
      const YAML::Node& here = node;
      if (k >= here.size()) break;
      node.reset(here[k]);
      at = close + 1;
      continue;
    }
    if (!node.Mark().is_null()) mark = node.Mark();
    at = end + (end < path.size() && path[end] == '.' ? 1 : 0);
  }
  if (!node.Mark().is_null()) mark = node.Mark();
  return InputError(at_mark(*file_, mark) + ": " + message);
}

}  // namespace softpack

