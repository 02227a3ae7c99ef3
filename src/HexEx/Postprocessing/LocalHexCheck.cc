#include "LocalHexCheck.hh"

#include "../Core/Prefetch.hh"

#include <array>
#include <cstddef>
#include <cstdint>

namespace HexEx {

namespace {

/// The darts of one 48-dart cell numbered 0..47 (their order in the cell list), and the
/// cell's alpha_0..alpha_2 links in those numbers, so that the orbit checks walk a table of
/// 144 bytes instead of the link array.
class LocalCell {
public:
    /// Numbers @p cell (48 distinct darts, all links 0..2 inside the cell).
    LocalCell(const std::vector<std::array<int, 4>>& alpha, const std::vector<int>& cell) {
        key_.fill(-1);
        for (std::size_t k = 0; k < cell.size(); ++k) {
            unsigned s = slot(cell[k]);
            while (key_[s] >= 0) s = (s + 1) & (kSlots - 1);
            key_[s] = cell[k];
            val_[s] = static_cast<std::uint8_t>(k);
        }
        for (std::size_t k = 0; k < cell.size(); ++k)
            for (int i = 0; i < 3; ++i) link_[k][static_cast<std::size_t>(i)] = local(alpha[static_cast<std::size_t>(cell[k])][static_cast<std::size_t>(i)]);
    }
    /// alpha_i of local dart @p k, as a local dart.
    int a(int k, int i) const { return link_[static_cast<std::size_t>(k)][static_cast<std::size_t>(i)]; }

private:
    static constexpr unsigned kSlots = 128;
    static unsigned slot(int d) { return (static_cast<std::uint32_t>(d) * 2654435761u) >> 25; }
    /// The number of @p d, a dart of the cell.
    std::uint8_t local(int d) const {
        unsigned s = slot(d);
        while (key_[s] != d) s = (s + 1) & (kSlots - 1);
        return val_[s];
    }
    std::array<int, kSlots> key_;
    std::array<std::uint8_t, kSlots> val_{};
    std::array<std::array<std::uint8_t, 3>, 48> link_{};
};

/// Checks one cell, whose darts are @p cell (all marked @p in_cell, all links 0..2 valid
/// involutions without fixed points inside the cell).
///
/// Equations 3-5 ask every dart's orbit under two alternating involutions to have a given
/// length. Both maps are involutions without fixed points on the cell's darts (alpha_1
/// alpha_2 alpha_1 too), so each orbit is a cycle whose links alternate between the two, and
/// the alternating walk from any of its darts returns after the cycle's length: the length
/// is the same for every dart of the orbit, and one walk per orbit decides for all of its
/// darts what a walk from each of them would.
bool cellIsHex(const std::vector<std::array<int, 4>>& alpha, const std::vector<char>& alive, const std::vector<int>& cell,
               const std::vector<std::uint8_t>& mark, std::uint8_t in_cell) {
    if (cell.size() != 48) return false;
    const LocalCell c(alpha, cell);
    // Length of the orbit of local dart k under alternately f and g (at most 49); every
    // dart passed is added to @p seen.
    auto orbit = [&](int k, auto f, auto g, std::uint64_t& seen) {
        int x = k, n = 0;
        do {
            seen |= std::uint64_t(1) << x;
            x = (n % 2 == 0) ? f(x) : g(x);
            ++n;
        } while (x != k && n <= 48);
        return n;
    };
    auto a0 = [&](int x) { return c.a(x, 0); };
    auto a1 = [&](int x) { return c.a(x, 1); };
    auto a2 = [&](int x) { return c.a(x, 2); };
    auto a121 = [&](int x) { return c.a(c.a(c.a(x, 1), 2), 1); };
    std::uint64_t seen3 = 0, seen4 = 0, seen5 = 0;
    for (int k = 0; k < 48; ++k) {
        if (c.a(c.a(c.a(c.a(k, 0), 2), 0), 2) != k) return false;                         // eq1
        if (!(seen3 >> k & 1) && orbit(k, a0, a1, seen3) != 8) return false;              // eq3
        if (!(seen4 >> k & 1) && orbit(k, a1, a2, seen4) != 6) return false;              // eq4
        if (!(seen5 >> k & 1) && orbit(k, a0, a121, seen5) != 8) return false;            // eq5
    }
    auto a = [&](int d, int i) { return alpha[static_cast<std::size_t>(d)][static_cast<std::size_t>(i)]; };
    auto usable = [&](int x) { return x >= 0 && alive[static_cast<std::size_t>(x)]; };
    // The alpha_3 partners lie in other cells, elsewhere in the arrays: fetch them all at
    // once instead of one miss after the other.
    for (int d : cell) {
        const int p = a(d, 3);
        if (p >= 0) {
            prefetch(&alpha[static_cast<std::size_t>(p)]);
            prefetch(&alive[static_cast<std::size_t>(p)]);
        }
    }
    for (int d : cell) {
        const int p = a(d, 3);
        if (p < 0 || p == d) continue;                      // boundary or unconnected
        if (!usable(p) || a(p, 3) != d) return false;
        if (mark[static_cast<std::size_t>(p)] & in_cell) return false;  // glued to itself
        for (int i = 0; i < 2; ++i) {                                     // eq2
            const int q = a(p, i);
            if (!usable(q)) return false;
            const int r = a(q, 3);
            if (!usable(r) || a(r, i) != d) return false;
        }
    }
    return true;
}

} // namespace

long countDefectiveHexCells(const std::vector<std::array<int, 4>>& alpha, const std::vector<char>& alive,
                            const std::vector<int>& seeds, std::vector<std::uint8_t>& mark, std::uint8_t in_cell,
                            std::uint8_t done, std::vector<int>* bad_darts, long stop_after) {
    long bad = 0;
    std::vector<int> cell, doneList;
    auto M = [&](int d) -> std::uint8_t& { return mark[static_cast<std::size_t>(d)]; };
    for (int s : seeds) {
        if (s < 0 || !alive[static_cast<std::size_t>(s)] || (M(s) & done)) continue;
        // Breadth-first over alpha_0..alpha_2; a broken link makes the cell defective but
        // the walk still collects what it reaches (at most 4 cells' worth).
        cell.clear();
        cell.push_back(s);
        M(s) |= in_cell;
        bool linksOk = true;
        for (std::size_t k = 0; k < cell.size() && cell.size() <= 192; ++k) {
            const int d = cell[k];
            for (int i = 0; i < 3; ++i) {
                const int p = alpha[static_cast<std::size_t>(d)][static_cast<std::size_t>(i)];
                if (p < 0 || p == d || !alive[static_cast<std::size_t>(p)] ||
                    alpha[static_cast<std::size_t>(p)][static_cast<std::size_t>(i)] != d) {
                    linksOk = false;
                    continue;
                }
                if (!(M(p) & in_cell)) {
                    M(p) |= in_cell;
                    cell.push_back(p);
                }
            }
        }
        const bool ok = linksOk && cellIsHex(alpha, alive, cell, mark, in_cell);
        for (int d : cell) {
            M(d) = static_cast<std::uint8_t>((M(d) & ~in_cell) | done);
            doneList.push_back(d);
        }
        if (!ok) {
            ++bad;
            if (bad_darts) bad_darts->insert(bad_darts->end(), cell.begin(), cell.end());
            if (bad == stop_after) break;  // (never for stop_after <= 0)
        }
    }
    for (int d : doneList) M(d) = static_cast<std::uint8_t>(M(d) & ~done);
    return bad;
}

} // namespace HexEx
