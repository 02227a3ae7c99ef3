#include "DartReconnection.hh"

#include "LocalHexCheck.hh"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <utility>

namespace HexEx {

namespace {

/// A frame (z, d1, d2, d3) in some chart.
struct Frame {
    Vec3i z;                   ///< grid point
    std::array<AxisDir, 3> d;  ///< directions
};

/// A rigid grid motion x -> R x + t with R a signed axis permutation (img[a]: image of +axis a).
struct Motion {
    std::array<AxisDir, 3> img{{0, 2, 4}};  ///< images of +x, +y, +z
    Vec3i t{0, 0, 0};                       ///< translation

    AxisDir dir(AxisDir d) const { return dirSign(d) > 0 ? img[dirAxis(d)] : dirNeg(img[dirAxis(d)]); }
    Vec3i vec(const Vec3i& v) const {
        Vec3i r(0, 0, 0);
        for (int a = 0; a < 3; ++a) r += v[a] * dirVec(img[a]);
        return r;
    }
    Frame apply(const Frame& f) const { return {vec(f.z) + t, {{dir(f.d[0]), dir(f.d[1]), dir(f.d[2])}}}; }
    /// this after @p o.
    Motion after(const Motion& o) const {
        Motion m;
        for (int a = 0; a < 3; ++a) m.img[a] = dir(o.img[a]);
        m.t = vec(o.t) + t;
        return m;
    }
    /// The motion that maps frame @p from onto frame @p to.
    static Motion between(const Frame& from, const Frame& to) {
        Motion m;
        for (int k = 0; k < 3; ++k) m.img[dirAxis(from.d[k])] = dirSign(from.d[k]) > 0 ? to.d[k] : dirNeg(to.d[k]);
        m.t = to.z - m.vec(from.z);
        return m;
    }
    auto key() const { return std::make_tuple(img[0], img[1], img[2], t[0], t[1], t[2]); }
    bool operator<(const Motion& o) const { return key() < o.key(); }
};

/// The expected partner alpha_i*(f), in f's chart.
Frame expectedPartner(const Frame& f, int i) {
    Frame e = f;
    switch (i) {
    case 0:
        e.z = f.z + dirVec(f.d[0]);
        e.d[0] = dirNeg(f.d[0]);
        break;
    case 1: std::swap(e.d[0], e.d[1]); break;
    case 2: std::swap(e.d[1], e.d[2]); break;
    default: e.d[2] = dirNeg(f.d[2]); break;
    }
    return e;
}

/// Lower corner of the unit cube that frame f spans.
Vec3i cubeOf(const Frame& f) {
    Vec3i lo = f.z;
    for (int k = 0; k < 3; ++k)
        if (dirSign(f.d[k]) < 0) lo[dirAxis(f.d[k])] -= 1;
    return lo;
}

/// Index 0..47 of a frame within its cube: corner (3 bits) and the direction permutation.
int flagIndex(const Frame& f, const Vec3i& lo) {
    const Vec3i c = f.z - lo;
    const int corner = c[0] + 2 * c[1] + 4 * c[2];
    const int perm = dirAxis(f.d[0]) * 2 + (dirAxis(f.d[1]) > dirAxis(f.d[2]) ? 1 : 0);
    return corner * 6 + perm;
}

using Key3 = std::tuple<int, int, int>;
Key3 key3(const Vec3i& v) { return std::make_tuple(v[0], v[1], v[2]); }

/// The frame with index @p f (flagIndex()) of the cube with lower corner @p lo.
Frame flagFrame(const Vec3i& lo, int f) {
    const int corner = f / 6, perm = f % 6;
    Frame r;
    r.z = lo + Vec3i(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    const int a1 = perm / 2;
    int rest[2], n = 0;
    for (int a = 0; a < 3; ++a)
        if (a != a1) rest[n++] = a;
    const int axes[3] = {a1, perm % 2 ? rest[1] : rest[0], perm % 2 ? rest[0] : rest[1]};
    for (int k = 0; k < 3; ++k) r.d[static_cast<std::size_t>(k)] = makeDir(axes[k], r.z[axes[k]] == lo[axes[k]] ? 1 : -1);
    return r;
}

/// Re-links the darts of @p group (frames @p common in one chart, which must fill whole
/// cubes, each flag once) cube by cube, and keeps the links only if the new cells and the
/// cells linked to them by alpha_3 pass the hex check. Returns the cells formed, or 0
/// (links unchanged, @p why set).
long relinkCubes(std::vector<std::array<int, 4>>& alpha, const std::vector<char>& alive, const std::vector<int>& group,
                 const std::vector<Frame>& common, std::vector<std::uint8_t>& mark, std::string& why) {
    std::map<Key3, std::array<int, 48>> cubes;
    for (std::size_t k = 0; k < group.size(); ++k) {
        const Vec3i lo = cubeOf(common[k]);
        auto ins = cubes.emplace(key3(lo), std::array<int, 48>{});
        if (ins.second) ins.first->second.fill(-1);
        int& s = ins.first->second[static_cast<std::size_t>(flagIndex(common[k], lo))];
        if (s >= 0) {
            why = "two darts on one corner, edge and face of a cube in the common chart";
            return 0L;
        }
        s = group[k];
    }
    if (cubes.size() * 48 != group.size()) {
        why = "the darts do not fill whole cubes in the common chart";
        return 0L;
    }
    std::vector<std::array<int, 4>> old(group.size());
    for (std::size_t k = 0; k < group.size(); ++k) old[k] = alpha[static_cast<std::size_t>(group[k])];
    for (std::size_t k = 0; k < group.size(); ++k) {
        const Vec3i lo = cubeOf(common[k]);
        const auto& flags = cubes.at(key3(lo));
        for (int i = 0; i < 3; ++i)
            alpha[static_cast<std::size_t>(group[k])][static_cast<std::size_t>(i)] =
                flags[static_cast<std::size_t>(flagIndex(expectedPartner(common[k], i), lo))];
    }
    std::vector<int> seeds = group;
    for (int d : group) {
        const int p = alpha[static_cast<std::size_t>(d)][3];
        if (p >= 0 && p != d) seeds.push_back(p);
    }
    if (countDefectiveHexCells(alpha, alive, seeds, mark, 1, 2) != 0) {
        for (std::size_t k = 0; k < group.size(); ++k) alpha[static_cast<std::size_t>(group[k])] = old[k];
        why = "the re-linked cells do not pass the hex check";
        return 0L;
    }
    return static_cast<long>(cubes.size());
}

/// Places the pieces of @p group in the chart of piece @p root (each next piece by the
/// motion most links from placed pieces agree on) and, if the frames fill whole cubes,
/// re-links the darts cube by cube; keeps the links only if the cells pass the hex check.
/// Returns the cells formed, or 0 (links unchanged, @p why set).
template <class FrameOf>
long placeAndRelink(std::vector<std::array<int, 4>>& alpha, const std::vector<char>& alive, const std::vector<int>& group,
                    const std::vector<int>& tetOf, int nt, int root, const FrameOf& frameOf, const std::map<int, int>& slot,
                    std::vector<std::uint8_t>& mark, std::string& why) {
    std::vector<char> placed(static_cast<std::size_t>(nt), 0);
    std::vector<Motion> toCommon(static_cast<std::size_t>(nt));
    placed[static_cast<std::size_t>(root)] = 1;
    for (int done = 1; done < nt; ++done) {
        // Votes of the links from placed tets into unplaced ones.
        std::map<std::pair<int, Motion>, int> votes;
        for (std::size_t k = 0; k < group.size(); ++k) {
            if (!placed[static_cast<std::size_t>(tetOf[k])]) continue;
            const int d = group[k];
            for (int i = 0; i < 4; ++i) {
                const int p = alpha[static_cast<std::size_t>(d)][static_cast<std::size_t>(i)];
                if (p < 0 || p == d) continue;
                const auto it = slot.find(p);
                if (it == slot.end()) continue;
                const int tp = tetOf[static_cast<std::size_t>(it->second)];
                if (placed[static_cast<std::size_t>(tp)]) continue;
                // p's chart -> d's chart: p's frame onto alpha_i*(d); then d's chart -> common.
                const Motion m = toCommon[static_cast<std::size_t>(tetOf[k])].after(Motion::between(frameOf(p), expectedPartner(frameOf(d), i)));
                ++votes[{tp, m}];
            }
        }
        if (votes.empty()) {
            why = "darts not linked to each other";
            return 0L;
        }
        auto best = votes.begin();
        for (auto it = votes.begin(); it != votes.end(); ++it)
            if (it->second > best->second || (it->second == best->second && it->first.first < best->first.first)) best = it;
        placed[static_cast<std::size_t>(best->first.first)] = 1;
        toCommon[static_cast<std::size_t>(best->first.first)] = best->first.second;
    }
    // Frames in the common chart, by cube (slot k of group per flag).
    std::vector<Frame> common(group.size());
    std::map<Key3, std::array<int, 48>> cubes;
    std::vector<std::pair<int, int>> collisions;  // (slot already on the flag, slot placed on it again)
    for (std::size_t k = 0; k < group.size(); ++k) {
        common[k] = toCommon[static_cast<std::size_t>(tetOf[k])].apply(frameOf(group[k]));
        const Vec3i lo = cubeOf(common[k]);
        auto ins = cubes.emplace(key3(lo), std::array<int, 48>{});
        if (ins.second) ins.first->second.fill(-1);
        int& s = ins.first->second[static_cast<std::size_t>(flagIndex(common[k], lo))];
        if (s >= 0) collisions.emplace_back(s, static_cast<int>(k));
        else s = static_cast<int>(k);
    }
    if (cubes.size() * 48 != group.size()) {
        why = "the darts do not fill whole cubes in the common chart";
        return 0L;
    }
    if (collisions.empty()) return relinkCubes(alpha, alive, group, common, mark, why);
    // Split vertices: as many darts on taken flags as flags without a dart. Try putting one
    // dart of each colliding pair on a free flag (every choice, every assignment, at most
    // kMaxSplit pairs); keep the first that gives hexes.
    constexpr std::size_t kMaxSplit = 3;
    std::vector<Frame> holes;
    for (const auto& c : cubes)
        for (int f = 0; f < 48; ++f)
            if (c.second[static_cast<std::size_t>(f)] < 0) holes.push_back(flagFrame(Vec3i(std::get<0>(c.first), std::get<1>(c.first), std::get<2>(c.first)), f));
    if (holes.size() != collisions.size() || holes.size() > kMaxSplit) {
        why = std::to_string(collisions.size()) + " darts on corners, edges and faces of cubes that other darts already take, in the common chart";
        return 0L;
    }
    const std::size_t c = collisions.size();
    for (unsigned mask = 0; mask < (1u << c); ++mask) {
        std::vector<int> order(c);
        for (std::size_t j = 0; j < c; ++j) order[j] = static_cast<int>(j);
        do {
            std::vector<Frame> trial = common;
            for (std::size_t j = 0; j < c; ++j) {
                const int mover = (mask >> j) & 1u ? collisions[j].first : collisions[j].second;
                trial[static_cast<std::size_t>(mover)] = holes[static_cast<std::size_t>(order[j])];
            }
            const long formed = relinkCubes(alpha, alive, group, trial, mark, why);
            if (formed > 0) return formed;
        } while (std::next_permutation(order.begin(), order.end()));
    }
    why = std::to_string(c) + " darts on taken corners, edges and faces of cubes; no assignment to the free ones gives hexes";
    return 0L;
}

/// Tries to reconnect one group of broken cells (@p group: its darts, ascending). Returns
/// the number of hex cells formed (0: nothing changed) and sets @p why otherwise.
long reconnectGroup(std::vector<std::array<int, 4>>& alpha, const std::vector<char>& alive, const DartVector& darts,
                    const std::vector<int>* pieceOfTet, const std::vector<int>& group, std::vector<std::uint8_t>& mark, std::string& why) {
    if (group.size() % 48 != 0) {
        why = std::to_string(group.size()) + " darts, not a multiple of 48";
        return 0;
    }
    auto at = [&](int d) -> const Dart& { return darts[static_cast<std::size_t>(d)]; };
    auto frameOf = [&](int d) { return Frame{at(d).z, at(d).d}; };
    std::map<int, int> slot;  // dart -> position in group
    for (std::size_t k = 0; k < group.size(); ++k) slot[group[k]] = static_cast<int>(k);
    for (int d : group)
        if (at(d).sign < 0) {
            why = "anti darts left";
            return 0;
        }
    // Two tries. First the pieces are chart components (tets joined by identity transitions):
    // their frames are exact relative to each other. A component can reach around a singular
    // edge, though, and then holds darts of two cells that the edge's rotation relates (pig
    // folded by 1.5, seed 16: one component has 32 darts in one cube and 8 in another, and the
    // placement fills three cubes). So if that fails, the pieces are split further by the unit
    // cube their darts span in the component's chart, and each part is placed on its own.
    std::string firstWhy;
    for (int byCube = 0; byCube < 2; ++byCube) {
        // Pieces of the group, numbered by first occurrence (darts ascend, so deterministic).
        std::map<std::tuple<int, int, int, int>, int> pieceIndex;
        std::vector<int> pieceOf(group.size());
        for (std::size_t k = 0; k < group.size(); ++k) {
            const Dart& D = at(group[k]);
            const int component = pieceOfTet ? (*pieceOfTet)[static_cast<std::size_t>(D.tet)] : D.tet;
            const Vec3i lo = byCube ? cubeOf(frameOf(group[k])) : Vec3i(0, 0, 0);
            const auto ins = pieceIndex.emplace(std::make_tuple(component, lo[0], lo[1], lo[2]), static_cast<int>(pieceIndex.size()));
            pieceOf[k] = ins.first->second;
        }
        const int np = static_cast<int>(pieceIndex.size());
        std::vector<int> size(static_cast<std::size_t>(np), 0);
        for (int t : pieceOf) ++size[static_cast<std::size_t>(t)];
        // One attempt per root piece (the piece whose chart is the common one): a piece placed
        // wrong can only be outvoted if it is not the root. Roots by size (most darts first,
        // ties: first piece), at most kRoots of them.
        constexpr int kRoots = 8;
        std::vector<int> roots(static_cast<std::size_t>(np));
        for (int t = 0; t < np; ++t) roots[static_cast<std::size_t>(t)] = t;
        std::stable_sort(roots.begin(), roots.end(), [&](int x, int y) { return size[static_cast<std::size_t>(x)] > size[static_cast<std::size_t>(y)]; });
        if (roots.size() > static_cast<std::size_t>(kRoots)) roots.resize(kRoots);
        for (int root : roots) {
            const long formed = placeAndRelink(alpha, alive, group, pieceOf, np, root, frameOf, slot, mark, why);
            if (formed > 0) return formed;
        }
        if (byCube == 0) firstWhy = why;
    }
    if (why != firstWhy) why = firstWhy + "; with the chart components split by cube: " + why;
    return 0;
}

/// Defective cells among those of @p group when the alpha_3 links of the group's darts are
/// ignored (set free for the check and put back).
long cellsBrokenInside(std::vector<std::array<int, 4>>& alpha, const std::vector<char>& alive, const std::vector<int>& group,
                       std::vector<std::uint8_t>& mark) {
    std::vector<int> a3(group.size());
    for (std::size_t k = 0; k < group.size(); ++k) {
        a3[k] = alpha[static_cast<std::size_t>(group[k])][3];
        alpha[static_cast<std::size_t>(group[k])][3] = group[k];
    }
    const long n = countDefectiveHexCells(alpha, alive, group, mark, 1, 2);
    for (std::size_t k = 0; k < group.size(); ++k) alpha[static_cast<std::size_t>(group[k])][3] = a3[k];
    return n;
}

} // namespace

ReconnectionStats reconnectBrokenCells(std::vector<std::array<int, 4>>& alpha, const std::vector<char>& alive, const DartVector& darts,
                                       const std::function<std::vector<int>()>& chart_components, const std::vector<int>* seeds,
                                       std::vector<std::pair<int, std::array<int, 4>>>* undo) {
    ReconnectionStats st;
    const std::size_t n = alpha.size();
    std::vector<int> allAlive;
    if (!seeds) {
        for (std::size_t d = 0; d < n; ++d)
            if (alive[d]) allAlive.push_back(static_cast<int>(d));
        seeds = &allAlive;
    }
    std::vector<std::uint8_t> mark(n, 0);
    std::vector<int> bad;
    if (countDefectiveHexCells(alpha, alive, *seeds, mark, 1, 2, &bad) == 0) return st;
    std::vector<int> pieces;
    if (chart_components) pieces = chart_components();
    const std::vector<int>* pieceOfTet = pieces.empty() ? nullptr : &pieces;
    std::sort(bad.begin(), bad.end());
    bad.erase(std::unique(bad.begin(), bad.end()), bad.end());
    // Groups: broken-cell darts joined by any link, in order of their smallest dart.
    constexpr std::uint8_t kBad = 4, kSeen = 8;
    for (int d : bad) mark[static_cast<std::size_t>(d)] |= kBad;
    for (int s : bad) {
        if (mark[static_cast<std::size_t>(s)] & kSeen) continue;
        std::vector<int> group{s};
        mark[static_cast<std::size_t>(s)] |= kSeen;
        for (std::size_t k = 0; k < group.size(); ++k)
            for (int i = 0; i < 4; ++i) {
                const int p = alpha[static_cast<std::size_t>(group[k])][static_cast<std::size_t>(i)];
                if (p < 0 || !(mark[static_cast<std::size_t>(p)] & kBad) || (mark[static_cast<std::size_t>(p)] & kSeen)) continue;
                mark[static_cast<std::size_t>(p)] |= kSeen;
                group.push_back(p);
            }
        std::sort(group.begin(), group.end());
        // Only cells broken in their own links (alpha_0..alpha_2) are this stage's: a group
        // whose cells are hexes once their alpha_3 links are ignored (partially connected
        // or crossed quads) is left to the face repair and relinking.
        const long cellsBefore = cellsBrokenInside(alpha, alive, group, mark);
        if (cellsBefore == 0) {
            ++st.alpha3_only_groups;
            continue;
        }
        st.broken_cells += cellsBefore;
        std::string why;
        std::vector<std::array<int, 4>> before;
        if (undo)
            for (int d : group) before.push_back(alpha[static_cast<std::size_t>(d)]);
        const long formed = reconnectGroup(alpha, alive, darts, pieceOfTet, group, mark, why);
        if (formed > 0) {
            if (undo)
                for (std::size_t k = 0; k < group.size(); ++k) undo->emplace_back(group[k], before[k]);
            st.reconnected_cells += formed;
        } else {
            st.unresolved_cells += cellsBefore;
            if (st.unresolved.size() < 8) {
                st.unresolved.emplace_back(group.front(), why);
                st.unresolved_size.emplace_back(static_cast<long>(group.size()), cellsBefore);
            }
        }
    }
    return st;
}

} // namespace HexEx
