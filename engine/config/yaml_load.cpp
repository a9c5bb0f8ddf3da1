// Loading a YAML file for a ConfigNode: the checks that run before yaml-cpp builds the nodes
// (UTF-8 text without control characters; keys that are text and unique; bounded nesting and
// aliases; one document), which make a hostile file an InputError with line and column.
#include <fmt/format.h>
#include <yaml-cpp/anchor.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string_view>
#include <vector>

#include "config/yaml_node.hpp"
#include "config/yaml_text.hpp"
#include "core/error.hpp"
#include "core/text_input.hpp"

namespace softpack {
namespace yaml_text {

std::string at_mark(const std::string& file, const YAML::Mark& m) {
  return m.is_null() ? file : fmt::format("{}:{}:{}", file, m.line + 1, m.column + 1);
}

std::string join_key(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

// Length of the UTF-8 sequence at text[i] and its code point, or 0 when it is not UTF-8
// (truncated, overlong, a surrogate, beyond U+10FFFF).
std::size_t utf8_sequence(const std::string& text, std::size_t i, char32_t& cp) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char c = byte(i);
  std::size_t n = 0;
  if (c < 0x80) {
    cp = c;
    return 1;
  }
  if ((c & 0xE0) == 0xC0) n = 2, cp = c & 0x1F;
  else if ((c & 0xF0) == 0xE0) n = 3, cp = c & 0x0F;
  else if ((c & 0xF8) == 0xF0) n = 4, cp = c & 0x07;
  else return 0;
  if (i + n > text.size()) return 0;
  for (std::size_t k = 1; k < n; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    cp = (cp << 6) | (byte(i + k) & 0x3F);
  }
  static constexpr char32_t kSmallest[5] = {0, 0, 0x80, 0x800, 0x10000};
  if (cp < kSmallest[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
  return n;
}

// YAML's printable characters (c-printable), plus or minus line breaks and tabs.
bool printable(char32_t cp, bool allow_breaks) {
  if (cp == '\t' || cp == '\n' || cp == '\r') return allow_breaks;
  return (cp >= 0x20 && cp < 0x7F) || cp == 0x85 || (cp >= 0xA0 && cp != 0xFFFE && cp != 0xFFFF);
}

}  // namespace yaml_text

namespace {

using namespace yaml_text;

// Far above any configuration (profiles nest 3 levels, scenes 4), far below what would exhaust
// the stack of the recursive code that walks or emits a node.
constexpr std::size_t kMaxDepth = 64;
// Nodes that aliases may add by repeating anchored ones: a profile uses none; the limit stops
// "billion laughs" documents (aliases of aliases) before they expand exponentially.
constexpr std::size_t kMaxAliasNodes = 100000;

// The file must be UTF-8 text (YAML's encoding; the executables copy it into JSON reports).
void check_text(const std::string& text, const std::string& file) {
  int line = 1, column = 1;
  for (std::size_t i = 0; i < text.size();) {
    char32_t cp = 0;
    const std::size_t n = utf8_sequence(text, i, cp);
    if (n == 0)
      throw InputError(fmt::format("{}:{}:{}: not UTF-8 text (byte 0x{:02X}); save the file as UTF-8", file, line, column,
                                   static_cast<unsigned char>(text[i])));
    if (!printable(cp, true))
      throw InputError(fmt::format("{}:{}:{}: control character U+{:04X} is not allowed in YAML", file, line, column,
                                   static_cast<std::uint32_t>(cp)));
    i += n;
    if (cp == '\n') line += 1, column = 1;
    else column += 1;
  }
}

// Checks the structure of a document as the parser reads it, before yaml-cpp builds the nodes
// (which it does without these checks): text keys, no duplicate keys, bounded nesting, aliases
// that neither loop nor expand beyond kMaxAliasNodes, a single document.
class DocumentCheck final : public YAML::EventHandler {
 public:
  explicit DocumentCheck(const std::string& file) : file_(file) {}

  YAML::Mark document_start;

  void OnDocumentStart(const YAML::Mark& mark) override { document_start = mark; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    begin(mark, anchor, nullptr, true);
    finish(anchor, 1, nullptr);
  }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, const std::string& value) override {
    begin(mark, anchor, &value, false);
    finish(anchor, 1, &value);
  }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    const Anchor* a = anchor < anchors_.size() && anchors_[anchor].done ? &anchors_[anchor] : nullptr;
    const std::string path = begin(mark, YAML::NullAnchor, a != nullptr && a->scalar ? &a->value : nullptr, false, true);
    if (a == nullptr) fail(mark, path, "this alias refers to the node that contains it (a loop)");
    if (frames_.size() + a->height > kMaxDepth) fail(mark, path, fmt::format("nested deeper than {} levels", kMaxDepth));
    total_ += a->size - 1;  // begin() counted one
    if (total_ - literal_ > kMaxAliasNodes)
      fail(mark, path, fmt::format("aliases repeat more than {} nodes; write the values out", kMaxAliasNodes));
    finish(YAML::NullAnchor, a->height, a->scalar ? &a->value : nullptr);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, YAML::EmitterStyle::value) override {
    open(mark, anchor, false);
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor, YAML::EmitterStyle::value) override {
    open(mark, anchor, true);
  }
  void OnMapEnd() override { close(); }

 private:
  struct Frame {
    bool map = false;
    YAML::anchor_t anchor = YAML::NullAnchor;
    std::string path;
    std::size_t height = 1;
    bool want_key = true;        // maps: the next node is a key
    std::string key;             // maps: the current key
    std::map<std::string, YAML::Mark> keys;
    std::size_t index = 0;       // sequences: the current item
  };
  struct Anchor {
    bool done = false;
    std::size_t start = 0, size = 0, height = 0;
    bool scalar = false;
    std::string value;
  };

  [[noreturn]] void fail(const YAML::Mark& mark, const std::string& path, const std::string& what) const {
    const std::string shown = path.empty() ? std::string("(top level)") : path.size() > 60 ? path.substr(0, 57) + "..." : path;
    throw InputError(fmt::format("{}: {}: {}", at_mark(file_, mark), shown, what));
  }

  // The path of the node that starts here; checks it as a key when it is one.
  std::string begin(const YAML::Mark& mark, YAML::anchor_t anchor, const std::string* scalar, bool null, bool alias = false) {
    std::string path;
    if (!frames_.empty()) {
      Frame& f = frames_.back();
      if (!f.map) {
        path = fmt::format("{}[{}]", f.path, f.index);
      } else if (f.want_key) {
        if (null) fail(mark, f.path, "a key is empty (null); keys are text, like 'name:'");
        if (scalar == nullptr) fail(mark, f.path, "a key must be text, like 'name:', not a list or a map");
        path = join_key(f.path, *scalar);
        const auto [it, fresh] = f.keys.emplace(*scalar, mark);
        if (!fresh)
          fail(mark, path,
               fmt::format("duplicate key (first at line {}, column {})", it->second.line + 1, it->second.column + 1));
        f.key = *scalar;
      } else {
        path = join_key(f.path, f.key);
      }
    }
    if (frames_.size() >= kMaxDepth) fail(mark, path, fmt::format("nested deeper than {} levels", kMaxDepth));
    ++total_;
    if (!alias) ++literal_;
    if (anchor != YAML::NullAnchor) {
      if (anchors_.size() <= anchor) anchors_.resize(anchor + 1);
      anchors_[anchor] = Anchor{false, total_ - 1, 0, 0, false, {}};
    }
    return path;
  }

  // A node of `height` levels ends.
  void finish(YAML::anchor_t anchor, std::size_t height, const std::string* scalar) {
    if (anchor != YAML::NullAnchor && anchor < anchors_.size()) {
      Anchor& a = anchors_[anchor];
      a.done = true;
      a.size = total_ - a.start;
      a.height = height;
      a.scalar = scalar != nullptr;
      if (scalar != nullptr) a.value = *scalar;
    }
    if (frames_.empty()) return;
    Frame& f = frames_.back();
    f.height = std::max(f.height, height + 1);
    if (f.map) f.want_key = !f.want_key;
    else ++f.index;
  }

  void open(const YAML::Mark& mark, YAML::anchor_t anchor, bool map) {
    const std::string path = begin(mark, anchor, nullptr, false);
    Frame f;
    f.map = map;
    f.anchor = anchor;
    f.path = path;
    frames_.push_back(std::move(f));
  }

  void close() {
    const Frame f = std::move(frames_.back());
    frames_.pop_back();
    finish(f.anchor, f.height, nullptr);
  }

  const std::string& file_;
  std::vector<Frame> frames_;
  std::vector<Anchor> anchors_;
  std::size_t total_ = 0;    // nodes, aliases expanded
  std::size_t literal_ = 0;  // nodes as written
};

}  // namespace

namespace {

// A '[' or '{' that opens a list or a map and is still open where a line starts at column 0 (a new
// top-level key) or at the end of the text: the reader would take the next keys into the open
// list or map and report something else about them ("a key must be text"). Counted: brackets where
// a value starts (after "key: ", "- ", at a line's start, or inside an open list or map); not
// brackets inside plain or quoted text, comments and block scalars (| and >).
void check_brackets_closed(const std::string& text, const std::string& name) {
  struct Open {
    char c;
    std::size_t line, column;
  };
  std::vector<Open> open;
  std::size_t line = 0, start = 0;
  long block_indent = -1;  // the indentation of the key of a block scalar being skipped
  while (start < text.size()) {
    ++line;
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view l(text.data() + start, end - start);
    start = end + 1;
    const std::size_t indent = std::min(l.find_first_not_of(' '), l.size());
    if (indent == l.size() || l[indent] == '#' || l[indent] == '\r') continue;  // blank or a comment
    if (block_indent >= 0 && static_cast<long>(indent) > block_indent) continue;  // inside a block scalar
    block_indent = -1;
    if (!open.empty() && indent == 0 && l[0] != ']' && l[0] != '}') {
      const Open& o = open.back();
      throw InputError(fmt::format("{}:{}:{}: malformed YAML: this '{}' is not closed before line {}, which starts a new key (a '{}' is missing)",
                                   name, o.line, o.column, o.c, line, o.c == '[' ? ']' : '}'));
    }
    char quote = 0;
    char prev = '\n';  // the last character that is not a space: '\n' at the line's start
    std::size_t last = indent;  // where the value of the line's last key starts (block scalars)
    for (std::size_t i = indent; i < l.size(); ++i) {
      const char c = l[i];
      if (quote) {
        if (c == quote && !(quote == '"' && l[i - 1] == '\\')) quote = 0, prev = c;
        continue;
      }
      if (c == ' ' || c == '\t') continue;
      if (c == '#' && (i == 0 || l[i - 1] == ' ')) break;  // a comment
      const bool value_start = prev == '\n' || prev == '[' || prev == '{' || prev == ',' ||
                               ((prev == ':' || prev == '-') && l[i - 1] == ' ');
      if (value_start && (c == '"' || c == '\'')) quote = c;
      else if (value_start && (c == '[' || c == '{')) open.push_back({c, line, i + 1});
      else if ((c == ']' || c == '}') && !open.empty()) open.pop_back();
      if (value_start && open.empty()) last = i;
      prev = c;
    }
    if (open.empty() && (l[last] == '|' || l[last] == '>') && l.substr(last).find_first_of("#:") == std::string_view::npos)
      block_indent = static_cast<long>(indent);
  }
  if (!open.empty()) {
    const Open& o = open.back();
    throw InputError(fmt::format("{}:{}:{}: malformed YAML: this '{}' is not closed by the end of the file (a '{}' is missing)", name, o.line,
                                 o.column, o.c, o.c == '[' ? ']' : '}'));
  }
}

}  // namespace

ConfigNode ConfigNode::load_string(const std::string& text, const std::string& name) {
  auto file = std::make_shared<const std::string>(name);
  check_text(text, name);
  check_brackets_closed(text, name);
  try {
    {
      std::istringstream in(text);
      YAML::Parser parser(in);
      DocumentCheck check(name);
      parser.HandleNextDocument(check);
      if (parser.HandleNextDocument(check))
        throw InputError(fmt::format("{}: a second YAML document; a configuration file holds one",
                                     at_mark(name, check.document_start)));
    }
    return ConfigNode(YAML::Load(text), "", file);
  } catch (const YAML::Exception& e) {
    throw InputError(fmt::format("{}:{}:{}: malformed YAML: {}", name, e.mark.line + 1, e.mark.column + 1, e.msg));
  }
}

ConfigNode ConfigNode::load_file(const std::string& path) {
  return load_string(read_text_input(path, "a YAML file"), path);
}

}  // namespace softpack
