#include "HexMeshAssembly.hh"
#include "OccurrenceRanks.hh"

#include "VertexPreimageChoice.hh"

#include "../Core/Parallel.hh"
#include "../Core/ConcurrentUnionFind.hh"
#include "../GMap/GMapValidator.hh"

#include <algorithm>
#include <cstdint>
#include <iterator>

namespace HexEx {

namespace {
/// Groups dart indices by label (counting sort, ascending darts within a group).
void groupByLabel(const std::vector<int>& label, int n_labels, std::vector<int>& off, std::vector<int>& idx) {
    off.assign(static_cast<std::size_t>(n_labels) + 1, 0);
    for (int l : label)
        if (l >= 0) ++off[static_cast<std::size_t>(l) + 1];
    for (int l = 0; l < n_labels; ++l) off[static_cast<std::size_t>(l) + 1] += off[static_cast<std::size_t>(l)];
    idx.assign(static_cast<std::size_t>(off.back()), 0);
    std::vector<int> fill(off.begin(), off.end() - 1);
    for (std::size_t d = 0; d < label.size(); ++d)
        if (label[d] >= 0) idx[static_cast<std::size_t>(fill[static_cast<std::size_t>(label[d])]++)] = static_cast<int>(d);
}

} // namespace


HexMesh assembleHexMesh(const GMap<3>& g, const DartGeometry& geo, const HexOrbitLabels& labels, AssemblyStats& stats,
                        const ImplicitCells* implicit, int threads, std::vector<int>* hex_darts, std::vector<int>* label_storage,
                        std::vector<std::uint64_t>* private_vertices, OccurrenceRanks* occurrence_ranks) {
    HexMesh out;
    if (private_vertices) private_vertices->clear();
    const auto& L = g.links();
    auto a = [&](int d, int i) { return L[static_cast<std::size_t>(d)][i]; };

    // Vertex classes: <alpha_1, alpha_2, alpha_3> orbits, joined with the occurrences the
    // darts sit on or link to when cells are implicit. Numbered by first appearance (darts
    // in order, then occurrences in order): the same as labelling orbits by smallest dart.
    const std::size_t nd = g.n_darts();
    const long nocc = implicit ? implicit->n_occurrences : 0;
    int nv = 0;
    std::vector<int> vlabel;
    if (label_storage) vlabel = std::move(*label_storage);
    if (label_storage) label_storage->clear();
    // Implicit cells: per occurrence the union-find slot that ends up holding its label
    // (encoded as -2 - label), so the occurrences need no label array of their own.
    std::vector<int> occSlot;
    int nk = 0;  // corner orbits: occurrence o has the slot nk + occ.rank(o)
    OccurrenceRanks occ;
    if (occurrence_ranks) occ = std::move(*occurrence_ranks);
    // Implicit cells: classes without darts (numbered nvDarts, nvDarts + 1, ...), each with
    // its first occurrence (ascending).
    std::vector<long> dartless;
    int nvDarts = 0;
    // Mostly implicit cells (the cylinder v6: 46 MB of hexes): the hexes' array is sized and
    // zeroed beside the sequential labelling. With few implicit cells it is sized after the
    // cells are built, as without them: sized early it would be held beside the cells' parts
    // (+2.3 MiB peak on pig x2 at 2 threads) for a zeroing that takes no time there.
    const bool hexesSizedEarly = implicit && implicit->cells.size() >= labels.cell_size.size();
    long nq = 0;
    // Implicit cells: faces of dart cells with a free alpha_3 that is not a link into an
    // implicit cell (boundary quads), marked in the pass of the unions below.
    std::vector<char> bq;
    if (!implicit) {
        // Vertex and quad orbits are independent labellings.
        parallelChunks(2, std::min(2, std::max(1, threads)), [&](int, std::size_t b, std::size_t e) {
            for (std::size_t job = b; job < e; ++job) {
                if (job == 0) vlabel = labelVertexOrbits(g, labels, &nv);
                else nq = countQuadOrbits(g, labels, &stats.boundary_quads);
            }
        });
    } else {
        // Union-find over corner orbits (<alpha_1, alpha_2>, from the validator: 6 darts
        // each) and occurrences: corners joined over alpha_3 and with the occurrences their
        // darts sit on or link to. The same classes as over darts, with 6x fewer elements.
        // Only the occurrences that are used (corners of implicit cells, or sat on or linked
        // to by a dart: they get a label) or joined across a face are elements, numbered by
        // their rank among those (most grid points of a tet's box lie outside its image, or
        // are neither): 1.88M of the 10.35M occurrences of the cylinder v6.
        const std::vector<int>& corner = labels.corner;
        nk = static_cast<int>(labels.corner_size.size());
        const DefaultInitVector<int>& dartOccs = implicit->dart_occurrence;
        auto dartOcc = [&](std::size_t d) { return dartOccs.empty() ? -1 : dartOccs[d]; };
        const DefaultInitVector<int>& a3Occ = implicit->alpha3_occurrence;
        const auto& jo = implicit->joined_occurrences;
        const auto nOcc = static_cast<std::size_t>(nocc);
        const int ufChunks = nd + nOcc >= 16384 ? std::max(1, threads) : 1;
        if (!occ.ready) occ = rankOccurrences(g, *implicit, threads);
        const auto nElements = static_cast<std::size_t>(nk) + static_cast<std::size_t>(occ.n);
        ConcurrentUnionFind uf(nElements);
        auto element = [&](int o) { return nk + occ.rank(o); };
        bq.assign(labels.face_size.size(), 0);
        // The validator groups the darts by cell only if every dart is alive and every link an
        // involution (alpha_3(alpha_3(d)) = d).
        const bool involutive = !labels.cell_offset.empty();
        // The unions run in parallel chunks of darts (the classes do not depend on the order).
        parallelChunks(nd, ufChunks, [&](int, std::size_t d0, std::size_t d1) {
            // The darts of one grid point of a tet (consecutive) share their occurrence: each
            // of their corners is joined with it once (the last few corners joined with the
            // current occurrence are remembered).
            int lastOcc = -1, lastElement = -1;
            int joined[8];
            int nJoined = 0;
            for (std::size_t d = d0; d < d1; ++d) {
                if (!g.is_alive(DartHandle(static_cast<int>(d)))) continue;
                const int k = corner[d];
                const int d3 = a(static_cast<int>(d), 3);
                // Partners on the same occurrence are joined through it anyway.
                const int o = dartOcc(d);
                // With involutive links (darts grouped by cell) the pair's union is made once,
                // from its smaller dart.
                if (d3 != static_cast<int>(d) && (!involutive || d3 > static_cast<int>(d)) &&
                    (o < 0 || o != dartOcc(static_cast<std::size_t>(d3))))
                    uf.unite(k, corner[static_cast<std::size_t>(d3)]);
                if (o >= 0) {
                    if (o != lastOcc) {
                        lastOcc = o;
                        lastElement = element(o);
                        nJoined = 0;
                    }
                    if (std::find(joined, joined + nJoined, k) == joined + nJoined) {
                        uf.unite(k, lastElement);
                        if (nJoined < 8) joined[nJoined++] = k;
                    }
                }
                const int o3 = nocc > 0 ? a3Occ[d] : -1;  // without occurrences every entry is -1
                if (o3 >= 0) {
                    uf.unite(k, element(o3));
                } else if (d3 == static_cast<int>(d)) {
                    __atomic_store_n(&bq[static_cast<std::size_t>(labels.face[d])], char(1), __ATOMIC_RELAXED);
                }
            }
        });
        parallelChunks(jo.size(), ufChunks, [&](int, std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e; ++i) uf.unite(element(jo[i].first), element(jo[i].second));
        });
        // Flatten (parent = root) every element.
        parallelChunks(nElements, ufChunks, [&](int, std::size_t b, std::size_t e) {
            for (std::size_t x = b; x < e; ++x) uf.store(static_cast<int>(x), uf.rootOf(static_cast<int>(x)));
        });
        // Labels by first appearance (alive darts in order, then used occurrences in order);
        // the root's slot in parent is reused for its label (encoded as -2 - label).
        // Every dart alive (involutive): each entry is written below, no -1 fill first.
        std::vector<int>& parent = uf.parent;
        // The hexes' array is sized (and zeroed) beside this sequential labelling: one entry
        // per cell of darts, then the implicit cells (cut to the hexes at the end).
        auto labelClasses = [&]() {
            if (!involutive || vlabel.size() != nd) vlabel.assign(nd, -1);
            auto labelOf = [&](int x) {
                const int r = parent[static_cast<std::size_t>(x)];
                if (r < 0) return -2 - r;  // x is a root that has a label already
                int& slot = parent[static_cast<std::size_t>(r)];
                if (slot < 0) return -2 - slot;
                slot = -2 - nv;
                return nv++;
            };
            for (std::size_t d = 0; d < nd; ++d)
                if (g.is_alive(DartHandle(static_cast<int>(d)))) vlabel[d] = labelOf(corner[d]);
            // Classes first labelled here have no darts; they are numbered in order from nvDarts.
            // After its label is taken, a used occurrence's own slot gets the label too (nothing
            // is looked up through a non-root slot: the labelled elements point to their roots).
            nvDarts = nv;
            // The first occurrence of each dartless class is collected (ascending) when its label
            // is taken; at most one per used occurrence is reserved.
            dartless.reserve(static_cast<std::size_t>(occ.n_used));
            const std::size_t nWords = occ.word.size();
            for (std::size_t w = 0; w < nWords; ++w) {
                int x = nk + static_cast<int>(occ.word[w].first);
                for (std::uint64_t m = occ.word[w].element; m != 0; m &= m - 1, ++x) {
                    const int i = __builtin_ctzll(m);
                    if (!((occ.used[w] >> i) & 1)) continue;
                    const int l = labelOf(x);
                    parent[static_cast<std::size_t>(x)] = -2 - l;
                    if (l == nvDarts + static_cast<int>(dartless.size())) dartless.push_back(static_cast<long>(64 * w) + i);
                }
            }
        };
        parallelChunks(2, hexesSizedEarly ? std::min(2, std::max(1, threads)) : 1, [&](int, std::size_t b, std::size_t e) {
            for (std::size_t job = b; job < e; ++job) {
                if (job == 0) labelClasses();
                else if (hexesSizedEarly) out.hexes.resize(labels.cell_size.size() + implicit->cells.size());
            }
        });
        occSlot = std::move(parent);
        if (private_vertices) {
            // A dartless class holds no corner, so its occurrences were united only across
            // faces: without a joined occurrence it is one occurrence. All dartless classes,
            // then the classes of the joined occurrences taken out (a used occurrence's slot
            // holds its label, an unused one's its root, whose slot holds the label if any).
            private_vertices->assign((static_cast<std::size_t>(nv) + 63) / 64, 0);
            std::uint64_t* const bits = private_vertices->data();
            for (auto l = static_cast<std::size_t>(nvDarts); l < static_cast<std::size_t>(nv); ++l)
                bits[l >> 6] |= std::uint64_t(1) << (l & 63);
            const std::vector<int>& slot = occSlot;
            auto notPrivate = [&](int o) {
                const int r = slot[static_cast<std::size_t>(element(o))];
                const int v = r < 0 ? r : slot[static_cast<std::size_t>(r)];
                if (v >= 0) return;  // a class without a label
                const auto l = static_cast<std::size_t>(-2 - v);
                __atomic_fetch_and(&bits[l >> 6], ~(std::uint64_t(1) << (l & 63)), __ATOMIC_RELAXED);
            };
            parallelChunks(jo.size(), ufChunks, [&](int, std::size_t b, std::size_t e) {
                for (std::size_t i = b; i < e; ++i) {
                    notPrivate(jo[i].first);
                    notPrivate(jo[i].second);
                }
            });
        }
    }
    if (stats.violations) describeViolations(g, vlabel, *stats.violations);
    VertexCandidates candidates;
    out.vertices = mergedVertexPositions(*geo.mesh, vlabel, nv, geo.placement, threads, &candidates);
    if (implicit) {
        // Classes without darts: position of their first occurrence.
        Vec3d* const first = out.vertices.data() + nvDarts;
        parallelChunks(dartless.size(), threads, [&](int, std::size_t b, std::size_t e) {
            if (implicit->positions) {
                implicit->positions(dartless.data() + b, e - b, first + b);
                return;
            }
            for (std::size_t k = b; k < e; ++k) first[k] = implicit->position(dartless[k]);
        });
    }

