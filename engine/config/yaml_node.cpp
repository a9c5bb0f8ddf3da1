#include "config/yaml_node.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "core/error.hpp"

namespace softpack {

ConfigNode::ConfigNode(YAML::Node node, std::string path, std::shared_ptr<const std::string> file)
    : node_(std::move(node)), path_(std::move(path)), file_(std::move(file)) {}

ConfigNode ConfigNode::load_string(const std::string& text, const std::string& name) {
  auto file = std::make_shared<const std::string>(name);
  try {
    return ConfigNode(YAML::Load(text), "", file);
  } catch (const YAML::Exception& e) {
    throw InputError(fmt::format("{}:{}:{}: malformed YAML: {}", name, e.mark.line + 1,
                                 e.mark.column + 1, e.msg));
  }
}

ConfigNode ConfigNode::load_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot open the file", path));
  std::stringstream text;
  text << in.rdbuf();
  return load_string(text.str(), path);
}

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

std::vector<std::string> ConfigNode::keys() const {
  std::vector<std::string> out;
  if (node_.IsMap())
    for (const auto& kv : node_) out.push_back(kv.first.as<std::string>());
  return out;
}

void ConfigNode::allow_only(const std::vector<std::string>& allowed) const {
  if (!node_.IsMap()) fail("expected a map of keys");
  for (const auto& kv : node_) {
    const std::string key = kv.first.as<std::string>();
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

double ConfigNode::number() const {
  if (!node_.IsScalar()) fail("expected a number");
  const std::string text = node_.Scalar();
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used != text.size()) throw std::invalid_argument(text);
    if (!std::isfinite(v)) fail(fmt::format("'{}' is not a finite number", text));
    return v;
  } catch (const std::logic_error&) {
    fail(fmt::format("expected a number, got '{}'", text));
  }
}

long ConfigNode::integer() const {
  const double v = number();
  if (v != std::floor(v) || std::abs(v) > 1e15) fail(fmt::format("expected an integer, got '{}'", node_.Scalar()));
  return static_cast<long>(v);
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
  return node_.Scalar();
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

double ConfigNode::positive() const {
  const double v = number();
  if (!(v > 0.0)) fail(fmt::format("{} is not allowed; allowed: > 0", node_.Scalar()));
  return v;
}

double ConfigNode::non_negative() const {
  const double v = number();
  if (!(v >= 0.0)) fail(fmt::format("{} is not allowed; allowed: >= 0", node_.Scalar()));
  return v;
}

double ConfigNode::in_range(double lo, bool lo_open, double hi, bool hi_open) const {
  const double v = number();
  const bool ok = (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  if (!ok)
    fail(fmt::format("{} is not allowed; allowed: {} {} value {} {}", node_.Scalar(), lo, lo_open ? "<" : "<=",
                     hi_open ? "<" : "<=", hi));
  return v;
}

std::string closest_match(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_d = std::numeric_limits<std::size_t>::max();
  for (const auto& c : candidates) {
    // Levenshtein distance, one row at a time.
    std::vector<std::size_t> row(c.size() + 1);
    for (std::size_t j = 0; j <= c.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= word.size(); ++i) {
      std::size_t diag = row[0];
      row[0] = i;
      for (std::size_t j = 1; j <= c.size(); ++j) {
        const std::size_t up = row[j];
        row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (word[i - 1] == c[j - 1] ? 0 : 1)});
        diag = up;
      }
    }
    if (row[c.size()] < best_d) {
      best_d = row[c.size()];
      best = c;
    }
  }
  const std::size_t limit = std::max<std::size_t>(2, word.size() / 3);
  return best_d <= limit ? best : "";
}

}  // namespace softpack
