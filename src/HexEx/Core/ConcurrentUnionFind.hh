#pragma once
/// @file ConcurrentUnionFind.hh
/// @ingroup kernel
/// Union-find over dense 32-bit ids that several threads may unite at once.

#include <cstddef>
#include <utility>
#include <vector>

namespace HexEx {

/// Disjoint sets over the ids 0 .. n-1 that threads may unite concurrently (lock-free: a
/// root is linked by compare-and-swap, paths are halved by compare-and-swap). A union links
/// the larger root below the smaller one, so every parent is at most its child and every
/// class's root is its smallest id: the classes and their roots do not depend on the order
/// of the unions or on the number of threads.
struct ConcurrentUnionFind {
    /// Parent per id; a root is its own parent. Public so that callers may reuse the
    /// storage once the classes are final (e.g. for labels).
    std::vector<int> parent;

    /// @p n singleton sets.
    explicit ConcurrentUnionFind(std::size_t n) : parent(n) {
        for (std::size_t i = 0; i < n; ++i) parent[i] = static_cast<int>(i);
    }
    /// Root of the set of @p x (halves the path on the way).
    int find(int x) {
        for (;;) {
            int p = load(x);
            if (p == x) return x;
            const int g = load(p);
            if (g != p) __atomic_compare_exchange_n(slot(x), &p, g, false, __ATOMIC_RELAXED, __ATOMIC_RELAXED);
            x = g;
        }
    }
    /// Joins the sets of @p x and @p y.
    void unite(int x, int y) {
        for (;;) {
            x = find(x);
            y = find(y);
            if (x == y) return;
            if (x < y) std::swap(x, y);
            int expected = x;  // x is still a root if nobody linked it meanwhile
            if (__atomic_compare_exchange_n(slot(x), &expected, y, false, __ATOMIC_RELAXED, __ATOMIC_RELAXED)) return;
        }
    }
    /// Root of the set of @p x without changing the parents (for passes that run while other
    /// threads flatten).
    int rootOf(int x) const {
        for (int p = load(x); p != x; p = load(x)) x = p;
        return x;
    }
    /// Sets the parent of @p x to @p p (an atomic store).
    void store(int x, int p) { __atomic_store_n(slot(x), p, __ATOMIC_RELAXED); }
    /// Parent of @p x (an atomic load).
    int load(int x) const { return __atomic_load_n(&parent[static_cast<std::size_t>(x)], __ATOMIC_RELAXED); }

private:
    int* slot(int x) { return &parent[static_cast<std::size_t>(x)]; }
};

} // namespace HexEx
