#include "LocalHexCheck.hh"

#include <cstddef>

namespace HexEx {

namespace {

/// Checks one cell, whose darts are @p cell (all marked @p in_cell, all links 0..2 valid involutions).
bool cellIsHex(const std::vector<std::array<int, 4>>& alpha, const std::vector<char>& alive, const std::vector<int>& cell,
               const std::vector<std::uint8_t>& mark, std::uint8_t in_cell) {
    if (cell.size() != 48) return false;
    auto a = [&](int d, int i) { return alpha[static_cast<std::size_t>(d)][static_cast<std::size_t>(i)]; };
    // Length of the orbit of d under alternately applying f and g (both involutions here).
    auto orbit = [&](int d, auto f, auto g) {
        int x = d, n = 0;
        do {
            x = (n % 2 == 0) ? f(x) : g(x);
            ++n;
        } while (x != d && n <= 48);
        return n;
    };
    auto a0 = [&](int x) { return a(x, 0); };
    auto a1 = [&](int x) { return a(x, 1); };
    auto a2 = [&](int x) { return a(x, 2); };
    auto a121 = [&](int x) { return a(a(a(x, 1), 2), 1); };
    auto usable = [&](int x) { return x >= 0 && alive[static_cast<std::size_t>(x)]; };
    for (int d : cell) {
        if (a(a(a(a(d, 0), 2), 0), 2) != d) return false;   // eq1
        if (orbit(d, a0, a1) != 8) return false;            // eq3
        if (orbit(d, a1, a2) != 6) return false;            // eq4
        if (orbit(d, a0, a121) != 8) return false;          // eq5
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
                            std::uint8_t done, std::vector<int>* bad_darts) {
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
        }
    }
    for (int d : doneList) M(d) = static_cast<std::uint8_t>(M(d) & ~done);
    return bad;
}

} // namespace HexEx
