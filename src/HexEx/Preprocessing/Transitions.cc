#include "Transitions.hh"

#include "../Core/Parallel.hh"

#include <algorithm>
#include <cmath>
#include <limits>

namespace HexEx {

namespace {

/// Local index of vertex @p v in cell @p c, or -1.
int localIndex(const TetMesh& mesh, CellHandle c, VertexHandle v) {
    const auto& cv = mesh.cell_vertices(c);
    for (int k = 0; k < 4; ++k)
        if (cv[k] == v) return k;
    return -1;
}

/// std::lround(x) without the libm call where |x| < 2^52 (elsewhere, NaN included, it calls
/// it): there the truncation t and the fraction x - t are exact, and halves round away from
/// zero as in std::lround.
long roundHalfAway(double x) {
    if (!(std::fabs(x) < 4503599627370496.0)) return std::lround(x);
    const long t = static_cast<long>(x);
    const double f = x - static_cast<double>(t);
    return f >= 0.5 ? t + 1 : f <= -0.5 ? t - 1 : t;
}

Vec3i roundVec(const Vec3d& v) {
    return Vec3i(static_cast<int>(roundHalfAway(v[0])), static_cast<int>(roundHalfAway(v[1])),
                 static_cast<int>(roundHalfAway(v[2])));
}

/// Per interior face: the candidate rotations (bit mask) and the translation per rotation.
struct FaceFit {
    std::uint32_t candidates = 0;
    int best = 0;
    bool ambiguous = false;
};

FaceFit fitFace(const Vec3d u[3], const Vec3d w[3]) {
    FaceFit f;
    const Vec3d e1 = u[1] - u[0], e2 = u[2] - u[0];
    const Vec3d f1 = w[1] - w[0], f2 = w[2] - w[0];
    if (e1 == f1 && e2 == f2 && (e1 % e2).sqrnorm() > 0) {  // identical charts: the common case
        f.best = 0;
        f.candidates = 1u;
        return f;
    }
    // |R e - f|^2 = |e|^2 + |f|^2 - 2 f.(R e): minimizing the residual over the 24 rotations
    // maximizes sum_j sign_j M[perm_j][j] with M = f1 e1^T + f2 e2^T.
    double M[3][3];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) M[r][c] = f1[r] * e1[c] + f2[r] * e2[c];
    double score[24];
    double best = -std::numeric_limits<double>::max();
    for (int r = 0; r < 24; ++r) {
        const Rotation R(r);
        score[r] = R.sign(0) * M[R.perm(0)][0] + R.sign(1) * M[R.perm(1)][1] + R.sign(2) * M[R.perm(2)][2];
        if (score[r] > best) {
            best = score[r];
            f.best = r;
        }
    }
    const double l1 = e1.sqrnorm(), l2 = e2.sqrnorm();
    const double area2 = (e1 % e2).sqrnorm();
    f.ambiguous = !(area2 > 1e-12 * l1 * l2) || l1 == 0 || l2 == 0;
    if (!f.ambiguous) {
        f.candidates = 1u << f.best;
    } else {
        const double tol = 0.5e-6 * (l1 + l2) + 1e-12;
        for (int r = 0; r < 24; ++r)
            if (score[r] >= best - tol) f.candidates |= 1u << r;
    }
    return f;
}

/// Per-corner translations w_k - R u_k under rotation @p R: the same doubles as
/// w[k] - R.apply(u[k]), with coordinate i of R u read from the coordinate of u that R maps
/// onto axis i (no stores at computed places into a vector that is read right after).
void cornerResiduals(const Vec3d u[3], const Vec3d w[3], const Rotation& R, Vec3d d[3]) {
    int from[3], sign[3];
    for (int j = 0; j < 3; ++j) {
        from[R.perm(j)] = j;
        sign[R.perm(j)] = R.sign(j);
    }
    for (int k = 0; k < 3; ++k)
        d[k] = Vec3d(w[k][0] - sign[0] * u[k][from[0]], w[k][1] - sign[1] * u[k][from[1]], w[k][2] - sign[2] * u[k][from[2]]);
}

/// Largest coordinate difference.
double maxDiff(const Vec3d& a, const Vec3d& b) {
    return std::max({std::fabs(a[0] - b[0]), std::fabs(a[1] - b[1]), std::fabs(a[2] - b[2])});
}

/// True if all three residuals round to the same integer vector (every consistent map).
bool residualsAgree(const Vec3d d[3]) {
    const Vec3i r0 = roundVec(d[0]);
    return r0 == roundVec(d[1]) && r0 == roundVec(d[2]);
}

/// Two corners agree on the translation if their residuals differ by at most this many
/// grid units; a third corner is an outlier if it is more than kOutlierDistance away from
/// them. Noise in a map moves all three residuals a little; a corrupted number moves one a
/// lot, which is what these thresholds tell apart.
constexpr double kPairTolerance = 0.05;
constexpr double kOutlierDistance = 0.5;
/// Residuals of two corners this close agree exactly (up to the rounding of a solver's
/// output): used where the least-squares fit looks fine but loose.
constexpr double kExactPair = 1e-6;

/// True if the three residuals agree within kPairTolerance (every continuous map).
bool residualsTight(const Vec3d d[3]) {
    return maxDiff(d[0], d[1]) <= kPairTolerance && maxDiff(d[0], d[2]) <= kPairTolerance &&
           maxDiff(d[1], d[2]) <= kPairTolerance;
}

/// The pair of corners (as the index of the third, the outlier) that agree while the third
/// is far off, and the pair's difference; -1 if there is no such pair.
int outlierCorner(const Vec3d d[3], double& pairError, double pairTolerance = kPairTolerance) {
    int best = -1;
    pairError = std::numeric_limits<double>::max();
    for (int o = 0; o < 3; ++o) {
        const Vec3d& a = d[(o + 1) % 3];
        const Vec3d& b = d[(o + 2) % 3];
        const double e = maxDiff(a, b);
        if (e > pairTolerance || e >= pairError) continue;
        const Vec3d mid = (a + b) * 0.5;
        if (maxDiff(d[o], mid) <= kOutlierDistance) continue;
        best = o;
        pairError = e;
    }
    return best;
}

/// The translation of a face under rotation @p R: the rounded mean of the three corners'
/// residuals (today's rule, kept whenever the corners agree), or, when one corner is an
/// outlier (a corrupted parameter), the rounded mean of the two that agree.
Vec3i faceTranslation(const Vec3d u[3], const Vec3d w[3], const Rotation& R) {
    Vec3d d[3];
    cornerResiduals(u, w, R, d);
    double e = 0;
    const int o = residualsAgree(d) ? -1 : outlierCorner(d, e);
    if (o < 0) return roundVec((d[0] + d[1] + d[2]) / 3.0);
    return roundVec((d[(o + 1) % 3] + d[(o + 2) % 3]) / 2.0);
}

/// Fit by consensus for a face whose corners do not agree under the least-squares
/// rotation: the rotations under which two corners agree closely while the third is an
/// outlier, the best-agreeing first. A single clean edge may be fitted by several rotations
/// (an axis-aligned edge); they become candidates for the edge-consistency resolution like
/// a degenerate face's. Returns false if no rotation shows such an outlier (noise rather
/// than a corrupted corner); the least-squares fit is kept then.
bool consensusFit(const Vec3d u[3], const Vec3d w[3], FaceFit& f, double pairTolerance) {
    double err[24];
    double minErr = std::numeric_limits<double>::max();
    int best = -1;
    for (int r = 0; r < 24; ++r) {
        Vec3d d[3];
        cornerResiduals(u, w, Rotation(r), d);
        err[r] = std::numeric_limits<double>::max();
        if (outlierCorner(d, err[r], pairTolerance) < 0) continue;
        if (err[r] < minErr) {
            minErr = err[r];
            best = r;
        }
    }
    if (best < 0) return false;
    f.best = best;
    f.candidates = 0;
    const double tol = 1e-9 + 4 * std::numeric_limits<double>::epsilon() * (1 + minErr);
    for (int r = 0; r < 24; ++r)
        if (err[r] <= minErr + tol) f.candidates |= 1u << r;
    f.ambiguous = (f.candidates & (f.candidates - 1)) != 0;
    return true;
}

/// True if the corners agree on the translation under some candidate rotation of @p f.
bool cornersAgree(const Vec3d u[3], const Vec3d w[3], const FaceFit& f) {
    for (int r = 0; r < 24; ++r) {
        if (!(f.candidates & (1u << r))) continue;
        Vec3d d[3];
        cornerResiduals(u, w, Rotation(r), d);
        if (residualsAgree(d)) return true;
    }
    return false;
}

/// How many edges ahead the holonomy walk prefetches the ring's tets.
constexpr std::size_t kEdgesAhead = 4;
/// How many halffaces (a multiple of 4: whole tets) ahead the fit prefetches.
constexpr std::size_t kHalffacesAhead = 16;
/// Halffaces per block handed to a thread in the fit (parallelBlocks(); whole tets).
constexpr std::size_t kFitBlock = 16384;

/// Asks the CPU to load the corners and parameters of the neighbours across the four
/// halffaces from @p h (the first of a tet) whose faces are fitted from this side.
void prefetchNeighbours(const TetMesh& mesh, const CornerParams& params, std::size_t h) {
    for (std::size_t k = h; k < h + 4; ++k) {
        const HalfFaceHandle o = mesh.opposite_halfface(HalfFaceHandle(static_cast<int>(k)));
        if (o.idx() < static_cast<int>(k)) continue;  // boundary, or fitted from the other side
        const CellHandle n = TetMesh::cell(o);
        mesh.prefetch_cell(n);
        const char* p = reinterpret_cast<const char*>(params[n.uidx()].data());
        prefetchKept(p);
        prefetchKept(p + sizeof(params[0]) - 1);
    }
}

} // namespace

