#pragma once
/// @file LccVertexNumbering.hh
/// @ingroup adapters
/// Numbers of the vertex attributes of a CGAL Linear_cell_complex, found from an
/// attribute's address (used by the CGAL adapter, CgalLinearCellComplex.hh).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace HexEx {
namespace detail {

/// Numbers the vertex attributes of an LCC 0, 1, ... in their container order and finds the
/// number of an attribute from its address.
///
/// CGAL keeps the attributes in blocks of consecutive objects (Compact_container), so the
/// pass over them finds a few hundred runs of consecutive addresses; a lookup is a binary
/// search over these runs (held in cache) instead of a hash-table probe into memory. Only
/// the container's iteration and the addresses of its elements are used: with erased
/// attributes (holes in a block) the runs just split.
class LccVertexNumbering {
public:
    /// Returned by find() for an address that is not one of the numbered attributes.
    static constexpr std::size_t npos = static_cast<std::size_t>(-1);

    /// Numbers the attributes of @p lcc (one pass over `lcc.vertex_attributes()`).
    template <class LCC>
    explicit LccVertexNumbering(const LCC& lcc) {
        stride_ = sizeof(*lcc.vertex_attributes().begin());
        std::uint64_t odd = stride_;
        while (!(odd & 1u)) {
            odd >>= 1;
            ++shift_;
        }
        lowMask_ = (std::uintptr_t(1) << shift_) - 1;
        inverse_ = odd;  // Newton's iteration: each step doubles the correct low bits (3 -> 96)
        for (int i = 0; i < 5; ++i) inverse_ *= 2 - odd * inverse_;
        for (auto it = lcc.vertex_attributes().begin(); it != lcc.vertex_attributes().end(); ++it) {
            const std::uintptr_t a = reinterpret_cast<std::uintptr_t>(&*it);
            if (runs_.empty() || a != runs_.back().begin + runs_.back().count * stride_) runs_.push_back({a, size_, 0});
            ++runs_.back().count;
            ++size_;
        }
        std::sort(runs_.begin(), runs_.end(), [](const Run& x, const Run& y) { return x.begin < y.begin; });
    }

    /// Number of attributes.
    std::size_t size() const { return size_; }

    /// The number of the attribute at @p p, npos if @p p is not one of them.
    std::size_t find(const void* p) const {
        std::size_t hint = 0;
        return find(p, hint);
    }
    /// The same, trying the run of @p hint first (a run index the caller keeps between
    /// calls, any value allowed) and setting it to the run of @p p: the corners of
    /// consecutive volumes mostly lie in the same few runs, so the binary search is skipped.
    std::size_t find(const void* p, std::size_t& hint) const {
        const std::uintptr_t a = reinterpret_cast<std::uintptr_t>(p);
        if (hint >= runs_.size() || a < runs_[hint].begin || a - runs_[hint].begin >= runs_[hint].count * stride_) {
            auto it = std::upper_bound(runs_.begin(), runs_.end(), a, [](std::uintptr_t x, const Run& r) { return x < r.begin; });
            if (it == runs_.begin()) return npos;
            hint = static_cast<std::size_t>(it - runs_.begin()) - 1;
        }
        const Run& r = runs_[hint];
        const std::uintptr_t offset = a - r.begin;
        // offset / stride_ without a division: stride_ = odd << shift_, and an exact multiple
        // of odd times its inverse modulo 2^64 gives the quotient (anything else gives a
        // value beyond every run's count).
        if (offset & lowMask_) return npos;
        const std::uint64_t q = (static_cast<std::uint64_t>(offset) >> shift_) * inverse_;
        if (q >= r.count) return npos;
        return r.first + static_cast<std::size_t>(q);
    }

private:
    /// Attributes first .. first + count - 1 at addresses begin, begin + stride, ...
    struct Run {
        std::uintptr_t begin;  ///< address of the first attribute of the run
        std::size_t first;     ///< its number
        std::size_t count;     ///< attributes in the run
    };
    std::vector<Run> runs_;   ///< sorted by address
    std::size_t stride_ = 1;  ///< size of an attribute object
    unsigned shift_ = 0;              ///< stride_ = odd << shift_
    std::uintptr_t lowMask_ = 0;      ///< (1 << shift_) - 1
    std::uint64_t inverse_ = 1;       ///< odd^-1 modulo 2^64
    std::size_t size_ = 0;    ///< attributes numbered
};

} // namespace detail
} // namespace HexEx
