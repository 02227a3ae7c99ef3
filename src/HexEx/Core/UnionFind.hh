#pragma once
/// @file UnionFind.hh
/// @ingroup kernel
/// Union-find over dense 32-bit ids, shared by the orbit labellings and the assembly.

#include <cstddef>
#include <utility>
#include <vector>

namespace HexEx {

/// Disjoint sets over the ids 0 .. n-1 with path halving. A union makes the smaller root
/// the root of both, so every class's root is its smallest id once all unions are done.
struct UnionFind {
    /// Parent per id; a root is its own parent. Public so that callers may reuse the
    /// storage once the classes are final (e.g. for labels).
    std::vector<int> parent;

    /// @p n singleton sets.
    explicit UnionFind(std::size_t n) : parent(n) {
        for (std::size_t i = 0; i < n; ++i) parent[i] = static_cast<int>(i);
    }
    /// Root of the set of @p x.
    int find(int x) {
        while (parent[static_cast<std::size_t>(x)] != x) {
            const int p = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
            parent[static_cast<std::size_t>(x)] = p;
            x = p;
        }
        return x;
    }
    /// Joins the sets of @p x and @p y.
    void unite(int x, int y) {
        x = find(x);
        y = find(y);
        if (x == y) return;
        if (x < y) std::swap(x, y);
        parent[static_cast<std::size_t>(x)] = y;
    }
};

} // namespace HexEx
