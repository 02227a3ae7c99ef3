#pragma once
/// @file HugePages.hh
/// @ingroup kernel
/// Large arrays on transparent huge pages: on Linux with transparent huge pages in "madvise"
/// mode, an untouched range advised with MADV_HUGEPAGE is backed by 2 MiB pages at its first
/// touch, one page fault per 2 MiB instead of one per 4 KiB. On this project's VM that makes
/// the first touch of 300 MB about 4 times cheaper in CPU time (0.15 -> 0.04 s) once the
/// guest has backed the memory. Elsewhere, or if the kernel refuses, nothing changes.

#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace HexEx {

/// Asks the kernel to back the 2 MiB-aligned part of the untouched range [p, p + bytes) with
/// huge pages (the parts before the first and after the last 2 MiB boundary keep 4 KiB
/// pages, so no memory beyond the range is used).
inline void adviseHugePages(const void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    constexpr std::uintptr_t kHuge = std::uintptr_t(1) << 21;
    const std::uintptr_t b = (reinterpret_cast<std::uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1);
    const std::uintptr_t e = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(kHuge - 1);
    if (e > b) madvise(reinterpret_cast<void*>(b), e - b, MADV_HUGEPAGE);
#else
    (void)p;
    (void)bytes;
#endif
}

/// Resizes @p v to @p n elements, advising the new storage for huge pages before the new
/// elements are constructed (value-initialised, or left as they are by an allocator such
/// as DefaultInitAllocator). Meant for empty vectors of many MiB that are then filled.
template <class T, class Alloc>
void resizeOnHugePages(std::vector<T, Alloc>& v, std::size_t n) {
    if (n > v.capacity()) {
        v.reserve(n);
        adviseHugePages(v.data() + v.size(), (n - v.size()) * sizeof(T));
    }
    v.resize(n);
}

} // namespace HexEx
