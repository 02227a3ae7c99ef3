#pragma once
/// @file DefaultInitAllocator.hh
/// @ingroup kernel
/// An allocator whose resize() default-initializes instead of value-initializing, so that
/// a large array of a type with an empty default constructor can be sized without a
/// zeroing pass and then filled in parallel (pages are touched only once, by the writers).

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace HexEx {

/// std::allocator, except that construct() without arguments default-initializes.
template <class T>
struct DefaultInitAllocator : std::allocator<T> {
    /// The same allocator for another type.
    template <class U>
    struct rebind {
        using other = DefaultInitAllocator<U>;  ///< the rebound type
    };
    DefaultInitAllocator() noexcept = default;
    /// Converting constructor (stateless).
    template <class U>
    DefaultInitAllocator(const DefaultInitAllocator<U>&) noexcept {}
    /// Default-initializes *p (no zeroing for trivial members).
    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
    /// Constructs *p from @p args.
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

/// A std::vector whose resize() leaves new elements of trivial types uninitialized
/// (DefaultInitAllocator): for large arrays that are sized and then filled completely, in
/// parallel, with no serial zeroing pass (the pages are touched first by their writers).
template <class T>
using DefaultInitVector = std::vector<T, DefaultInitAllocator<T>>;

} // namespace HexEx
