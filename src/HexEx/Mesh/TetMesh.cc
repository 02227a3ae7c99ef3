#include "TetMesh.hh"

#include "../Core/Error.hh"
#include "../Core/Parallel.hh"

#include <algorithm>
#include <sstream>

namespace HexEx {

constexpr int TetMesh::kFaceCorners[4][3];
constexpr int TetMesh::kEdgeCorners[6][2];

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
    // Vertex -> cells (counting sort keeps cells ascending).
    vc_off_.assign(nv + 1, 0);
    for (const auto& c : cells_)
        for (auto v : c) ++vc_off_[v.uidx() + 1];
    for (std::size_t i = 0; i < nv; ++i) vc_off_[i + 1] += vc_off_[i];
    vc_idx_.resize(vc_off_[nv]);
    {
        std::vector<int> fill(vc_off_.begin(), vc_off_.end() - 1);
        for (std::size_t c = 0; c < nc; ++c)
            for (auto v : cells_[c]) vc_idx_[fill[v.uidx()]++] = static_cast<int>(c);
    }

    // Opposite halffaces. Every face is matched within the bucket of its smallest vertex
    // v: the halffaces of the tets around v whose smallest vertex is v, keyed by their
    // other two vertices and sorted; equal keys are the two sides of one face. A halfface
    // lies in exactly one bucket, so the vertices run in parallel and each writes only the
    // slots of its own bucket. A key held by three or more halffaces is a non-manifold
    // face; the one whose first tet and face come first is reported (for any thread count).
    opposite_.assign(4 * nc, -1);  // -1: boundary
    const int vchunks = nv < 20000 ? 1 : resolveThreadCount(threads);
    std::vector<std::array<long long, 2>> badFace(static_cast<std::size_t>(std::max(1, vchunks)), {-1, 0});
    parallelChunks(nv, vchunks, [&](int chunk, std::size_t vb, std::size_t ve) {
        struct Side {
            unsigned long long key;  // the other two vertices, smaller one in the high half
            int hf;
        };
        std::vector<Side> bucket;
        long long firstBad = -1, firstBadCount = 0;
        for (std::size_t v = vb; v < ve; ++v) {
            bucket.clear();
            for (int o = vc_off_[v]; o < vc_off_[v + 1]; ++o) {
                const int c = vc_idx_[o];
                const auto& cv = cells_[static_cast<std::size_t>(c)];
                for (int i = 0; i < 4; ++i) {
                    if (cv[i].uidx() == v) continue;  // the face opposite v does not contain it
                    int a = cv[kFaceCorners[i][0]].idx(), b = cv[kFaceCorners[i][1]].idx(), d = cv[kFaceCorners[i][2]].idx();
                    if (a == static_cast<int>(v)) a = d;
                    else if (b == static_cast<int>(v)) b = d;
                    if (a < static_cast<int>(v) || b < static_cast<int>(v)) continue;  // another vertex's bucket
                    if (b < a) std::swap(a, b);
                    bucket.push_back({(static_cast<unsigned long long>(a) << 32) | static_cast<unsigned>(b), 4 * c + i});
                }
            }
            std::sort(bucket.begin(), bucket.end(),
                      [](const Side& x, const Side& y) { return x.key < y.key || (x.key == y.key && x.hf < y.hf); });
            for (std::size_t k = 0; k < bucket.size();) {
                std::size_t e = k + 1;
                while (e < bucket.size() && bucket[e].key == bucket[k].key) ++e;
                if (e - k == 2) {
                    opposite_[static_cast<std::size_t>(bucket[k].hf)] = bucket[k + 1].hf;
                    opposite_[static_cast<std::size_t>(bucket[k + 1].hf)] = bucket[k].hf;
                } else if (e - k > 2 && (firstBad < 0 || bucket[k].hf < firstBad)) {
                    firstBad = bucket[k].hf;
                    firstBadCount = static_cast<long long>(e - k);
                }
                k = e;
            }
        }
        badFace[static_cast<std::size_t>(chunk)] = {firstBad, firstBadCount};
    });
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
    const int chunks = nc < 50000 ? 1 : resolveThreadCount(threads);

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

