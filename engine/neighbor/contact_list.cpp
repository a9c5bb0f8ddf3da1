#include "neighbor/contact_list.hpp"

namespace softpack {
namespace {

// Sorted merge of the old keys into the fresh ones (both sorted). For a fresh entry found in
// the old list, `carry(old_index, fresh_index)` copies what it keeps; the indices of the
// entries not found are returned, for the caller to compute their constants.
template <class OldKey, class FreshKey, class Carry>
std::vector<std::size_t> merge(std::size_t old_count, std::size_t fresh_count, OldKey old_key, FreshKey fresh_key, Carry carry) {
  std::vector<std::size_t> new_ones;
  std::size_t a = 0;
  for (std::size_t b = 0; b < fresh_count; ++b) {
    const auto kb = fresh_key(b);
    while (a < old_count && old_key(a) < kb) ++a;
    if (a < old_count && old_key(a) == kb) carry(a, b);
    else new_ones.push_back(b);
  }
  return new_ones;
}

std::uint64_t pair_key(std::int32_t i, std::int32_t j) {
  return (static_cast<std::uint64_t>(i) << 32) | static_cast<std::uint32_t>(j);
}

}  // namespace

std::vector<std::size_t> PairList::replace(const std::vector<PairEntry>& fresh, bool keep_springs) {
  ConstantArrays constants;
  constants.resize(k.field.size(), fresh.size());
  std::vector<Vec3> springs(keep_springs ? fresh.size() : 0, Vec3::Zero());
  const auto new_ones = merge(
      size(), fresh.size(), [&](std::size_t a) { return pair_key(i[a], j[a]); },
      [&](std::size_t b) { return pair_key(fresh[b].i, fresh[b].j); },
      [&](std::size_t a, std::size_t b) {
        constants.copy(k, a, b);
        if (keep_springs) springs[b] = spring[a];
      });
  i.resize(fresh.size()), j.resize(fresh.size()), r_sum.resize(fresh.size());
  for (std::size_t b = 0; b < fresh.size(); ++b) i[b] = fresh[b].i, j[b] = fresh[b].j, r_sum[b] = fresh[b].r_sum;
  k = std::move(constants);
  spring = std::move(springs);
  spring_live.clear();
  masked = false;
  live.clear();
  ++generation;
  return new_ones;
}

std::vector<std::size_t> WallList::replace(const std::vector<std::int32_t>& fresh, bool keep_springs) {
  ConstantArrays constants;
  constants.resize(k.field.size(), fresh.size());
  std::vector<Vec3> springs(keep_springs ? fresh.size() : 0, Vec3::Zero());
  const auto new_ones = merge(
      size(), fresh.size(), [&](std::size_t a) { return i[a]; }, [&](std::size_t b) { return fresh[b]; },
      [&](std::size_t a, std::size_t b) {
        constants.copy(k, a, b);
        if (keep_springs) springs[b] = spring[a];
      });
  i = fresh;
  k = std::move(constants);
  spring = std::move(springs);
  return new_ones;
}

}  // namespace softpack