void HalffaceTransitions::reset(std::size_t n) {
    code_.assign(n, 0);
    sparse_.clear();
    dense_.clear();
}

bool HalffaceTransitions::all_identity() const {
    // Blocks of bytes OR-ed together (vectorized), an exit after the first non-zero block.
    constexpr std::size_t kBlock = 4096;
    const std::uint8_t* c = code_.data();
    for (std::size_t b = 0; b < code_.size(); b += kBlock) {
        const std::size_t e = std::min(code_.size(), b + kBlock);
        unsigned any = 0;
        for (std::size_t h = b; h < e; ++h) any |= c[h];
        if (any) return false;
    }
    return true;
}

Vec3i HalffaceTransitions::translation(std::size_t h) const {
    if (!dense_.empty()) return dense_[h];
    const auto it = std::lower_bound(sparse_.begin(), sparse_.end(), static_cast<int>(h),
                                     [](const std::pair<int, Vec3i>& x, int k) { return x.first < k; });
    return it->second;
}

void HalffaceTransitions::set(std::size_t h, const GridTransform& g) {
    const bool moved = !(g.t == Vec3i(0, 0, 0));
    const bool had = (code_[h] & kTranslated) != 0;
    code_[h] = static_cast<std::uint8_t>(g.R.index() | (moved ? kTranslated : 0));
    if (!dense_.empty()) {
        dense_[h] = g.t;
        return;
    }
    const auto it = std::lower_bound(sparse_.begin(), sparse_.end(), static_cast<int>(h),
                                     [](const std::pair<int, Vec3i>& x, int k) { return x.first < k; });
    if (had && moved) it->second = g.t;
    else if (had) sparse_.erase(it);
    else if (moved) sparse_.insert(it, {static_cast<int>(h), g.t});
}

