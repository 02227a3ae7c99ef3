#include "TetMesh.hh"

#include "../Core/Error.hh"
#include "../Core/Parallel.hh"
#include "../Core/Prefetch.hh"

#include <algorithm>
#include <sstream>

namespace HexEx {

constexpr int TetMesh::kFaceCorners[4][3];
constexpr int TetMesh::kEdgeCorners[6][2];

namespace {
/// How many vertices ahead of the current one the per-vertex passes prefetch the star.
constexpr std::size_t kStarAhead = 2;
/// Vertices per block handed to a thread in the per-vertex passes (parallelBlocks()).
constexpr std::size_t kVertexBlock = 2048;
/// Asks the CPU to load the cache line of element @p stride * c of @p perTet for every tet c
/// in @p first..@p last early: the tets of a star are scattered over the per-tet arrays, and
/// the per-vertex passes over them are chains of dependent loads.
template <class T>
void prefetchStar(const int* first, const int* last, const T* perTet, std::size_t stride) {
    for (const int* c = first; c != last; ++c) prefetchKept(perTet + stride * static_cast<std::size_t>(*c));
}
} // namespace

VertexHandle TetMesh::add_vertex(const Vec3d& p) {
    positions_.push_back(p);
    vprops_.resize(positions_.size());
    return VertexHandle(static_cast<int>(positions_.size()) - 1);
}

CellHandle TetMesh::add_cell(const std::array<VertexHandle, 4>& v) {
    cells_.push_back(v);
    adjacency_built_ = false;
    cprops_.resize(cells_.size());
    hfprops_.resize(4 * cells_.size());
    ccprops_.resize(4 * cells_.size());
    return CellHandle(static_cast<int>(cells_.size()) - 1);
}

void TetMesh::assign(std::vector<Vec3d>&& positions, std::vector<std::array<VertexHandle, 4>>&& cells) {
    positions_ = std::move(positions);
    cells_ = std::move(cells);
    adjacency_built_ = false;
    vprops_.resize(positions_.size());
    cprops_.resize(cells_.size());
    hfprops_.resize(4 * cells_.size());
    ccprops_.resize(4 * cells_.size());
}

void TetMesh::reserve(std::size_t nv, std::size_t nc) {
    positions_.reserve(nv);
    cells_.reserve(nc);
}

void TetMesh::swap_corners(CellHandle c, int i, int j) {
    std::swap(cells_[c.uidx()][i], cells_[c.uidx()][j]);
    adjacency_built_ = false;
}

std::array<VertexHandle, 3> TetMesh::halfface_vertices(HalfFaceHandle hf) const {
    const auto& cv = cells_[cell(hf).uidx()];
    const int* fc = kFaceCorners[opposite_corner(hf)];
    return {cv[fc[0]], cv[fc[1]], cv[fc[2]]};
}

std::array<HalfFaceHandle, 2> TetMesh::face_halffaces(FaceHandle f) const {
    const auto& h = face_halffaces_[f.uidx()];
    return {HalfFaceHandle(h[0]), HalfFaceHandle(h[1])};
}

EdgeHandle TetMesh::find_edge(VertexHandle a, VertexHandle b) const {
    if (b < a) std::swap(a, b);
    const int* first = ve_idx_.data() + ve_off_[a.uidx()];
    const int* last = ve_idx_.data() + ve_off_[a.uidx() + 1];
    // Edges of vertex a (as smaller endpoint) are sorted by their other endpoint.
    const int* it = std::lower_bound(first, last, b.idx(), [&](int e, int v) { return edges_[e][1].idx() < v; });
    if (it != last && edges_[*it][1] == b) return EdgeHandle(*it);
    return EdgeHandle();
}

void TetMesh::build_adjacency(int threads) {
    const std::size_t nv = positions_.size(), nc = cells_.size();
    // Vertex -> cells (counting sort keeps cells ascending). In chunks of cells: each
    // counts its cells per vertex; per vertex, the chunks' counts become their first slots,
    // chunk after chunk (cells stay ascending within a vertex); each chunk fills its slots.
    // The same table for any chunk count.
    const int chunks = nc < 50000 ? 1 : resolveThreadCount(threads);
    std::vector<std::vector<int>> next(static_cast<std::size_t>(chunks));  // per chunk and vertex: count, then next slot
    parallelChunks(nc, chunks, [&](int k, std::size_t b, std::size_t e) {
        std::vector<int>& count = next[static_cast<std::size_t>(k)];
        count.assign(nv, 0);
        for (std::size_t c = b; c < e; ++c)
            for (auto v : cells_[c]) ++count[v.uidx()];
    });
    vc_off_.resize(nv + 1);
    int at = 0;
    for (std::size_t v = 0; v < nv; ++v) {
        vc_off_[v] = at;
        for (std::vector<int>& count : next) {
            const int m = count[v];
            count[v] = at;
            at += m;
        }
    }
    vc_off_[nv] = at;
    vc_idx_.resize(static_cast<std::size_t>(at));
    parallelChunks(nc, chunks, [&](int k, std::size_t b, std::size_t e) {
        int* const slot = next[static_cast<std::size_t>(k)].data();
        for (std::size_t c = b; c < e; ++c)
            for (auto v : cells_[c]) vc_idx_[static_cast<std::size_t>(slot[v.uidx()]++)] = static_cast<int>(c);
    });
    std::vector<std::vector<int>>().swap(next);

    // Opposite halffaces. Every face is matched within the bucket of its smallest vertex
    // v: the halffaces of the tets around v whose smallest vertex is v, keyed by their
    // other two vertices; equal keys are the two sides of one face. A halfface
    // lies in exactly one bucket, so the vertices run in parallel and each writes only the
    // slots of its own bucket. A key held by three or more halffaces is a non-manifold
    // face; the one whose first tet and face come first is reported (for any thread count).
    opposite_.assign(4 * nc, -1);  // -1: boundary
    // The face and edge passes hand out blocks of vertices to the threads as they finish: the
    // work per vertex follows its star and its edges to larger vertices, which are not spread
    // evenly over the numbering (on pig x2 the hex corners come first: two equal chunks of
    // the edge pass took 0.043 and 0.018 s).
    const int vthreads = nv < 20000 ? 1 : resolveThreadCount(threads);
    const std::size_t vblocks = (nv + kVertexBlock - 1) / kVertexBlock;
    std::vector<std::array<long long, 2>> badFace(std::max<std::size_t>(1, vblocks), {-1, 0});
    // A face's key: its other two vertices, the smaller one in the high half. Keys go into a
    // small hash table per thread (open addressing; a slot belongs to the vertex in its stamp,
    // so it is never cleared), which pairs the two sides of a face without sorting the bucket;
    // the halffaces arrive in ascending order (the star is in tet order), so a key's first
    // halfface is its smallest.
    struct FaceSlot {
        unsigned long long key;
        int first, second, count, stamp;
    };
    struct FaceTable {
        std::vector<FaceSlot> slot;
        std::vector<std::size_t> used;  // the slots of the current vertex
    };
    // The same pass over the star counts the edges' first pass (see "Edges" below): v's
    // larger neighbours and the (tet, edge) incidences of its edges.
    ve_off_.resize(nv + 1);
    ve_off_[0] = 0;
    std::vector<int> incidences(nv + 1);  // per vertex: (tet, edge) pairs of its edges; then prefix sums
    incidences[0] = 0;
    std::vector<FaceTable> tables(static_cast<std::size_t>(vthreads));
    std::vector<std::vector<int>> seenOf(static_cast<std::size_t>(vthreads));
    parallelBlocks(nv, kVertexBlock, vthreads, [&](int thread, std::size_t block, std::size_t vb, std::size_t ve) {
        FaceTable& table = tables[static_cast<std::size_t>(thread)];
        std::vector<int>& seen = seenOf[static_cast<std::size_t>(thread)];  // seen[w] == v: w counted for v
        if (seen.empty()) seen.assign(nv, -1);
        long long firstBad = -1, firstBadCount = 0;
        for (std::size_t v = vb; v < ve; ++v) {
            if (v + kStarAhead < ve)
                prefetchStar(vc_idx_.data() + vc_off_[v + kStarAhead], vc_idx_.data() + vc_off_[v + kStarAhead + 1],
                             cells_.data(), 1);
            const int vi = static_cast<int>(v);
            // At most three faces of each tet of the star contain v: at most half the slots used.
            const std::size_t need = std::max<std::size_t>(16, 6 * static_cast<std::size_t>(vc_off_[v + 1] - vc_off_[v]));
            if (table.slot.size() < need) {
                std::size_t size = 16;
                while (size < need) size *= 2;
                table.slot.assign(size, FaceSlot{0, -1, -1, 0, -1});
            }
            const std::size_t mask = table.slot.size() - 1;
            table.used.clear();
            int distinct = 0, total = 0;
            for (int o = vc_off_[v]; o < vc_off_[v + 1]; ++o) {
                const int c = vc_idx_[o];
                const auto& cv = cells_[static_cast<std::size_t>(c)];
                for (const auto w : cv) {
                    if (w.idx() <= vi) continue;
                    ++total;
                    distinct += seen[w.uidx()] != vi;
                    seen[w.uidx()] = vi;
                }
                for (int i = 0; i < 4; ++i) {
                    if (cv[i].uidx() == v) continue;  // the face opposite v does not contain it
                    int a = cv[kFaceCorners[i][0]].idx(), b = cv[kFaceCorners[i][1]].idx(), d = cv[kFaceCorners[i][2]].idx();
                    if (a == static_cast<int>(v)) a = d;
                    else if (b == static_cast<int>(v)) b = d;
                    if (a < static_cast<int>(v) || b < static_cast<int>(v)) continue;  // another vertex's bucket
                    if (b < a) std::swap(a, b);
                    const unsigned long long key = (static_cast<unsigned long long>(a) << 32) | static_cast<unsigned>(b);
                    std::size_t at = static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 40) & mask;
                    while (table.slot[at].stamp == vi && table.slot[at].key != key) at = (at + 1) & mask;
                    FaceSlot& f = table.slot[at];
                    if (f.stamp != vi) {
                        f = FaceSlot{key, 4 * c + i, -1, 1, vi};
                        table.used.push_back(at);
                    } else if (++f.count == 2) {
                        f.second = 4 * c + i;
                    }
                }
            }
            ve_off_[v + 1] = distinct;
            incidences[v + 1] = total;
            for (const std::size_t at : table.used) {
                const FaceSlot& f = table.slot[at];
                if (f.count == 2) {
                    opposite_[static_cast<std::size_t>(f.first)] = f.second;
                    opposite_[static_cast<std::size_t>(f.second)] = f.first;
                } else if (f.count > 2 && (firstBad < 0 || f.first < firstBad)) {
                    firstBad = f.first;
                    firstBadCount = f.count;
                }
            }
        }
        badFace[block] = {firstBad, firstBadCount};
    });
    std::vector<std::vector<int>>().swap(seenOf);
    std::array<long long, 2> bad = {-1, 0};
    for (const auto& b : badFace)
        if (b[0] >= 0 && (bad[0] < 0 || b[0] < bad[0])) bad = b;
    if (bad[0] >= 0) {
        const std::size_t c = static_cast<std::size_t>(bad[0] / 4);
        const int i = static_cast<int>(bad[0] % 4);
        std::ostringstream os;
        os << "non-manifold mesh: face (" << cells_[c][kFaceCorners[i][0]] << ", " << cells_[c][kFaceCorners[i][1]] << ", "
           << cells_[c][kFaceCorners[i][2]] << ") of tet " << c << " is shared by " << bad[1] << " tets";
        throw InputError(os.str());
    }

