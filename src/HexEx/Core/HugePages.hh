#pragma once
/// @file HugePages.hh
/// @ingroup kernel
/// Advice for transparent huge pages on large arrays: on Linux with transparent huge pages
/// in "madvise" mode, an untouched range advised with MADV_HUGEPAGE is backed by 2 MiB pages
/// at its first touch. Whether that pays depends on the machine: on this project's VM it
/// cut the page faults but raised the system time of one-shot `hexex` runs (issue 36, third
/// round, in performance.md), so the writers and the extraction stages do not use it; the
/// arc stage advises its growing output arrays. Elsewhere, or if the kernel refuses,
/// nothing changes.

#include <cstddef>
#include <cstdint>

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

} // namespace HexEx
