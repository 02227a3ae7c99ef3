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

} // namespace HexEx
