#include "scene/bodies.hpp"

#include <unordered_map>

namespace softpack {

BodyTree::BodyTree(const std::vector<ShellDef>& shells) {
  for (const ShellDef& s : shells)
    if (s.parent != kNoBody) parent_[s.body] = s.parent;
}

int BodyTree::parent(int body) const {
  const auto it = parent_.find(body);
  return it == parent_.end() ? kNoBody : it->second;
}

int BodyTree::root(int body) const {
  // At most one step per shell: validate() refuses cycles, this bound keeps a bad scene finite.
  for (std::size_t k = 0; k <= parent_.size(); ++k) {
    const int up = parent(body);
    if (up == kNoBody) return body;
    body = up;
  }
  return body;
}

bool BodyTree::within(int body, int outer) const {
  if (body == kNoBody || outer == kNoBody) return false;
  for (std::size_t k = 0; k <= parent_.size() && body != kNoBody; ++k, body = parent(body))
    if (body == outer) return true;
  return false;
}

std::vector<std::vector<int>> shell_members(const std::vector<ShellDef>& shells, const std::vector<int>& bodies) {
  std::unordered_map<int, std::size_t> shell_of;  // body -> its shell
  for (std::size_t k = 0; k < shells.size(); ++k) shell_of.emplace(shells[k].body, k);
  const BodyTree tree(shells);
  std::vector<std::vector<int>> out(shells.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    if (bodies[i] == kNoBody) continue;
    // The sphere's body and each enclosing one: sphere i in index order in every list.
    for (int b = bodies[i], k = 0; b != kNoBody && k <= static_cast<int>(shells.size()); b = tree.parent(b), ++k)
      if (const auto it = shell_of.find(b); it != shell_of.end()) out[it->second].push_back(static_cast<int>(i));
  }
  return out;
}

}  // namespace softpack