    // Edges, grouped by smaller endpoint and sorted by the larger one: per vertex the
    // larger neighbours are counted, then (after a prefix sum) written, both in parallel.
    // The second pass also does, for the edges of its vertex v (smaller endpoint), what
    // needs the edge numbers: the tets' edge slots, the number of tets per edge and the
    // start tet of every edge's walk below. The tets of an edge are all in the star of v,
    // visited in tet order, so the start rule (the last boundary face met in tet order,
    // else the first tet) does not depend on the thread count.
    auto largerNeighbours = [&](std::size_t v, std::vector<int>& nbrs) {
        nbrs.clear();
        for (int o = vc_off_[v]; o < vc_off_[v + 1]; ++o)
            for (auto w : cells_[static_cast<std::size_t>(vc_idx_[o])])
                if (w.idx() > static_cast<int>(v)) nbrs.push_back(w.idx());
        std::sort(nbrs.begin(), nbrs.end());
        nbrs.erase(std::unique(nbrs.begin(), nbrs.end()), nbrs.end());
    };
    ve_off_.assign(nv + 1, 0);
    parallelChunks(nv, vchunks, [&](int, std::size_t b, std::size_t e) {
        std::vector<int> nbrs;
        for (std::size_t v = b; v < e; ++v) {
            largerNeighbours(v, nbrs);
            ve_off_[v + 1] = static_cast<int>(nbrs.size());
        }
    });
    for (std::size_t v = 0; v < nv; ++v) ve_off_[v + 1] += ve_off_[v];
    const std::size_t ne = static_cast<std::size_t>(ve_off_[nv]);
    edges_.resize(ne);
    ve_idx_.resize(ne);
    cell_edges_.resize(6 * nc);
    ec_off_.assign(ne + 1, 0);
    std::vector<int> start(ne, -1);     // a cell of the edge, preferring one at the boundary
    std::vector<int> start_hf(ne, -1);  // the halfface of start through which the walk must NOT leave
    parallelChunks(nv, vchunks, [&](int, std::size_t b, std::size_t e) {
        std::vector<int> nbrs;
        for (std::size_t v = b; v < e; ++v) {
            largerNeighbours(v, nbrs);
            const int first = ve_off_[v];
            for (std::size_t k = 0; k < nbrs.size(); ++k) {
                const std::size_t id = static_cast<std::size_t>(first) + k;
                ve_idx_[id] = static_cast<int>(id);
                edges_[id] = {VertexHandle(static_cast<int>(v)), VertexHandle(nbrs[k])};
            }
            for (int o = vc_off_[v]; o < vc_off_[v + 1]; ++o) {
                const std::size_t c = static_cast<std::size_t>(vc_idx_[o]);
                const auto& cv = cells_[c];
                for (int k = 0; k < 6; ++k) {
                    const int a = kEdgeCorners[k][0], bb = kEdgeCorners[k][1];
                    const int x = cv[a].idx(), y = cv[bb].idx();
                    if (std::min(x, y) != static_cast<int>(v)) continue;  // another vertex's edge
                    const int w = std::max(x, y);
                    const int id = first + static_cast<int>(std::lower_bound(nbrs.begin(), nbrs.end(), w) - nbrs.begin());
                    cell_edges_[6 * c + static_cast<std::size_t>(k)] = id;
                    ++ec_off_[static_cast<std::size_t>(id) + 1];
                    for (int j = 0; j < 4; ++j)
                        if (j != a && j != bb && opposite_[4 * c + static_cast<std::size_t>(j)] < 0) {
                            start[static_cast<std::size_t>(id)] = static_cast<int>(c);
                            start_hf[static_cast<std::size_t>(id)] = static_cast<int>(4 * c) + j;
                        }
                    if (start[static_cast<std::size_t>(id)] < 0) start[static_cast<std::size_t>(id)] = static_cast<int>(c);
                }
            }
        }
    });

