#pragma once
/// @file Prefetch.hh
/// @ingroup kernel
/// A portable cache-line prefetch hint.

namespace HexEx {

/// Asks the CPU to load @p p's cache line early (for walks that jump around big arrays);
/// a no-op where the compiler offers no builtin.
inline void prefetch(const void* p) {
#if defined(__GNUC__)
    __builtin_prefetch(p);
#else
    (void)p;
#endif
}

/// prefetch() for a loop that does nothing but prefetch (requests ahead of the real work):
/// GCC deletes such a loop, a prefetch being no side effect to it; the empty volatile asm
/// that takes @p p keeps the loop.
inline void prefetchKept(const void* p) {
#if defined(__GNUC__)
    __builtin_prefetch(p);
    asm volatile("" : : "r"(p));
#else
    (void)p;
#endif
}

} // namespace HexEx