    const std::vector<int>& flabel = labels.face;
    const std::vector<int>& clabel = labels.cell;
    const std::vector<int>& klabel = labels.corner;
    const std::vector<int>& fsize = labels.face_size;
    const std::vector<int>& ksize = labels.corner_size;
    const int nc = static_cast<int>(labels.cell_size.size());
    if (!implicit) {
        stats.quads = nq;
    } else {
        // Boundary quads: faces with a free alpha_3 that is not a link into an implicit cell
        // (marked in bq with the unions).
        stats.boundary_quads = std::count(bq.begin(), bq.end(), 1) + implicit->boundary_quads;
        // Quads are counted at the end from the cells: interior ones are shared by two.
    }

    std::vector<int> off, idx;
    // The validator usually grouped the darts by cell already (in search order within a
    // cell; the loop below does not depend on the order within a cell).
    const bool grouped = !labels.cell_offset.empty();
    if (!grouped) groupByLabel(clabel, nc, off, idx);
    const std::vector<int>& cellOff = grouped ? labels.cell_offset : off;
    const std::vector<int>& cellDarts = grouped ? labels.cell_darts : idx;
    auto V = [&](int d) { return vlabel[static_cast<std::size_t>(d)]; };
    // Cells in parallel chunks (each dart belongs to one cell, so only reads are shared);
    // the chunks' hexes and polyhedra are appended in chunk order.
    struct CellPart {
        std::vector<std::array<int, 8>> hexes;
        std::vector<int> hexDarts;
        std::vector<Polyhedron> polyhedra;
        long degenerate_faces = 0, collapsed_cells = 0;
    };
    // Every face orbit of 8 and corner orbit of 6 darts (always on a valid map): a cell of
    // 48 darts needs no look-up of its darts' face and corner sizes.
    const bool regularOrbits = std::all_of(fsize.begin(), fsize.end(), [](int x) { return x == 8; }) &&
                               std::all_of(ksize.begin(), ksize.end(), [](int x) { return x == 6; });
    const int cellChunks = std::max(1, std::min(threads, nc / 1024));
    std::vector<CellPart> cellParts(static_cast<std::size_t>(cellChunks));
    parallelChunks(static_cast<std::size_t>(nc), cellChunks, [&](int part, std::size_t cb, std::size_t ce) {
        CellPart& P = cellParts[static_cast<std::size_t>(part)];
        P.hexes.reserve(ce - cb);
        for (int c = static_cast<int>(cb); c < static_cast<int>(ce); ++c) {
            const int* first = cellDarts.data() + cellOff[static_cast<std::size_t>(c)];
            const int size = cellOff[static_cast<std::size_t>(c) + 1] - cellOff[static_cast<std::size_t>(c)];
            bool hex = size == 48;
            int d0 = -1;  // the smallest right-handed dart (cell darts need not be sorted)
            // A cell's first dart is its smallest (both groupings list it first): if it is
            // right-handed and no orbit size needs checking, the others need not be read.
            const bool firstWins = hex && regularOrbits && geo.handedness[static_cast<std::size_t>(first[0])] > 0;
            if (firstWins) d0 = first[0];
            for (int k = 0; k < size && hex && !firstWins; ++k) {
                const int d = first[k];
                if (!regularOrbits && (fsize[static_cast<std::size_t>(flabel[static_cast<std::size_t>(d)])] != 8 ||
                                       ksize[static_cast<std::size_t>(klabel[static_cast<std::size_t>(d)])] != 6))
                    hex = false;
                if (geo.handedness[static_cast<std::size_t>(d)] > 0 && (d0 < 0 || d < d0)) d0 = d;
            }
            if (hex && d0 >= 0) {
                auto up = [&](int d) { return a(a(a(d, 2), 1), 0); };
                const int d1 = a(d0, 0), d3 = a(a(d0, 1), 0), d2 = a(a(d1, 1), 0);
                std::array<int, 8> h = {V(d0), V(d1), V(d2), V(d3), V(up(d0)), V(up(d1)), V(up(d2)), V(up(d3))};
                std::array<int, 8> s = h;
                std::sort(s.begin(), s.end());
                if (std::adjacent_find(s.begin(), s.end()) == s.end()) {
                    P.hexes.push_back(h);
                    if (hex_darts) P.hexDarts.push_back(d0);
                    continue;
                }
            }
            // Not a hexahedron: write every face of the cell as a vertex loop, faces in the
            // order of their smallest dart.
            std::vector<int> sortedDarts(first, first + size);
            std::sort(sortedDarts.begin(), sortedDarts.end());
            Polyhedron poly;
            std::vector<int> seenFaces;
            for (int k = 0; k < size; ++k) {
                const int f0 = sortedDarts[static_cast<std::size_t>(k)];
                const int fl = flabel[static_cast<std::size_t>(f0)];
                if (std::find(seenFaces.begin(), seenFaces.end(), fl) != seenFaces.end()) continue;
                seenFaces.push_back(fl);
                std::vector<int> loop;
                int d = f0;
                for (int step = 0; step < size; ++step) {
                    loop.push_back(V(d));
                    const int e = a(d, 0);
                    const int nx = a(e, 1);
                    if (e == d || nx == e || nx == f0) break;
                    d = nx;
                }
                loop.erase(std::unique(loop.begin(), loop.end()), loop.end());
                if (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
                std::vector<int> distinct = loop;
                std::sort(distinct.begin(), distinct.end());
                if (std::unique(distinct.begin(), distinct.end()) - distinct.begin() < 3 || distinct.size() != loop.size()) {
                    ++P.degenerate_faces;
                    continue;
                }
                if (geo.handedness[static_cast<std::size_t>(f0)] < 0) std::reverse(loop.begin(), loop.end());
                poly.faces.push_back(loop);
            }
            if (poly.faces.empty()) {
                ++P.collapsed_cells;
                continue;
            }
            P.polyhedra.push_back(std::move(poly));
        }
    });
    std::size_t nHex = 0, nPoly = 0;
    for (const CellPart& P : cellParts) {
        nHex += P.hexes.size();
        nPoly += P.polyhedra.size();
    }
    // Sized beside the labelling (one entry per cell), or here.
    if (!hexesSizedEarly) out.hexes.reserve(nHex + (implicit ? implicit->cells.size() : 0));
    out.polyhedra.reserve(nPoly);
    if (hex_darts) {
        hex_darts->clear();
        hex_darts->reserve(nHex);
    }
    std::size_t at = 0;
    for (CellPart& P : cellParts) {
        if (hexesSizedEarly) std::copy(P.hexes.begin(), P.hexes.end(), out.hexes.begin() + static_cast<std::ptrdiff_t>(at));
        else out.hexes.insert(out.hexes.end(), P.hexes.begin(), P.hexes.end());
        at += P.hexes.size();
        if (hex_darts) hex_darts->insert(hex_darts->end(), P.hexDarts.begin(), P.hexDarts.end());
        std::move(P.polyhedra.begin(), P.polyhedra.end(), std::back_inserter(out.polyhedra));
        stats.degenerate_faces += P.degenerate_faces;
        stats.collapsed_cells += P.collapsed_cells;
    }
    if (implicit) {
        const std::size_t base = nHex;
        out.hexes.resize(base + implicit->cells.size());
        // The corners' element numbers (ranks): the bottom four (0-3) are the previous cell's
        // top four (4-7) when the cells are consecutive along z, and a top corner that is the
        // occurrence after the corner below it has the next rank (elements o and o + 1:
        // rank(o + 1) = rank(o) + 1); only the others are counted in the bit set.
        parallelChunks(implicit->cells.size(), threads, [&](int, std::size_t b, std::size_t e) {
            std::array<int, 8> prevOcc, prevRank{};
            prevOcc.fill(-1);
            for (std::size_t i = b; i < e; ++i) {
                const auto& c = implicit->cells[i];
                std::array<int, 8>& h = out.hexes[base + i];
                std::array<int, 8> r;
                if (c[0] == prevOcc[4] && c[1] == prevOcc[5] && c[2] == prevOcc[6] && c[3] == prevOcc[7]) {
                    for (std::size_t k = 0; k < 4; ++k) r[k] = prevRank[k + 4];
                } else {
                    for (std::size_t k = 0; k < 4; ++k) r[k] = occ.rank(c[k]);
                }
                for (std::size_t k = 4; k < 8; ++k) r[k] = c[k] == c[k - 4] + 1 ? r[k - 4] + 1 : occ.rank(c[k]);
                for (std::size_t k = 0; k < 8; ++k) h[k] = -2 - occSlot[static_cast<std::size_t>(nk) + static_cast<std::size_t>(r[k])];
                prevOcc = c;
                prevRank = r;
            }
        });
        long cellFaces = 6 * static_cast<long>(out.hexes.size());
        for (const auto& p : out.polyhedra) cellFaces += static_cast<long>(p.faces.size());
        stats.quads = (cellFaces + stats.boundary_quads) / 2;
    }
    stats.non_hex_cells = static_cast<long>(out.polyhedra.size()) + stats.collapsed_cells;
    stats.ambiguous_vertices = static_cast<long>(candidates.vertex.size());
    chooseVertexPreimages(out, candidates);
    return out;
}

} // namespace HexEx