    // Edge -> cells in cyclic order: walk across the faces that contain the edge.
    for (std::size_t e = 0; e < ne; ++e) ec_off_[e + 1] += ec_off_[e];
    ec_idx_.assign(static_cast<std::size_t>(ec_off_[ne]), -1);
    boundary_edge_.assign(ne, 0);
    // Every edge fills only its own slots: edges in parallel.
    parallelChunks(ne, ne < 20000 ? 1 : resolveThreadCount(threads), [&](int, std::size_t eb, std::size_t ee) {
    for (std::size_t e = eb; e < ee; ++e) {
        int c = start[e], in_hf = start_hf[e];
        if (in_hf >= 0) boundary_edge_[e] = 1;
        int pos = ec_off_[e];
        const int end = ec_off_[e + 1];
        while (pos < end) {
            ec_idx_[pos++] = c;
            // The two halffaces of c that contain the edge: opposite the corners not on it.
            int k = 0;
            while (cell_edges_[6 * c + k] != static_cast<int>(e)) ++k;
            const int a = kEdgeCorners[k][0], b = kEdgeCorners[k][1];
            int out = -1;
            for (int j = 0; j < 4; ++j)
                if (j != a && j != b && 4 * c + j != in_hf) {
                    out = 4 * c + j;
                    if (in_hf < 0) break;  // first step of an interior ring: either direction
                }
            const int next = opposite_[out];
            if (next < 0 || next / 4 == start[e]) break;
            c = next / 4;
            in_hf = next;
        }
        // A non-manifold edge leaves slots unfilled; check_manifold() reports it.
    }
    });

    boundary_vertex_.assign(nv, 0);
    for (std::size_t hf = 0; hf < 4 * nc; ++hf)
        if (opposite_[hf] < 0)
            for (int k = 0; k < 3; ++k) boundary_vertex_[cells_[hf / 4][kFaceCorners[hf % 4][k]].uidx()] = 1;
    adjacency_built_ = true;
}

std::string TetMesh::check_manifold(int threads) const {
    std::ostringstream os;
    for (std::size_t e = 0; e < edges_.size(); ++e)
        for (int o = ec_off_[e]; o < ec_off_[e + 1]; ++o)
            if (ec_idx_[o] < 0) {
                os << "non-manifold edge " << e << " (" << edges_[e][0] << ", " << edges_[e][1]
                   << "): its tets do not form a single fan";
                return os.str();
            }
    // Vertex stars must be connected through faces that contain the vertex. Vertices in
    // parallel chunks (each with its own marks); the first bad vertex of the first chunk
    // that has one is reported, i.e. the first in vertex order, for any thread count.
    const std::size_t nv = positions_.size();
    const int chunks = nv < 20000 ? 1 : resolveThreadCount(threads);
    std::vector<long long> firstBad(static_cast<std::size_t>(std::max(1, chunks)), -1);
    parallelChunks(nv, chunks, [&](int chunk, std::size_t vb, std::size_t ve) {
        std::vector<int> stack, mark(cells_.size(), -1);
        for (std::size_t v = vb; v < ve; ++v) {
            const int first = vc_off_[v], last = vc_off_[v + 1];
            if (first == last) continue;
            int reached = 0;
            stack.assign(1, vc_idx_[first]);
            mark[vc_idx_[first]] = static_cast<int>(v);
            while (!stack.empty()) {
                const int c = stack.back();
                stack.pop_back();
                ++reached;
                for (int j = 0; j < 4; ++j) {
                    if (cells_[c][j].idx() == static_cast<int>(v)) continue;  // face opposite v does not contain it
                    const int opp = opposite_[4 * c + j];
                    if (opp >= 0 && mark[opp / 4] != static_cast<int>(v)) {
                        mark[opp / 4] = static_cast<int>(v);
                        stack.push_back(opp / 4);
                    }
                }
            }
            if (reached != last - first) {
                firstBad[static_cast<std::size_t>(chunk)] = static_cast<long long>(v);
                return;
            }
        }
    });
    for (const long long v : firstBad)
        if (v >= 0) {
            os << "non-manifold vertex " << v << ": its " << (vc_off_[v + 1] - vc_off_[v])
               << " tets form more than one connected fan";
            return os.str();
        }
    return {};
}

} // namespace HexEx
