#pragma once
// A std::allocator that asks the kernel for transparent huge pages (2 MB) on large blocks: the
// block is aligned to 2 MB and marked with madvise(MADV_HUGEPAGE), so filling a growing array of
// hundreds of MB takes a few hundred page faults instead of tens of thousands of 4 KB ones (the
// Delaunay kernels' tet arrays). Small blocks, and systems without madvise, get plain memory,
// aligned to a cache line. Value-initialisation (`resize`) leaves trivial elements unwritten, as
// NoFillAllocator below: for arrays whose every element the code writes before reading it.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace riemesh {

namespace detail {

inline constexpr std::size_t kHugePage = std::size_t{1} << 21;
inline constexpr std::align_val_t kCacheLine{64};

/// Asks for huge pages on the 2 MB-aligned part of [p, p + bytes) (a hint; no effect on
/// correctness, errors ignored).
inline void advise_huge_pages(void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const auto begin = (reinterpret_cast<std::uintptr_t>(p) + kHugePage - 1) & ~(kHugePage - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(kHugePage - 1);
  if (end > begin) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

}  // namespace detail

template <class T>
struct HugePageAllocator {
  using value_type = T;

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    if (bytes < detail::kHugePage)
      return static_cast<T*>(::operator new(bytes, detail::kCacheLine));
    // Rounded up to whole huge pages, as aligned_alloc requires a multiple of the alignment.
    const std::size_t rounded = (bytes + detail::kHugePage - 1) & ~(detail::kHugePage - 1);
    void* p = std::aligned_alloc(detail::kHugePage, rounded);
    if (!p) throw std::bad_alloc();
    detail::advise_huge_pages(p, rounded);
    return static_cast<T*>(p);
  }

  void deallocate(T* p, std::size_t n) noexcept {
    if (n * sizeof(T) < detail::kHugePage)
      ::operator delete(p, detail::kCacheLine);
    else
      std::free(p);
  }

  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }

  template <class U>
  bool operator==(const HugePageAllocator<U>&) const noexcept {
    return true;
  }
};

/// std::allocator whose value-initialisation (what `resize` and `vector(n)` ask for) is
/// default-initialisation: a resized array of ints or doubles is left unwritten instead of
/// zero-filled, for arrays whose every element the code writes before reading it (the 2D Delaunay
/// kernel's triangle arrays grow by chunks it then fills). Any other construction as usual.
template <class T>
struct NoFillAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = NoFillAllocator<U>;
  };
  NoFillAllocator() = default;
  template <class U>
  NoFillAllocator(const NoFillAllocator<U>&) noexcept {}

  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

}  // namespace riemesh
