#pragma once
/// @file GMap.hh
/// @ingroup pipeline
/// A dimension-generic generalized map (paper section 3): darts with involutions
/// alpha_0 .. alpha_Dim. A free link is a fixed point (alpha_i(d) == d).

#include "../Core/Handles.hh"
#include "../Core/Property.hh"

#include <array>
#include <cstdint>
#include <vector>

namespace HexEx {

/// Tag of darts.
struct DartTag {};
/// Handle of a dart.
using DartHandle = Handle<DartTag>;

/// Generalized map of dimension @p Dim (2 or 3).
template <int Dim>
class GMap {
public:
    static_assert(Dim >= 1 && Dim <= 3, "GMap supports dimensions 1 to 3");
    /// Number of alpha links per dart.
    static constexpr int kLinks = Dim + 1;

    /// Adds a free dart.
    DartHandle add_dart() {
        const int d = static_cast<int>(alpha_.size());
        std::array<int, kLinks> a;
        a.fill(d);
        alpha_.push_back(a);
        alive_.push_back(1);
        props_.resize(alpha_.size());
        return DartHandle(d);
    }
    /// Adds @p n free darts; returns the first.
    DartHandle add_darts(std::size_t n) {
        const DartHandle first(static_cast<int>(alpha_.size()));
        alpha_.reserve(alpha_.size() + n);
        for (std::size_t k = 0; k < n; ++k) add_dart();
        return first;
    }
    /// Replaces the map by @p links (one entry per dart, all darts alive); entries must be
    /// valid dart indices (use the dart itself for a free link). Takes the vector over
    /// without copying.
    void assign_links(std::vector<std::array<int, kLinks>>&& links) {
        alpha_ = std::move(links);
        alive_.assign(alpha_.size(), 1);
        props_.resize(alpha_.size());
    }
    /// Number of dart slots (including erased ones).
    std::size_t n_darts() const { return alpha_.size(); }
    /// True if dart @p d was not erased.
    bool is_alive(DartHandle d) const { return alive_[d.uidx()] != 0; }
    /// alpha_i(d).
    DartHandle alpha(DartHandle d, int i) const { return DartHandle(alpha_[d.uidx()][i]); }
    /// True if alpha_i(d) == d.
    bool is_free(DartHandle d, int i) const { return alpha_[d.uidx()][i] == d.idx(); }
    /// Links d and e by alpha_i (both directions). Previous partners become free.
    void sew(DartHandle d, DartHandle e, int i) {
        unsew(d, i);
        unsew(e, i);
        alpha_[d.uidx()][i] = e.idx();
        alpha_[e.uidx()][i] = d.idx();
    }
    /// Sets only alpha_i(d) = e (for building maps whose links are computed per dart;
    /// run the validator to check they are involutions).
    void link(DartHandle d, DartHandle e, int i) { alpha_[d.uidx()][i] = e.idx(); }
    /// Frees alpha_i of d and of its partner.
    void unsew(DartHandle d, int i) {
        const int p = alpha_[d.uidx()][i];
        if (p != d.idx() && alpha_[static_cast<std::size_t>(p)][i] == d.idx()) alpha_[static_cast<std::size_t>(p)][i] = p;
        alpha_[d.uidx()][i] = d.idx();
    }
    /// Unsews all links of @p d and marks it erased.
    void erase(DartHandle d) {
        for (int i = 0; i < kLinks; ++i) unsew(d, i);
        alive_[d.uidx()] = 0;
    }
    /// The darts reachable from @p d using the links whose bits are set in @p mask
    /// (bit i = alpha_i), in breadth-first order starting with d.
    std::vector<DartHandle> orbit(DartHandle d, unsigned mask) const {
        std::vector<DartHandle> out{d};
        std::vector<int> seen{d.idx()};
        for (std::size_t q = 0; q < out.size(); ++q)
            for (int i = 0; i < kLinks; ++i) {
                if (!(mask & (1u << i))) continue;
                const int n = alpha_[out[q].uidx()][i];
                bool known = false;
                for (int s : seen)
                    if (s == n) { known = true; break; }
                if (!known) {
                    seen.push_back(n);
                    out.push_back(DartHandle(n));
                }
            }
        return out;
    }
    /// Dart properties.
    PropertyManager<DartTag>& dart_props() { return props_; }
    /// Raw links (for fast algorithms).
    const std::vector<std::array<int, kLinks>>& links() const { return alpha_; }

private:
    std::vector<std::array<int, kLinks>> alpha_;
    std::vector<std::uint8_t> alive_;
    PropertyManager<DartTag> props_;
};

} // namespace HexEx
