// Insertion orders of the 3D Delaunay kernel (declared in delaunay3d.hpp).
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>

#include "generate/delaunay3d.hpp"
#include "mesh/hilbert.hpp"

namespace riemesh {

namespace {

/// SplitMix64 (Steele, Lea & Flood 2014): a small deterministic generator for the shuffle.
std::uint64_t split_mix(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

/// Sorts ids[begin, end) by Hilbert key, ties by id (deterministic). The (key, id) pairs are
/// sorted together: comparing ids through keys[id] read the keys in random order, a cache miss
/// per comparison on large inputs.
void sort_by_key(std::vector<Id>& ids, std::size_t begin, std::size_t end,
                 const std::vector<std::uint64_t>& keys) {
  std::vector<std::pair<std::uint64_t, Id>> pairs(end - begin);
  for (std::size_t i = begin; i < end; ++i)
    pairs[i - begin] = {keys[static_cast<std::size_t>(ids[i])], ids[i]};
  std::sort(pairs.begin(), pairs.end());
  for (std::size_t i = begin; i < end; ++i) ids[i] = pairs[i - begin].second;
}

}  // namespace

std::vector<Id> insertion_order(const std::vector<double>& coords, InsertionOrder order) {
  const std::size_t n = coords.size() / 3;
  std::vector<Id> ids(n);
  std::iota(ids.begin(), ids.end(), Id{0});
  if (order == InsertionOrder::kAsGiven || n == 0) return ids;
  // Points already sorted along a curve: BRIO's rounds over their order, no sort. Inserted as
  // given, each point lands on the frontier of the region triangulated so far, next to its flat
  // hull tets: a third more conflict tests and deleted tets per point than with rounds.
  if (order == InsertionOrder::kRounds) return brio_rounds(ids);
  if (order == InsertionOrder::kCoarseFirst) return coarse_first(ids);
  const std::vector<std::uint64_t> keys = hilbert_keys(coords, 3);
  if (order == InsertionOrder::kHilbert) {
    sort_by_key(ids, 0, n, keys);
    return ids;
  }
  // BRIO: shuffle, then rounds [n/2, n), [n/4, n/2), ... down to a first round of at most
  // kFirst points, each round sorted along the curve. The randomness between rounds keeps the
  // expected cavity sizes small; the sorting inside a round keeps the walks short.
  constexpr std::size_t kFirst = 1000;
  std::uint64_t state = 0x5EED;
  for (std::size_t i = n - 1; i > 0; --i)
    std::swap(ids[i], ids[static_cast<std::size_t>(split_mix(state) % (i + 1))]);
  std::size_t end = n;
  while (end > 0) {
    const std::size_t begin = end > kFirst ? end / 2 : 0;
    sort_by_key(ids, begin, end, keys);
    end = begin;
  }
  return ids;
}

}  // namespace riemesh
