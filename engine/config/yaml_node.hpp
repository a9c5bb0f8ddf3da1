// Validated reading of YAML configuration. A ConfigNode knows its file, its key path and its
// line/column, so every error names them:
//
//   experiments/scene.yaml:12:5: walls[0].normal: expected a list of 3 numbers
//   experiments/scene.yaml:4:3: effects.frcition: unknown key; did you mean 'friction'?
//     (allowed: normal, friction, rotation, damping, gravity)
#pragma once
#include <yaml-cpp/yaml.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/suggest.hpp"
#include "core/types.hpp"

namespace softpack {

class ConfigNode {
 public:
  /// Parses a file; malformed YAML and unreadable files throw InputError with line and column.
  /// Refused too, with line and column: text that is not UTF-8 or holds control characters,
  /// keys that are not text or appear twice in a map, nesting deeper than 64 levels, aliases
  /// that loop or repeat more than 100000 nodes, a second document.
  static ConfigNode load_file(const std::string& path);
  /// Parses text (tests, fuzzing); `name` stands for the file in messages.
  static ConfigNode load_string(const std::string& text, const std::string& name);

  const std::string& path() const { return path_; }
  /// The file it was read from (load_file), or the name load_string was given.
  const std::string& file() const { return *file_; }
  const YAML::Node& yaml() const { return node_; }

  // Maps.
  bool has(const std::string& key) const;
  ConfigNode at(const std::string& key) const;  ///< required key
  std::optional<ConfigNode> find(const std::string& key) const;
  /// Rejects keys outside `allowed`, suggesting the closest allowed one.
  void allow_only(const std::vector<std::string>& allowed) const;
  std::vector<std::string> keys() const;

  // Sequences.
  std::vector<ConfigNode> items() const;

  // Scalars.
  double number() const;
  /// Read exactly (core/integer_text.hpp): decimal digits with an optional '-', no point,
  /// exponent, '+' or leading zero; within the range of long. The key's range is its reader's.
  long integer() const;
  bool boolean() const;
  std::string string() const;  ///< one line of text: no control characters
  Vec3 vec3() const;
  /// One of `allowed`.
  std::string choice(const std::vector<std::string>& allowed) const;

  /// Throws InputError "file:line:col: key.path: what".
  [[noreturn]] void fail(const std::string& what) const;

  /// An error found after reading ("key.path: what", e.g. from validate()), placed in the file:
  /// the message prefixed with the file, line and column of that key under this node (or of its
  /// nearest ancestor that the file holds). A message that names no key of this node gets the
  /// file's name.
  InputError locate(const InputError& error) const;

 private:
  ConfigNode(YAML::Node node, std::string path, std::shared_ptr<const std::string> file);
  ConfigNode child(const YAML::Node& node, const std::string& path) const;
  std::string key_text(const YAML::Node& key) const;
  std::string where() const;

  YAML::Node node_;
  std::string path_;
  std::shared_ptr<const std::string> file_;
};

}  // namespace softpack