void HalffaceTransitions::add_translations(const std::vector<std::pair<int, Vec3i>>& list) {
    add_translations(std::vector<std::vector<std::pair<int, Vec3i>>>(1, list), 1);
}

void HalffaceTransitions::add_translations(const std::vector<std::vector<std::pair<int, Vec3i>>>& parts, int threads) {
    std::size_t added = 0;
    for (const auto& part : parts) added += part.size();
    if (dense_.empty() && (sparse_.size() + added) * 8 > code_.size()) {
        // Many translations: a dense array is smaller than the sparse pairs and faster. It is
        // zeroed in parallel chunks (its pages first touched there, not in one serial pass).
        dense_.resize(code_.size());
        parallelChunks(dense_.size(), threads, [&](int, std::size_t b, std::size_t e) {
            std::fill(dense_.begin() + static_cast<std::ptrdiff_t>(b), dense_.begin() + static_cast<std::ptrdiff_t>(e), Vec3i(0, 0, 0));
        });
        for (const auto& e : sparse_) dense_[static_cast<std::size_t>(e.first)] = e.second;
        std::vector<std::pair<int, Vec3i>>().swap(sparse_);
    }
    if (!dense_.empty()) {
        // Each halfface is in one part: parts write distinct entries.
        parallelChunks(parts.size(), threads, [&](int, std::size_t b, std::size_t e) {
            for (std::size_t k = b; k < e; ++k)
                for (const auto& t : parts[k]) {
                    code_[static_cast<std::size_t>(t.first)] |= kTranslated;
                    dense_[static_cast<std::size_t>(t.first)] = t.second;
                }
        });
        return;
    }
    for (const auto& part : parts)
        for (const auto& t : part) {
            code_[static_cast<std::size_t>(t.first)] |= kTranslated;
            sparse_.push_back(t);
        }
    std::sort(sparse_.begin(), sparse_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
}

HalfFaceHandle halffaceTowards(const TetMesh& mesh, CellHandle c, CellHandle next) {
    for (int j = 0; j < 4; ++j) {
        const HalfFaceHandle hf = TetMesh::halfface(c, j);
        const HalfFaceHandle o = mesh.opposite_halfface(hf);
        if (o.is_valid() && TetMesh::cell(o) == next) return hf;
    }
    return HalfFaceHandle();
}

Transitions computeTransitions(const TetMesh& mesh, const CornerParams& params, const std::vector<int>* given,
                               int threads) {
    Transitions out;
    const std::size_t nhf = mesh.n_halffaces();
    out.halfface.reset(nhf);
    // Fits are kept only for the (rare) ambiguous faces, sorted by halfface.
    std::vector<std::pair<std::size_t, FaceFit>> fits;
    auto fitOf = [&](std::size_t h) -> const FaceFit& {
        return std::lower_bound(fits.begin(), fits.end(), h, [](const auto& x, std::size_t k) { return x.first < k; })->second;
    };
    // Per halfface: its transition is known; built only when there are ambiguous faces to
    // resolve (before that every face is decided or in the list of fits).
    std::vector<char> decided;

    // With a list, only rotations are written and non-zero translations are collected
    // (the parallel pass); without, the transform is stored at once (the sequential pass).
    auto setTransition = [&](std::size_t h, int rot, std::vector<std::pair<int, Vec3i>>* translations = nullptr) {
        const HalfFaceHandle hf(static_cast<int>(h));
        const HalfFaceHandle opp = mesh.opposite_halfface(hf);
        const CellHandle c = TetMesh::cell(hf), c2 = TetMesh::cell(opp);
        const Rotation R(rot);
        Vec3d u[3], w[3];
        for (int k = 0; k < 3; ++k) {
            const int lc = TetMesh::kFaceCorners[TetMesh::opposite_corner(hf)][k];
            u[k] = params[c.uidx()][lc];
            w[k] = params[c2.uidx()][localIndex(mesh, c2, mesh.cell_vertex(c, lc))];
        }
        const GridTransform g(R, faceTranslation(u, w, R));
        const GridTransform gi = g.inverse();
        if (translations) {
            out.halfface.set_rotation_only(h, g.R);
            out.halfface.set_rotation_only(opp.uidx(), gi.R);
            if (!(g.t == Vec3i(0, 0, 0))) {
                translations->emplace_back(static_cast<int>(h), g.t);
                translations->emplace_back(opp.idx(), gi.t);
            }
        } else {
            out.halfface.set(h, g);
            out.halfface.set(opp.uidx(), gi);
        }
        if (!decided.empty()) decided[h] = decided[opp.uidx()] = 1;
    };

    // Each interior face is fitted by the block owning its smaller halfface; the writes go to
    // that halfface and its opposite only, so blocks never touch the same entries. Blocks are
    // handed out as threads finish: faces inside a chart cost a comparison, faces between
    // charts a fit, and the charts' faces are not spread evenly over the halfface range (on
    // pig x2 two equal chunks took 0.026 and 0.017 s).
    // One block on one thread (nothing to balance; no per-block lists to join).
    const std::size_t blockSize = threads > 1 ? kFitBlock : std::max<std::size_t>(1, nhf);
    const std::size_t nBlocks = (nhf + blockSize - 1) / blockSize;
    std::vector<int> ambiguous(nBlocks, 0);
    std::vector<int> inconsistent(nBlocks, 0);
    std::vector<std::vector<std::pair<std::size_t, FaceFit>>> ambiguousFits(nBlocks);
    std::vector<std::vector<std::pair<int, Vec3i>>> translations(nBlocks);
    parallelBlocks(nhf, blockSize, std::max(1, threads), [&](int, std::size_t block, std::size_t hb, std::size_t he) {
        for (std::size_t h = hb; h < he; ++h) {
            // The neighbours' corners and parameters a few tets ahead (they lie anywhere in
            // the arrays; this tet's own are read in order).
            if (h % 4 == 0 && h + kHalffacesAhead < he) prefetchNeighbours(mesh, params, h + kHalffacesAhead);
            const HalfFaceHandle hf(static_cast<int>(h));
            const HalfFaceHandle opp = mesh.opposite_halfface(hf);
            if (!opp.is_valid() || opp.idx() < hf.idx()) continue;
            auto& moved = translations[block];
            if (given) {
                setTransition(h, (*given)[h], &moved);
                continue;
            }
            const CellHandle c = TetMesh::cell(hf), c2 = TetMesh::cell(opp);
            const auto& cv = mesh.cell_vertices(c);
            const auto& cv2 = mesh.cell_vertices(c2);  // contains the face's three vertices
            Vec3d u[3], w[3];
            for (int k = 0; k < 3; ++k) {
                const int lc = TetMesh::kFaceCorners[TetMesh::opposite_corner(hf)][k];
                u[k] = params[c.uidx()][lc];
                w[k] = params[c2.uidx()][TetMesh::corner_of(cv2, cv[lc])];
            }
            // Same chart on both sides of a proper face: identity (already set). A face whose
            // image is degenerate may hide a rotation about it, so it goes through the fit.
            if (u[0] == w[0] && u[1] == w[1] && u[2] == w[2] && ((u[1] - u[0]) % (u[2] - u[0])).sqrnorm() > 0) continue;
            FaceFit fit = fitFace(u, w);
            // A corrupted corner makes the three corners disagree on the translation under
            // the least-squares rotation (and can mislead that rotation): fit by consensus.
            // Residuals that round alike but spread widely may still hide a corrupted corner
            // that misled the rotation (on a small face a wrong rotation can make them round
            // alike); there only an exact pair (a continuous map with one bad corner), not a
            // noisy one, may overrule the least-squares fit.
            bool agree, loose = false;
            if (fit.ambiguous) {
                agree = cornersAgree(u, w, fit);
            } else {
                Vec3d d[3];
                cornerResiduals(u, w, Rotation(fit.best), d);
                agree = residualsAgree(d);
                loose = agree && !residualsTight(d);
            }
            if ((!agree && consensusFit(u, w, fit, kPairTolerance)) || (loose && consensusFit(u, w, fit, kExactPair)))
                ++inconsistent[block];
            if (fit.ambiguous) {
                ambiguousFits[block].emplace_back(h, fit);
                ++ambiguous[block];
            } else {
                setTransition(h, fit.best, &moved);
            }
        }
    });
    out.halfface.add_translations(translations, threads);
    for (int a : ambiguous) out.n_ambiguous += a;
    for (int a : inconsistent) out.n_inconsistent += a;
    for (auto& part : ambiguousFits) fits.insert(fits.end(), part.begin(), part.end());  // blocks are in halfface order
    if (out.n_ambiguous == 0) return out;
    decided.assign(nhf, 1);
    for (const auto& f : fits) decided[f.first] = decided[mesh.opposite_halfface(HalfFaceHandle(static_cast<int>(f.first))).uidx()] = 0;

    // Resolve ambiguous faces from edge consistency: the rotation that makes the holonomy
    // around one of the face's edges trivial, once all other faces around that edge are known.
    bool progress = true;
    while (progress) {
        progress = false;
        for (std::size_t h = 0; h < nhf; ++h) {
            if (decided[h]) continue;
            const HalfFaceHandle hf(static_cast<int>(h));
            const HalfFaceHandle opp = mesh.opposite_halfface(hf);
            if (opp.idx() < hf.idx()) continue;
            const CellHandle c = TetMesh::cell(hf), c2 = TetMesh::cell(opp);
            const int oc = TetMesh::opposite_corner(hf);
            for (int k = 0; k < 3 && !decided[h]; ++k) {
                const VertexHandle a = mesh.cell_vertex(c, TetMesh::kFaceCorners[oc][k]);
                const VertexHandle b = mesh.cell_vertex(c, TetMesh::kFaceCorners[oc][(k + 1) % 3]);
                const EdgeHandle e = mesh.find_edge(a, b);
                if (mesh.is_boundary(e)) continue;
                auto ring = mesh.edge_cells(e);
                const int m = static_cast<int>(ring.second - ring.first);
                int j = 0;
                while (j < m && ring.first[j] != c2.idx()) ++j;
                // Walk from c2 around the ring back to c (the long way), composing transitions.
                GridTransform A;
                bool known = true;
                int cur = j;
                int dir = (ring.first[(j + 1) % m] == c.idx()) ? -1 : 1;
                for (int step = 0; step < m - 1; ++step) {
                    const int nxt = ((cur + dir) % m + m) % m;
                    const HalfFaceHandle t = halffaceTowards(mesh, CellHandle(ring.first[cur]), CellHandle(ring.first[nxt]));
                    if (!t.is_valid() || !decided[t.uidx()]) { known = false; break; }
                    A = out.halfface[t.uidx()] * A;
                    cur = nxt;
                }
                if (!known || ring.first[cur] != c.idx()) continue;
                // A maps chart c2 -> chart c; the loop c -> c2 -> c is trivial iff X = A^-1.
                const int want = A.R.inverse().index();
                if (fitOf(h).candidates & (1u << want)) {
                    setTransition(h, want);
                    progress = true;
                }
            }
        }
    }
    for (std::size_t h = 0; h < nhf; ++h) {
        const HalfFaceHandle hf(static_cast<int>(h));
        const HalfFaceHandle opp = mesh.opposite_halfface(hf);
        if (decided[h] || opp.idx() < hf.idx()) continue;
        ++out.n_unresolved;
        setTransition(h, (fitOf(h).candidates & 1u) ? 0 : fitOf(h).best);
    }
    return out;
}

Singularities findSingularities(const TetMesh& mesh, const CornerParams& params, const Transitions& tr, int threads) {
    Singularities s;
    s.is_singular_vertex.assign(mesh.n_vertices(), 0);
    // One chart (every transition the identity): every holonomy is the identity.
    if (tr.halfface.all_identity()) return s;
    std::vector<int> count(mesh.n_vertices(), 0);
    // Edges are independent: chunks collect their singular edges, concatenated in order.
    const int chunks = std::max(1, threads);
    std::vector<std::vector<SingularEdge>> found(static_cast<std::size_t>(chunks));
    parallelChunks(mesh.n_edges(), chunks, [&](int chunk, std::size_t eb, std::size_t ee) {
    for (std::size_t ei = eb; ei < ee; ++ei) {
        if (ei + kEdgesAhead < ee) {  // the ring's tets lie anywhere in the arrays
            auto ahead = mesh.edge_cells(EdgeHandle(static_cast<int>(ei + kEdgesAhead)));
            for (const int* c = ahead.first; c != ahead.second; ++c) mesh.prefetch_cell(CellHandle(*c));
        }
        const EdgeHandle e(static_cast<int>(ei));
        if (mesh.is_boundary(e)) continue;
        auto ring = mesh.edge_cells(e);
        const int m = static_cast<int>(ring.second - ring.first);
        Rotation H;
        for (int j = 0; j < m; ++j) {
            const HalfFaceHandle hf = halffaceTowards(mesh, CellHandle(ring.first[j]), CellHandle(ring.first[(j + 1) % m]));
            if (hf.is_valid()) H = tr.halfface.rotation(hf.uidx()) * H;
        }
        if (H.is_identity()) continue;
        double angle = 0;
        const auto ev = mesh.edge_vertices(e);
        for (int j = 0; j < m; ++j) {
            const CellHandle c(ring.first[j]);
            // Parametric dihedral angle of c at the edge, signed by the tet's orientation.
            const auto& cv = mesh.cell_vertices(c);
            const auto& p = params[c.uidx()];
            int ia = -1, ib = -1, o[2], no = 0;
            for (int k = 0; k < 4; ++k) {
                if (cv[k] == ev[0]) ia = k;
                else if (cv[k] == ev[1]) ib = k;
                else o[no++] = k;
            }
            if (ia < 0 || ib < 0 || no != 2) continue;
            const Vec3d d = p[ib] - p[ia];
            const double dl2 = d.sqrnorm();
            if (dl2 == 0) continue;
            Vec3d u = p[o[0]] - p[ia], v = p[o[1]] - p[ia];
            u -= d * ((u | d) / dl2);
            v -= d * ((v | d) / dl2);
            const double vol = tetVolume6(p[0], p[1], p[2], p[3]);
            const double ang = std::atan2((u % v).norm(), u | v);
            angle += vol > 0 ? ang : vol < 0 ? -ang : 0.0;
        }
        SingularEdge se;
        se.edge = e;
        se.holonomy = H;
        se.valence = static_cast<int>(std::lround(angle / (M_PI / 2)));
        found[static_cast<std::size_t>(chunk)].push_back(se);
    }
    });
    for (const auto& part : found)
        for (const SingularEdge& se : part) {
            s.edges.push_back(se);
            const auto ev = mesh.edge_vertices(se.edge);
            ++count[ev[0].uidx()];
            ++count[ev[1].uidx()];
            s.is_singular_vertex[ev[0].uidx()] = s.is_singular_vertex[ev[1].uidx()] = 1;
        }
    for (std::size_t v = 0; v < count.size(); ++v)
        if (count[v] != 0 && count[v] != 2) s.vertices.push_back(VertexHandle(static_cast<int>(v)));
    return s;
}

} // namespace HexEx
