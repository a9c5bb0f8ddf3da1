#include "neighbor/contact_list.hpp"

namespace softpack {
namespace {

// Sorted merge of the old entries into the fresh ones (both sorted by `key`): a fresh entry
// found in the old list takes its constants and, when `springs` is kept, its spring; the
// indices of the entries not found are returned, for the caller to compute their constants.
template <class Entry, class Key>
std::vector<std::size_t> merge(const std::vector<Entry>& old_entries, const std::vector<Vec3>& old_springs,
                               std::vector<Entry>& fresh, std::vector<Vec3>& springs, bool keep_springs, Key key) {
  std::vector<std::size_t> new_ones;
  if (keep_springs) springs.assign(fresh.size(), Vec3::Zero());
  std::size_t a = 0;
  for (std::size_t b = 0; b < fresh.size(); ++b) {
    const auto kb = key(fresh[b]);
    while (a < old_entries.size() && key(old_entries[a]) < kb) ++a;
    if (a < old_entries.size() && key(old_entries[a]) == kb) {
      fresh[b] = old_entries[a];
      if (keep_springs) springs[b] = old_springs[a];
    } else {
      new_ones.push_back(b);
    }
  }
  return new_ones;
}

}  // namespace

std::vector<std::size_t> PairList::replace(std::vector<PairEntry>&& fresh, bool keep_springs) {
  std::vector<Vec3> springs;
  const auto new_ones = merge(pairs, spring, fresh, springs, keep_springs,
                              [](const PairEntry& e) { return (static_cast<std::uint64_t>(e.i) << 32) | static_cast<std::uint32_t>(e.j); });
  pairs = std::move(fresh);
  spring = std::move(springs);
  return new_ones;
}

std::vector<std::size_t> WallList::replace(std::vector<WallEntry>&& fresh, bool keep_springs) {
  std::vector<Vec3> springs;
  const auto new_ones = merge(entries, spring, fresh, springs, keep_springs, [](const WallEntry& e) { return e.i; });
  entries = std::move(fresh);
  spring = std::move(springs);
  return new_ones;
}

}  // namespace softpack
