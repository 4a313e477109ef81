#pragma once
// Reserving the large arrays of the remeshers with a transparent-huge-page hint. A mesh of
// 1.76 M triangles touches ~500 MB of fresh memory in one 2D adaptation: with 4 KB pages that
// is ~140,000 page faults and as many TLB entries walked at random; on Linux with
// transparent huge pages in "madvise" mode (the usual default) the hint makes them 2 MB pages.
// The hint changes no value (results stay identical); elsewhere it is a plain reserve.
#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace riemesh {

/// Arrays below this size are left alone (a huge page would only round them up).
inline constexpr std::size_t kHugePageMinBytes = std::size_t{4} << 20;

/// Asks the kernel for huge pages on the 2 MB-aligned part of [data, data + bytes) not yet
/// touched. Advisory: an error (no THP support) is ignored.
inline void advise_huge_pages([[maybe_unused]] void* data, [[maybe_unused]] std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
  if (bytes < kHugePageMinBytes) return;
  const std::uintptr_t lo = (reinterpret_cast<std::uintptr_t>(data) + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t hi = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kHuge - 1);
  if (hi > lo) (void)madvise(reinterpret_cast<void*>(lo), hi - lo, MADV_HUGEPAGE);
#endif
}

/// v.reserve(n) for an empty v, with the huge-page hint on the new storage (call before the
/// first write: pages already touched stay small).
template <class T, class A>
void reserve_huge(std::vector<T, A>& v, std::size_t n) {
  v.reserve(n);
  advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

/// std::vector<T>(n, value) with the huge-page hint on its storage before it is filled.
template <class T>
std::vector<T> huge_vector(std::size_t n, const T& value = T()) {
  std::vector<T> v;
  reserve_huge(v, n);
  v.assign(n, value);
  return v;
}

}  // namespace riemesh