    // Faces.
    // A halfface opens a new face unless its opposite comes first; faces are numbered in
    // halfface order: new faces counted per chunk, numbered after a prefix sum, then the
    // second halfface of every face takes its number (all three passes in parallel).
    const std::size_t nhf = 4 * nc;
    halfface_face_.assign(nhf, -1);
    const int fchunks = std::max(1, chunks);
    std::vector<int> newFaces(static_cast<std::size_t>(fchunks) + 1, 0), boundaryFaces(static_cast<std::size_t>(fchunks), 0);
    parallelChunks(nhf, fchunks, [&](int k, std::size_t b, std::size_t e) {
        int nNew = 0, nBoundary = 0;
        for (std::size_t hf = b; hf < e; ++hf) {
            const int opp = opposite_[hf];
            nNew += !(opp >= 0 && opp < static_cast<int>(hf));
            nBoundary += opp < 0;
        }
        newFaces[static_cast<std::size_t>(k) + 1] = nNew;
        boundaryFaces[static_cast<std::size_t>(k)] = nBoundary;
    });
    for (std::size_t k = 0; k < static_cast<std::size_t>(fchunks); ++k) newFaces[k + 1] += newFaces[k];
    face_halffaces_.resize(static_cast<std::size_t>(newFaces.back()));
    n_boundary_faces_ = 0;
    for (const int nb : boundaryFaces) n_boundary_faces_ += static_cast<std::size_t>(nb);
    parallelChunks(nhf, fchunks, [&](int k, std::size_t b, std::size_t e) {
        int f = newFaces[static_cast<std::size_t>(k)];
        for (std::size_t hf = b; hf < e; ++hf) {
            const int opp = opposite_[hf];
            if (opp >= 0 && opp < static_cast<int>(hf)) continue;
            halfface_face_[hf] = f;
            face_halffaces_[static_cast<std::size_t>(f)] = {static_cast<int>(hf), opp};
            ++f;
        }
    });
    parallelChunks(nhf, fchunks, [&](int, std::size_t b, std::size_t e) {
        for (std::size_t hf = b; hf < e; ++hf) {
            const int opp = opposite_[hf];
            if (opp >= 0 && opp < static_cast<int>(hf)) halfface_face_[hf] = halfface_face_[static_cast<std::size_t>(opp)];
        }
    });

