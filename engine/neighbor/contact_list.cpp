#include "neighbor/contact_list.hpp"

namespace softpack {
namespace {

// Sorted merge of old entries into new ones by key; copies the spring of matching keys.
template <class Entry, class Key>
std::vector<Vec3> carry_springs(const std::vector<Entry>& old_entries,
                                const std::vector<Vec3>& old_springs,
                                const std::vector<Entry>& fresh, Key key) {
  std::vector<Vec3> springs(fresh.size(), Vec3::Zero());
  std::size_t a = 0;
  for (std::size_t b = 0; b < fresh.size(); ++b) {
    const auto kb = key(fresh[b]);
    while (a < old_entries.size() && key(old_entries[a]) < kb) ++a;
    if (a < old_entries.size() && key(old_entries[a]) == kb) springs[b] = old_springs[a];
  }
  return springs;
}

}  // namespace

void PairList::replace(std::vector<PairEntry>&& fresh, bool keep_springs) {
  if (keep_springs) {
    auto key = [](const PairEntry& e) { return (static_cast<long long>(e.i) << 32) | e.j; };
    spring = carry_springs(pairs, spring, fresh, key);
  }
  pairs = std::move(fresh);
}

void WallList::replace(std::vector<WallEntry>&& fresh, bool keep_springs) {
  if (keep_springs) spring = carry_springs(entries, spring, fresh, [](const WallEntry& e) { return e.i; });
  entries = std::move(fresh);
}

}  // namespace softpack
