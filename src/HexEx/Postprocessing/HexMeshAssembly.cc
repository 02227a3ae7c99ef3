#include "HexMeshAssembly.hh"

#include "VertexPreimageChoice.hh"

#include "../Core/Parallel.hh"
#include "../Core/ConcurrentUnionFind.hh"
#include "../GMap/GMapValidator.hh"

#include <algorithm>
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
                        const ImplicitCells* implicit, int threads, std::vector<int>* hex_darts, std::vector<int>* label_storage) {
    HexMesh out;
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
    int nk = 0;  // corner orbits: occurrence o has the slot nk + o
    // Implicit cells: classes without darts (numbered nvDarts, nvDarts + 1, ...), each with
    // its first occurrence (ascending).
    std::vector<long> dartless;
    int nvDarts = 0;
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
        // The unions run in parallel chunks of darts (the classes do not depend on the order).
        const std::vector<int>& corner = labels.corner;
        nk = static_cast<int>(labels.corner_size.size());
        ConcurrentUnionFind uf(static_cast<std::size_t>(nk) + static_cast<std::size_t>(nocc));
        std::vector<char> used(static_cast<std::size_t>(nocc), 0);
        auto use = [&](int o) { __atomic_store_n(&used[static_cast<std::size_t>(o)], char(1), __ATOMIC_RELAXED); };
        const std::vector<int>& dartOcc = implicit->dart_occurrence;
        const std::vector<int>& flabel = labels.face;
        bq.assign(labels.face_size.size(), 0);
        const int ufChunks = nd + static_cast<std::size_t>(nocc) >= 16384 ? std::max(1, threads) : 1;
        parallelChunks(nd, ufChunks, [&](int, std::size_t d0, std::size_t d1) {
            // The darts of one grid point of a tet (consecutive) share their occurrence: each
            // of their corners is joined with it once (the last few corners joined with the
            // current occurrence are remembered).
            int lastOcc = -1;
            int joined[8];
            int nJoined = 0;
            for (std::size_t d = d0; d < d1; ++d) {
                if (!g.is_alive(DartHandle(static_cast<int>(d)))) continue;
                const int k = corner[d];
                const int d3 = a(static_cast<int>(d), 3);
                // Partners on the same occurrence are joined through it anyway.
                if (d3 != static_cast<int>(d) && (dartOcc[d] < 0 || dartOcc[d] != dartOcc[static_cast<std::size_t>(d3)]))
                    uf.unite(k, corner[static_cast<std::size_t>(d3)]);
                const int o = dartOcc[d];
                if (o >= 0) {
                    if (o != lastOcc) {
                        lastOcc = o;
                        nJoined = 0;
                        use(o);
                    }
                    if (std::find(joined, joined + nJoined, k) == joined + nJoined) {
                        uf.unite(k, nk + o);
                        if (nJoined < 8) joined[nJoined++] = k;
                    }
                }
                const int o3 = implicit->alpha3_occurrence[d];
                if (o3 >= 0) {
                    uf.unite(k, nk + o3);
                    use(o3);
                } else if (d3 == static_cast<int>(d)) {
                    __atomic_store_n(&bq[static_cast<std::size_t>(flabel[d])], char(1), __ATOMIC_RELAXED);
                }
            }
        });
        const auto& jo = implicit->joined_occurrences;
        parallelChunks(jo.size(), ufChunks, [&](int, std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e; ++i) uf.unite(nk + jo[i].first, nk + jo[i].second);
        });
        parallelChunks(implicit->cells.size(), ufChunks, [&](int, std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e; ++i)
                for (int o : implicit->cells[i]) use(o);
        });
        // Flatten (parent = root) the elements that get a label: the corners and the used
        // occurrences (most box points of a large tet lie outside its image and are never used).
        const std::size_t nElements = static_cast<std::size_t>(nk) + static_cast<std::size_t>(nocc);
        auto labelled = [&](std::size_t x) { return x < static_cast<std::size_t>(nk) || used[x - static_cast<std::size_t>(nk)] != 0; };
        parallelChunks(nElements, ufChunks, [&](int, std::size_t b, std::size_t e) {
            for (std::size_t x = b; x < e; ++x)
                if (labelled(x)) uf.store(static_cast<int>(x), uf.rootOf(static_cast<int>(x)));
        });
        // Labels by first appearance (alive darts in order, then used occurrences in order);
        // the root's slot in parent is reused for its label (encoded as -2 - label).
        vlabel.assign(nd, -1);
        std::vector<int>& parent = uf.parent;
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
        // The first occurrence of each dartless class is marked (used = 2), then collected.
        nvDarts = nv;
        constexpr char kFirstOfDartless = 2;
        long nDartless = 0;
        for (long o = 0; o < nocc; ++o) {
            char& u = used[static_cast<std::size_t>(o)];
            if (!u) continue;
            const int x = nk + static_cast<int>(o);
            const int l = labelOf(x);
            parent[static_cast<std::size_t>(x)] = -2 - l;
            if (l == nvDarts + nDartless) {  // a class first labelled here: it has no darts
                ++nDartless;
                u = kFirstOfDartless;
            }
        }
        dartless.reserve(static_cast<std::size_t>(nDartless));
        for (long o = 0; o < nocc; ++o)
            if (used[static_cast<std::size_t>(o)] == kFirstOfDartless) dartless.push_back(o);
        occSlot = std::move(parent);
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
            for (int k = 0; k < size && hex; ++k) {
                const int d = first[k];
                if (fsize[static_cast<std::size_t>(flabel[static_cast<std::size_t>(d)])] != 8 ||
                    ksize[static_cast<std::size_t>(klabel[static_cast<std::size_t>(d)])] != 6)
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
    out.hexes.reserve(nHex + (implicit ? implicit->cells.size() : 0));
    out.polyhedra.reserve(nPoly);
    if (hex_darts) {
        hex_darts->clear();
        hex_darts->reserve(nHex);
    }
    for (CellPart& P : cellParts) {
        out.hexes.insert(out.hexes.end(), P.hexes.begin(), P.hexes.end());
        if (hex_darts) hex_darts->insert(hex_darts->end(), P.hexDarts.begin(), P.hexDarts.end());
        std::move(P.polyhedra.begin(), P.polyhedra.end(), std::back_inserter(out.polyhedra));
        stats.degenerate_faces += P.degenerate_faces;
        stats.collapsed_cells += P.collapsed_cells;
    }
    if (implicit) {
        const std::size_t base = out.hexes.size();
        out.hexes.resize(base + implicit->cells.size());
        parallelChunks(implicit->cells.size(), threads, [&](int, std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e; ++i) {
                const auto& c = implicit->cells[i];
                std::array<int, 8>& h = out.hexes[base + i];
                for (int k = 0; k < 8; ++k) h[static_cast<std::size_t>(k)] = -2 - occSlot[static_cast<std::size_t>(nk) + static_cast<std::size_t>(c[static_cast<std::size_t>(k)])];
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