    // Edges, grouped by smaller endpoint v and sorted by the larger one w; all their work is
    // done per vertex v, on the tets of its star (the tets of an edge (v, w) all contain v),
    // in two parallel passes. Pass 1 (within the face matching above) counts v's larger
    // neighbours and the (tet, edge) incidences of its edges (marks per thread instead of
    // sorting the neighbour lists);
    // after two prefix sums, pass 2 numbers the edges, fills the tets' edge slots, the
    // number of tets per edge, and walks every edge's ring of tets while the star is in the
    // cache. The walk starts at the last boundary face met in tet order (the star is in tet
    // order), else at the first tet: the same rule for any thread count.
    for (std::size_t v = 0; v < nv; ++v) {
        ve_off_[v + 1] += ve_off_[v];
        incidences[v + 1] += incidences[v];
    }
    const std::size_t ne = static_cast<std::size_t>(ve_off_[nv]);
    edges_.resize(ne);
    ve_idx_.resize(ne);
    cell_edges_.resize(6 * nc);
    ec_off_.resize(ne + 1);
    ec_off_[ne] = incidences[nv];
    ec_idx_.resize(static_cast<std::size_t>(incidences[nv]));
    boundary_edge_.resize(ne);
    boundary_vertex_.resize(nv);
    // Per block: its first non-manifold edge and vertex (what check_manifold() reports).
    std::vector<std::array<long long, 2>> firstBad(std::max<std::size_t>(1, vblocks), {-1, -1});
    struct EdgeScratch {
        std::vector<int> slot;  // slot[w]: w's place among the larger neighbours of the current v
        std::vector<int> nbrs, count, start, startHf, stack;
        std::vector<int> mark;  // mark[c] == v: tet c reached in the walk over v's star
    };
    std::vector<EdgeScratch> edgeScratch(static_cast<std::size_t>(vthreads));
    parallelBlocks(nv, kVertexBlock, vthreads, [&](int thread, std::size_t block, std::size_t b, std::size_t e) {
        EdgeScratch& S = edgeScratch[static_cast<std::size_t>(thread)];
        if (S.slot.empty()) {
            S.slot.assign(nv, -1);
            S.mark.assign(nc, -1);
        }
        std::vector<int>& slot = S.slot;
        std::vector<int>& nbrs = S.nbrs;
        std::vector<int>& count = S.count;
        std::vector<int>& start = S.start;
        std::vector<int>& startHf = S.startHf;
        std::vector<int>& stack = S.stack;
        std::vector<int>& mark = S.mark;
        long long badEdge = -1, badVertex = -1;
        for (std::size_t v = b; v < e; ++v) {
            if (v + kStarAhead < e) {
                const int* aheadBegin = vc_idx_.data() + vc_off_[v + kStarAhead];
                const int* aheadEnd = vc_idx_.data() + vc_off_[v + kStarAhead + 1];
                prefetchStar(aheadBegin, aheadEnd, cells_.data(), 1);
                prefetchStar(aheadBegin, aheadEnd, opposite_.data(), 4);
                prefetchStar(aheadBegin, aheadEnd, cell_edges_.data(), 6);
                prefetchStar(aheadBegin, aheadEnd, mark.data(), 1);
            }
            const int vi = static_cast<int>(v);
            const int* const starBegin = vc_idx_.data() + vc_off_[v];
            const int* const starEnd = vc_idx_.data() + vc_off_[v + 1];
            // The larger neighbours, sorted: the edges of v in edge order.
            nbrs.clear();
            for (const int* o = starBegin; o != starEnd; ++o)
                for (const auto w : cells_[static_cast<std::size_t>(*o)])
                    if (w.idx() > vi && slot[w.uidx()] != -2 - vi) {
                        slot[w.uidx()] = -2 - vi;  // collected for v (distinct from any place)
                        nbrs.push_back(w.idx());
                    }
            std::sort(nbrs.begin(), nbrs.end());
            const std::size_t n = nbrs.size();
            const int first = ve_off_[v];
            for (std::size_t k = 0; k < n; ++k) {
                slot[static_cast<std::size_t>(nbrs[k])] = static_cast<int>(k);
                const std::size_t id = static_cast<std::size_t>(first) + k;
                ve_idx_[id] = static_cast<int>(id);
                edges_[id] = {VertexHandle(vi), VertexHandle(nbrs[k])};
            }
            count.assign(n, 0);
            start.assign(n, -1);    // a tet of the edge, preferring one at the boundary
            startHf.assign(n, -1);  // the halfface of start through which the walk must NOT leave
            char onBoundary = 0;
            for (const int* o = starBegin; o != starEnd; ++o) {
                const int c = *o;
                const std::size_t cu = static_cast<std::size_t>(c);
                const auto& cv = cells_[cu];
                for (int j = 0; j < 4; ++j)  // a boundary face that contains v
                    onBoundary |= static_cast<char>(cv[j].idx() != vi && opposite_[4 * cu + static_cast<std::size_t>(j)] < 0);
                for (int k = 0; k < 6; ++k) {
                    const int a = kEdgeCorners[k][0], bb = kEdgeCorners[k][1];
                    const int x = cv[a].idx(), y = cv[bb].idx();
                    if (std::min(x, y) != vi) continue;  // another vertex's edge
                    const std::size_t local = static_cast<std::size_t>(slot[static_cast<std::size_t>(std::max(x, y))]);
                    cell_edges_[6 * cu + static_cast<std::size_t>(k)] = first + static_cast<int>(local);
                    ++count[local];
                    for (int j = 0; j < 4; ++j)
                        if (j != a && j != bb && opposite_[4 * cu + static_cast<std::size_t>(j)] < 0) {
                            start[local] = c;
                            startHf[local] = 4 * c + j;
                        }
                    if (start[local] < 0) start[local] = c;
                }
            }
            boundary_vertex_[v] = onBoundary;
            // The rings: walk across the faces that contain the edge, from the start tet.
            int pos = incidences[v];
            for (std::size_t k = 0; k < n; ++k) {
                const std::size_t id = static_cast<std::size_t>(first) + k;
                const VertexHandle w(nbrs[k]);
                ec_off_[id] = pos;
                const int end = pos + count[k];
                int c = start[k], inHf = startHf[k];
                boundary_edge_[id] = inHf >= 0;
                while (pos < end) {
                    ec_idx_[static_cast<std::size_t>(pos++)] = c;
                    // The two halffaces of c that contain the edge: opposite the corners not on it.
                    const auto& cv = cells_[static_cast<std::size_t>(c)];
                    int out = -1;
                    for (int j = 0; j < 4; ++j)
                        if (cv[j].idx() != vi && cv[j] != w && 4 * c + j != inHf) {
                            out = 4 * c + j;
                            if (inHf < 0) break;  // first step of an interior ring: either direction
                        }
                    const int next = opposite_[static_cast<std::size_t>(out)];
                    if (next < 0 || next / 4 == start[k]) break;
                    c = next / 4;
                    inHf = next;
                }
                // A non-manifold edge leaves slots unfilled; check_manifold() reports it.
                if (pos < end && badEdge < 0) badEdge = static_cast<long long>(id);
                for (; pos < end; ++pos) ec_idx_[static_cast<std::size_t>(pos)] = -1;
            }
            // The star must be connected through faces that contain v (a disk or sphere link),
            // checked while its tets are in the cache.
            if (badVertex < 0 && starBegin != starEnd) {
                int reached = 0;
                stack.assign(1, *starBegin);
                mark[static_cast<std::size_t>(*starBegin)] = vi;
                while (!stack.empty()) {
                    const std::size_t c = static_cast<std::size_t>(stack.back());
                    stack.pop_back();
                    ++reached;
                    for (int j = 0; j < 4; ++j) {
                        if (cells_[c][j].idx() == vi) continue;  // the face opposite v does not contain it
                        const int opp = opposite_[4 * c + static_cast<std::size_t>(j)];
                        if (opp >= 0 && mark[static_cast<std::size_t>(opp / 4)] != vi) {
                            mark[static_cast<std::size_t>(opp / 4)] = vi;
                            stack.push_back(opp / 4);
                        }
                    }
                }
                if (reached != starEnd - starBegin) badVertex = static_cast<long long>(v);
            }
        }
        firstBad[block] = {badEdge, badVertex};
    });
    // Blocks are in vertex order and edges numbered in it: the first found is the first.
    first_bad_edge_ = first_bad_vertex_ = -1;
    for (const auto& f : firstBad) {
        if (first_bad_edge_ < 0) first_bad_edge_ = f[0];
        if (first_bad_vertex_ < 0) first_bad_vertex_ = f[1];
    }

    adjacency_built_ = true;
}

std::string TetMesh::check_manifold(int) const {
    std::ostringstream os;
    if (first_bad_edge_ >= 0) {
        const std::size_t e = static_cast<std::size_t>(first_bad_edge_);
        os << "non-manifold edge " << e << " (" << edges_[e][0] << ", " << edges_[e][1]
           << "): its tets do not form a single fan";
        return os.str();
    }
    if (first_bad_vertex_ >= 0) {
        const std::size_t v = static_cast<std::size_t>(first_bad_vertex_);
        os << "non-manifold vertex " << v << ": its " << (vc_off_[v + 1] - vc_off_[v])
           << " tets form more than one connected fan";
        return os.str();
    }
    return {};
}

} // namespace HexEx
