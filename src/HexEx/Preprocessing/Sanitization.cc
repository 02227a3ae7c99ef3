#include "Sanitization.hh"

#include "../Core/Parallel.hh"
#include "../Core/Prefetch.hh"
#include "../Predicates/ExactPredicates.hh"

#include <algorithm>
#include <cmath>

namespace HexEx {

void quantizeParameter(Vec3d& u, double bound, double epsilon, int& snapped) {
    int e = 0;
    std::frexp(bound + 1.0, &e);  // bound + 1 < 2^e
    const double quantum = std::ldexp(1.0, e - 52);
    for (int k = 0; k < 3; ++k) {
        if (!std::isfinite(u[k])) continue;
        u[k] = std::nearbyint(u[k] / quantum) * quantum;
        const double r = std::nearbyint(u[k]);
        if (u[k] != r && std::fabs(u[k] - r) <= epsilon) {
            u[k] = r;
            ++snapped;
        }
    }
}

namespace {
/// g^-1(p), the same doubles as g.inverse().apply(p): R^-1 is the transpose of R, so
/// coordinate j of the result is sign(j) p[perm(j)] minus the integer sign(j) t[perm(j)].
/// Reads at computed places and writes to fixed ones (no stores at computed places into a
/// temporary that is read right after).
Vec3d applyInverse(const GridTransform& g, const Vec3d& p) {
    Vec3d r;
    for (int j = 0; j < 3; ++j) {
        const int i = g.R.perm(j), sign = g.R.sign(j);
        r[j] = sign * p[i] + static_cast<double>(-(sign * g.t[i]));
    }
    return r;
}

/// The common case, without the breadth-first walk: every face around @p v has the
/// identity transition and every cell holds the same parameter for @p v. Then all copies
/// get the same quantized value. Returns false (nothing changed) otherwise. With
/// @p oneChart (every transition the identity) the transitions are not looked at.
bool sanitizeSimpleVertex(const TetMesh& mesh, CornerParams& params, const Transitions& tr, bool oneChart,
                          VertexHandle v, double epsilon, int& snapped) {
    auto cells = mesh.vertex_cells(v);
    const Vec3d* first = nullptr;
    for (auto it = cells.first; it != cells.second; ++it) {
        const CellHandle c(*it);
        const int k = TetMesh::corner_of(mesh.cell_vertices(c), v);
        const Vec3d& p = params[c.uidx()][k];
        if (first && !(p == *first)) return false;
        if (!first) first = &p;
        if (oneChart) continue;
        for (int j = 0; j < 4; ++j)
            if (j != k && !tr.halfface.is_identity(TetMesh::halfface(c, j).uidx())) return false;
    }
    Vec3d u = *first;
    quantizeParameter(u, std::max({std::fabs(u[0]), std::fabs(u[1]), std::fabs(u[2])}), epsilon, snapped);
    if (u == *first) return true;  // already clean: nothing to write
    for (auto it = cells.first; it != cells.second; ++it) {
        const CellHandle c(*it);
        params[c.uidx()][TetMesh::corner_of(mesh.cell_vertices(c), v)] = u;
    }
    return true;
}
/// How many vertices ahead of the current one the star is prefetched.
constexpr std::size_t kPrefetchAhead = 2;
/// Vertices per block handed to a thread (parallelBlocks()).
constexpr std::size_t kVertexBlock = 1024;

/// One thread's buffers for the walk over the stars (reused from vertex to vertex).
struct StarScratch {
    std::vector<int> star;                 ///< cells around the vertex, BFS order
    std::vector<unsigned char> slot;       ///< per star entry: the vertex's corner in that cell
    std::vector<GridTransform> toChart;    ///< transform from the reference chart, per star entry
    /// mark[c] == v: cell c already in the star of vertex v (O(1) instead of a search);
    /// allocated at the thread's first vertex that needs the walk (none on a one-chart map).
    std::vector<int> mark;
    std::vector<Vec3d> ref;                ///< the star's values in the reference chart (vote)
    std::vector<char> agrees;              ///< per star entry: agrees with the voted value
};

/// Asks the CPU to load what the sanitization of @p v reads (the corners, opposite
/// halffaces, transition codes and parameters of its tets) early: the tets of a star are
/// scattered over the arrays, and the walk over them is a chain of dependent loads.
void prefetchStar(const TetMesh& mesh, const CornerParams& params, const Transitions& tr, VertexHandle v) {
    auto cells = mesh.vertex_cells(v);
    for (auto it = cells.first; it != cells.second; ++it) {
        const CellHandle c(*it);
        mesh.prefetch_cell(c);
        const char* p = reinterpret_cast<const char*>(params[c.uidx()].data());
        prefetchKept(p);
        prefetchKept(p + sizeof(params[0]) - 1);
        tr.halfface.prefetch(4 * c.uidx());
    }
}

/// Asks the CPU to load the walk's marks of the tets of @p v early (an int per tet, as
/// scattered as the tets).
void prefetchMarks(const TetMesh& mesh, const std::vector<int>& mark, VertexHandle v) {
    auto cells = mesh.vertex_cells(v);
    for (auto it = cells.first; it != cells.second; ++it) prefetchKept(&mark[static_cast<std::size_t>(*it)]);
}

/// True if two values of a vertex (in one chart) are the same up to @p epsilon, relative
/// to their magnitude once above 1.
bool sameValue(const Vec3d& a, const Vec3d& b, double epsilon) {
    for (int k = 0; k < 3; ++k) {
        const double tol = epsilon * std::max({1.0, std::fabs(a[k]), std::fabs(b[k])});
        if (!(std::fabs(a[k] - b[k]) <= tol)) return false;
    }
    return true;
}

/// Which star entry's value seeds the vertex: entry 0 (the first tet's) unless the values
/// (mapped into the reference chart through @p toChart) disagree and a strict majority of
/// the star's tets share one value: then the first entry holding it. Fills @p ref with the
/// mapped values, and @p agrees (per entry: agrees with the chosen value) only in the
/// majority case, i.e. when there is something to repair; else it is left empty.
/// Consistent stars cost one pass. @p corner(q) is the value of star entry q.
template <class Corner>
std::size_t voteSeed(const std::vector<int>& star, const std::vector<GridTransform>& toChart, Corner&& corner,
                     double epsilon, std::vector<Vec3d>& ref, std::vector<char>& agrees) {
    const std::size_t n = star.size();
    agrees.clear();
    ref.resize(n);
    ref[0] = corner(0);
    bool all = true;
    for (std::size_t q = 1; q < n; ++q) {
        ref[q] = applyInverse(toChart[q], corner(q));
        all = all && sameValue(ref[0], ref[q], epsilon);
    }
    if (all) return 0;
    std::size_t best = 0, bestCount = 0;
    for (std::size_t q = 0; q < n; ++q) {
        std::size_t count = 0;
        for (std::size_t r = 0; r < n; ++r) count += sameValue(ref[q], ref[r], epsilon) ? 1 : 0;
        if (count > bestCount) {
            bestCount = count;
            best = q;
        }
    }
    if (2 * bestCount <= n) return 0;  // no strict majority: nothing to vote on (noise, not a typo)
    agrees.resize(n);
    for (std::size_t q = 0; q < n; ++q) agrees[q] = sameValue(ref[best], ref[q], epsilon) ? 1 : 0;
    return best;
}
} // namespace

SanitizeStats sanitizeParameters(const TetMesh& mesh, CornerParams& params, const Transitions& tr,
                                 const SanitizeOptions& opt) {
    SanitizeStats stats;
    // Every vertex reads and writes only its own corners, so vertices are processed in
    // parallel. The work per vertex varies along the numbering (on pig x2 the first half of
    // the vertices all need the walk, the second half half of them: 0.054 s against 0.008 s
    // in two equal chunks), so blocks of vertices are handed out as threads finish.
    const int threads = std::max(1, opt.threads);
    const bool oneChart = tr.halfface.all_identity();
    // One block on one thread (nothing to balance).
    const std::size_t blockSize = threads > 1 ? kVertexBlock : std::max<std::size_t>(1, mesh.n_vertices());
    const std::size_t nBlocks = (mesh.n_vertices() + blockSize - 1) / blockSize;
    std::vector<int> snapped(nBlocks, 0);
    std::vector<std::vector<CornerRepair>> repaired(nBlocks);
    std::vector<StarScratch> scratch(static_cast<std::size_t>(threads));
    parallelBlocks(mesh.n_vertices(), blockSize, threads, [&](int thread, std::size_t block, std::size_t vbegin, std::size_t vend) {
    StarScratch& S = scratch[static_cast<std::size_t>(thread)];
    std::vector<int>& star = S.star;
    std::vector<unsigned char>& slot = S.slot;
    std::vector<GridTransform>& toChart = S.toChart;
    std::vector<int>& mark = S.mark;
    std::vector<Vec3d>& ref = S.ref;
    std::vector<char>& agrees = S.agrees;
    for (std::size_t vi = vbegin; vi < vend; ++vi) {
        const VertexHandle v(static_cast<int>(vi));
        if (vi + kPrefetchAhead < vend) {
            const VertexHandle ahead(static_cast<int>(vi + kPrefetchAhead));
            prefetchStar(mesh, params, tr, ahead);
            if (!mark.empty()) prefetchMarks(mesh, mark, ahead);
        }
        auto cells = mesh.vertex_cells(v);
        if (cells.first == cells.second) continue;
        if (sanitizeSimpleVertex(mesh, params, tr, oneChart, v, opt.epsilon, snapped[block])) continue;
        if (mark.empty()) mark.assign(mesh.n_cells(), -1);
        star.assign(1, *cells.first);
        slot.assign(1, static_cast<unsigned char>(TetMesh::corner_of(mesh.cell_vertices(CellHandle(*cells.first)), v)));
        mark[static_cast<std::size_t>(*cells.first)] = static_cast<int>(vi);
        toChart.assign(1, GridTransform());
        for (std::size_t q = 0; q < star.size(); ++q) {
            const CellHandle c(star[q]);
            for (int j = 0; j < 4; ++j) {
                if (mesh.cell_vertex(c, j) == v) continue;  // that face does not contain v
                const HalfFaceHandle hf = TetMesh::halfface(c, j);
                const HalfFaceHandle o = mesh.opposite_halfface(hf);
                if (!o.is_valid()) continue;
                const int n = TetMesh::cell(o).idx();
                if (mark[static_cast<std::size_t>(n)] == static_cast<int>(vi)) continue;
                mark[static_cast<std::size_t>(n)] = static_cast<int>(vi);
                star.push_back(n);
                slot.push_back(static_cast<unsigned char>(TetMesh::corner_of(mesh.cell_vertices(CellHandle(n)), v)));
                // Faces inside a chart (most of them) have the identity: nothing to compose.
                toChart.push_back(tr.halfface.is_identity(hf.uidx()) ? toChart[q] : tr.halfface[hf.uidx()] * toChart[q]);
            }
        }
        auto corner = [&](std::size_t q) -> Vec3d& { return params[static_cast<std::size_t>(star[q])][slot[q]]; };
        // The seed: the first tet's value, unless most tets of the star agree on another one
        // (a corrupted corner must not spread over the whole star).
        const std::size_t seed = voteSeed(star, toChart, corner, opt.epsilon, ref, agrees);
        Vec3d u = seed == 0 ? corner(0) : ref[seed];
        auto& list = repaired[block];
        const std::size_t firstRepair = list.size();
        if (!agrees.empty()) {
            for (std::size_t q = 0; q < star.size(); ++q) {
                if (agrees[q]) continue;
                list.push_back({star[q], slot[q], static_cast<int>(vi), corner(q), Vec3d()});
            }
        }
        // Largest magnitude the parameter reaches in any chart (raw values, plus the
        // propagated ones' bound), so that truncation leaves every chart exact. Repaired
        // corners' raw values do not count: they are overwritten.
        double bound = 0;
        const double umax = std::max({std::fabs(u[0]), std::fabs(u[1]), std::fabs(u[2])});
        for (std::size_t q = 0; q < star.size(); ++q) {
            if (!agrees.empty() && !agrees[q]) continue;
            const Vec3d& p = corner(q);
            const Vec3i& t = toChart[q].t;
            bound = std::max({bound, std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2]),
                              umax + std::max({std::abs(t[0]), std::abs(t[1]), std::abs(t[2])})});
        }
        quantizeParameter(u, bound, opt.epsilon, snapped[block]);
        for (std::size_t q = 0; q < star.size(); ++q) corner(q) = toChart[q].apply(u);
        for (std::size_t k = firstRepair; k < list.size(); ++k)
            list[k].repaired = params[static_cast<std::size_t>(list[k].tet)][list[k].corner];
    }
    });
    for (int n : snapped) stats.snapped_coordinates += n;
    for (const auto& part : repaired) {
        stats.repaired_corners += static_cast<long>(part.size());
        stats.repairs.insert(stats.repairs.end(), part.begin(), part.end());
    }
    // Blocks are in vertex order, so the list is too, for any thread count.
    if (stats.repairs.size() > SanitizeStats::kMaxListed) stats.repairs.resize(SanitizeStats::kMaxListed);
    return stats;
}

std::vector<signed char> classifyTets(const CornerParams& params) {
    std::vector<signed char> s(params.size());
    for (std::size_t c = 0; c < params.size(); ++c) {
        const auto& p = params[c];
        s[c] = static_cast<signed char>(orient3d(p[0], p[1], p[2], p[3]));
    }
    return s;
}

} // namespace HexEx
