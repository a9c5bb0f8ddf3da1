// Bodies inside bodies (nested soft-particles, docs/nested.md). A body is the spheres of one id
// (`ParticleDef::body`) and, when it has one, its shell; a shell's `parent` is the body whose
// shell encloses it: the content of a soft-particle resolved holds the packings of its own
// soft-particles in their shells. A body's content is its spheres and those of every body
// inside it: its shell confines them all, a driver of the body moves them all, and the force
// between two bodies counts them all.
#pragma once
#include <unordered_map>
#include <vector>

#include "scene/scene_def.hpp"

namespace softpack {

class BodyTree {
 public:
  BodyTree() = default;
  /// From the shells' `body` and `parent`; validate() refuses a parent without a shell and a cycle.
  explicit BodyTree(const std::vector<ShellDef>& shells);

  /// The body whose shell encloses `body`'s; kNoBody at the top (and for kNoBody).
  int parent(int body) const;
  /// The outermost body that holds `body` (itself at the top; kNoBody for kNoBody).
  int root(int body) const;
  /// Whether `body` is `outer` or lies inside it.
  bool within(int body, int outer) const;
  /// Whether any shell has a parent.
  bool nested() const { return !parent_.empty(); }

 private:
  std::unordered_map<int, int> parent_;
};

/// The spheres each shell confines — those of its body and of every body inside it — in index
/// order; `bodies[i]` is sphere i's body.
std::vector<std::vector<int>> shell_members(const std::vector<ShellDef>& shells, const std::vector<int>& bodies);

}  // namespace softpack
