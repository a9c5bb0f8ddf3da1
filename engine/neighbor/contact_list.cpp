#include "neighbor/contact_list.hpp"

namespace softpack {
namespace {

// Sorted merge of the old entries into the fresh ones (both sorted by `key`). For a fresh
// entry found in the old list, `carry(old_index, fresh_index)` copies what it keeps; the
// indices of the entries not found are returned, for the caller to compute their constants.
template <class Entry, class Key, class Carry>
std::vector<std::size_t> merge(const std::vector<Entry>& old_entries, const std::vector<Entry>& fresh, Key key,
                               Carry carry) {
  std::vector<std::size_t> new_ones;
  std::size_t a = 0;
  for (std::size_t b = 0; b < fresh.size(); ++b) {
    const auto kb = key(fresh[b]);
    while (a < old_entries.size() && key(old_entries[a]) < kb) ++a;
    if (a < old_entries.size() && key(old_entries[a]) == kb) carry(a, b);
    else new_ones.push_back(b);
  }
  return new_ones;
}

}  // namespace

std::vector<std::size_t> PairList::replace(std::vector<PairEntry>&& fresh, bool keep_springs) {
  std::vector<ContactCoefficients> coefficients(fresh.size());
  std::vector<Vec3> springs(keep_springs ? fresh.size() : 0, Vec3::Zero());
  const auto new_ones = merge(
      pairs, fresh, [](const PairEntry& e) { return (static_cast<std::uint64_t>(e.i) << 32) | static_cast<std::uint32_t>(e.j); },
      [&](std::size_t a, std::size_t b) {
        coefficients[b] = k[a];
        if (keep_springs) springs[b] = spring[a];
      });
  pairs = std::move(fresh);
  k = std::move(coefficients);
  spring = std::move(springs);
  spring_live.clear();
  return new_ones;
}

std::vector<std::size_t> WallList::replace(std::vector<WallEntry>&& fresh, bool keep_springs) {
  std::vector<Vec3> springs(keep_springs ? fresh.size() : 0, Vec3::Zero());
  const auto new_ones = merge(entries, fresh, [](const WallEntry& e) { return e.i; }, [&](std::size_t a, std::size_t b) {
    fresh[b].k = entries[a].k;
    if (keep_springs) springs[b] = spring[a];
  });
  entries = std::move(fresh);
  spring = std::move(springs);
  return new_ones;
}

}  // namespace softpack
