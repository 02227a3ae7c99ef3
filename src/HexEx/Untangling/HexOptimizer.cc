/// @file HexOptimizer.cc
/// Max-min scaled-Jacobian optimisation of hex meshes: global L-BFGS blocks on a soft
/// minimum, then local vertex moves, every accepted step certified valid.

#include "HexOptimizer.hh"

#include "../Core/Parallel.hh"
#include "BoundaryPillowing.hh"
#include "FlatCornerSplitting.hh"
#include "FoldedBoundary.hh"
#include "SurfaceProjection.hh"
#include "../Mesh/HexArcs.hh"
#include "../Mesh/HexMeshQuality.hh"
#include "../Mesh/HexValidity.hh"
#include "Lbfgs.hh"
#include "LocalSurfaceProjection.hh"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

namespace HexEx {

namespace {

/// How a vertex may move.
enum Kind : char {
    kInterior = 0,  ///< anywhere (3 variables)
    kSurface = 1,   ///< on its patch of the surface (2 variables: tangent plane, then projection)
    kCurve = 2,     ///< on its feature curve (1 variable: tangent, then projection)
    kFixed = 3,     ///< not at all (fixed boundary, feature corner, polyhedron vertex, no surface)
};

/// Number of variables of a vertex kind.
int dofOf(char k) { return k == kInterior ? 3 : k == kSurface ? 2 : k == kCurve ? 1 : 0; }

/// Problem size (hexes of a global block) above which OptimizeOptions::handover_gain applies.
constexpr std::size_t kHandoverElements = 2000;

/// Largest exponent of the soft minimum's terms (keeps exp() finite).
constexpr double kMaxExponent = 600;

/// Scaled Jacobian det(a,b,c)/(|a||b||c|) of one corner and its gradient with respect to a,
/// b and c. Returns -2 (and no gradient) if an edge has zero length or the value is not finite.
double cornerSJWithGradient(const Vec3d& a, const Vec3d& b, const Vec3d& c, Vec3d* ga, Vec3d* gb, Vec3d* gc) {
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    const double len = la * lb * lc;
    if (!(len > 0) || !std::isfinite(len)) return -2;
    const Vec3d bc = b % c;
    const double s = (bc | a) / len;
    if (!std::isfinite(s)) return -2;
    if (ga) {
        *ga = bc / len - a * (s / (la * la));
        *gb = (c % a) / len - b * (s / (lb * lb));
        *gc = (a % b) / len - c * (s / (lc * lc));
    }
    return s;
}

/// Smallest exponent of the soft minimum's terms that is evaluated: exp(-60) < 1e-26, so the
/// corners skipped by it change the energy (at least about exp(0) from the worst corner) by
/// less than its rounding.
constexpr double kMinExponent = -60;

/// Scaled Jacobian of one corner with the intermediate values its gradient needs.
struct CornerSJ {
    double s = -2;          ///< det(a,b,c)/(|a||b||c|); -2 if an edge has zero length or not finite
    double la = 0, lb = 0, lc = 0, len = 0;  ///< edge lengths and their product
    Vec3d bc;               ///< b x c
};

/// Value part of cornerSJWithGradient() (same operations, so the same bits).
CornerSJ cornerSJ(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
    CornerSJ r;
    r.la = a.norm();
    r.lb = b.norm();
    r.lc = c.norm();
    r.len = r.la * r.lb * r.lc;
    if (!(r.len > 0) || !std::isfinite(r.len)) return r;
    r.bc = b % c;
    const double s = (r.bc | a) / r.len;
    r.s = std::isfinite(s) ? s : -2;
    return r;
}

/// Gradient part of cornerSJWithGradient() for a corner with r.s > 0.
void cornerSJGradient(const CornerSJ& r, const Vec3d& a, const Vec3d& b, const Vec3d& c, Vec3d& ga, Vec3d& gb, Vec3d& gc) {
    ga = r.bc / r.len - a * (r.s / (r.la * r.la));
    gb = (c % a) / r.len - b * (r.s / (r.lb * r.lb));
    gc = (a % b) / r.len - c * (r.s / (r.lc * r.lc));
}

/// Vertex -> hexes incidence in CSR form.
struct VertexHexes {
    std::vector<int> offset, hexes;
    VertexHexes(std::size_t n_vertices, const std::vector<std::array<int, 8>>& hx) : offset(n_vertices + 1, 0) {
        for (const auto& h : hx)
            for (const int v : h) ++offset[static_cast<std::size_t>(v) + 1];
        for (std::size_t i = 0; i < n_vertices; ++i) offset[i + 1] += offset[i];
        hexes.resize(static_cast<std::size_t>(offset.back()));
        std::vector<int> fill(offset.begin(), offset.end() - 1);
        for (std::size_t c = 0; c < hx.size(); ++c)
            for (const int v : hx[c]) hexes[static_cast<std::size_t>(fill[static_cast<std::size_t>(v)]++)] = static_cast<int>(c);
    }
    const int* begin(int v) const { return hexes.data() + offset[static_cast<std::size_t>(v)]; }
    const int* end(int v) const { return hexes.data() + offset[static_cast<std::size_t>(v) + 1]; }
};

/// Two unit vectors orthogonal to the unit vector @p n and to each other.
std::array<Vec3d, 2> tangentFrame(const Vec3d& n) {
    const Vec3d helper = std::abs(n[0]) < 0.6 ? Vec3d(1, 0, 0) : Vec3d(0, 1, 0);
    const Vec3d t1 = (helper - n * (helper | n)).normalized();
    return {{t1, n % t1}};
}

/// The optimiser's state: positions live in the mesh; per-hex SJ and validity are kept up
/// to date with every accepted step.
class Optimizer {
public:
    Optimizer(HexMesh& mesh, const OptimizeOptions& opt, OptimizeReport& rep)
        : mesh_(mesh), opt_(opt), rep_(rep), threads_(resolveThreadCount(opt.threads)), vh_(mesh.vertices.size(), mesh.hexes) {}

    /// Per-hex SJ and validity; false (with the report filled) if the input is refused.
    bool start() {
        sj_ = scaledJacobians(mesh_);
        const auto val = hexValidities(mesh_, threads_);
        valid_.resize(val.size());
        long inverted = 0;
        for (std::size_t c = 0; c < val.size(); ++c) {
            valid_[c] = val[c] == HexValidity::Valid;
            rep_.invalid_before += !valid_[c];
            inverted += sj_[c] <= 0;
        }
        if (inverted > 0) {
            rep_.success = false;
            rep_.message = std::to_string(inverted) + " hexes are inverted (a corner Jacobian <= 0); untangle the mesh "
                           "first (hexex untangle, extract --untangle or --optimize, which untangles)";
            return false;
        }
        return true;
    }

    /// Classifies the vertices (step 0 also puts boundary vertices on the surface).
    void setup(const TriangleSurface* surface) {
        const std::size_t nv = mesh_.vertices.size();
        kind_.assign(nv, kFixed);
        loc_.assign(nv, -1);
        std::vector<char> used(nv, 0), boundary(nv, 0);
        for (const auto& h : mesh_.hexes)
            for (const int v : h) used[static_cast<std::size_t>(v)] = 1;
        const TriangleSurface own = hexMeshBoundary(mesh_);
        for (const auto& t : own.triangles)
            for (const int v : t) boundary[static_cast<std::size_t>(v)] = 1;
        for (std::size_t v = 0; v < nv; ++v)
            if (used[v] && !boundary[v]) kind_[v] = kInterior;
        std::vector<char> poly(nv, 0);
        for (const auto& p : mesh_.polyhedra)
            for (const auto& f : p.faces)
                for (const int v : f)
                    if (v >= 0 && static_cast<std::size_t>(v) < nv) {
                        kind_[static_cast<std::size_t>(v)] = kFixed;
                        poly[static_cast<std::size_t>(v)] = 1;
                    }
        Vec3d lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
        for (const auto& p : mesh_.vertices) {
            lo.minimize(p);
            hi.maximize(p);
        }
        diag_ = mesh_.vertices.empty() ? 1.0 : (hi - lo).norm();
        if (!(diag_ > 0)) diag_ = 1.0;
        rep_.diagonal = mesh_.vertices.empty() ? 0.0 : (hi - lo).norm();
        if (opt_.boundary == BoundaryMode::Surface) {
            proj_.reset(new LocalSurfaceProjection(surface ? *surface : own, opt_.feature_angle_deg));
            if (proj_->triangles() == 0) {
                proj_.reset();
                rep_.message = "the surface has no triangles: boundary vertices were kept fixed";
            }
        }
        if (proj_) {
            rep_.feature_curves = static_cast<long>(proj_->featureCurves());
            rep_.feature_corners = static_cast<long>(proj_->corners());
        }
        corner_of_.assign(nv, -1);
        for (std::size_t v = 0; v < nv; ++v) {
            if (!boundary[v] || !used[v] || !proj_ || poly[v]) continue;
            const Vec3d p = mesh_.vertices[v];
            const double tol = std::max(opt_.feature_tolerance * diag_, 0.1 * shortestEdge(static_cast<int>(v)));
            double dc = 0;
            const int c = proj_->nearestCorner(p, &dc);
            if (c >= 0 && dc <= tol) {
                corner_of_[v] = c;
                continue;  // fixed at the corner (put there below)
            }
            const int s = proj_->nearestSegment(p);
            if (s >= 0) {
                int seg = s;
                const Vec3d q = proj_->projectOnCurve(p, seg);
                if ((q - p).norm() <= tol) {
                    kind_[v] = kCurve;
                    loc_[v] = seg;
                    continue;
                }
            }
            kind_[v] = kSurface;
            loc_[v] = proj_->nearestTriangle(p);
        }
        // Step 0: put the boundary vertices on their corner, curve or patch, one by one,
        // where the hexes around stay valid (positive corners; Valid hexes stay Valid).
        for (std::size_t v = 0; v < nv; ++v) {
            const bool corner = corner_of_[v] >= 0;
            if (!corner && kind_[v] != kSurface && kind_[v] != kCurve) continue;
            const Vec3d p = mesh_.vertices[v];
            int l = loc_[v];
            const Vec3d q = corner ? proj_->corner(corner_of_[v]) : project(static_cast<int>(v), p, l, nullptr);
            if (q != p && !tryPosition(static_cast<int>(v), q, -std::numeric_limits<double>::infinity())) {
                ++rep_.unprojected_vertices;
                kind_[v] = kFixed;
                corner_of_[v] = -1;
                continue;
            }
            loc_[v] = l;
        }
        for (std::size_t v = 0; v < nv; ++v) {
            rep_.surface_vertices += kind_[v] == kSurface;
            rep_.curve_vertices += kind_[v] == kCurve;
            rep_.corner_vertices += corner_of_[v] >= 0;
            rep_.free_vertices += kind_[v] != kFixed;
            rep_.fixed_vertices += used[v] && kind_[v] == kFixed;
        }
        boundary_ = boundary;
    }

    double minSJ() const { return sj_.empty() ? 0.0 : *std::min_element(sj_.begin(), sj_.end()); }
    /// True if the global phase handed over to the local phase before its block limit.
    bool handedOver() const { return !std::isnan(handover_min_); }
    /// The worst SJ when the global phase handed over (NaN if it did not).
    double handoverMin() const { return handover_min_; }

    /// Global phase: L-BFGS blocks on the soft minimum, at most max_global_blocks over all
    /// calls. With @p handover it may stop early and hand over to the local phase (see
    /// OptimizeOptions::handover_gain); handed_over_ then holds the worst SJ at that point.
    void globalPhase(bool handover) {
        double k = 20;
        int slow = 0;
        for (; blocks_done_ < opt_.max_global_blocks; ++blocks_done_) {
            const double m0 = minSJ();
            if (m0 >= opt_.target) break;
            buildProblem(m0 + opt_.window);
            if (free_.empty()) break;
            ++rep_.global_blocks;
            const std::vector<Vec3d> saved = freePositions();
            const std::vector<int> saved_loc = freeLocations();
            Eigen::VectorXd q = Eigen::VectorXd::Zero(n_vars_);
            LbfgsOptions lo;
            lo.max_iterations = opt_.block_iterations;
            lo.relative_decrease = 1e-7;
            lo.gradient_tolerance = 1e-12;
            auto f = [&](const Eigen::VectorXd& x, Eigen::VectorXd& g) { return energy(x, k, m0, &g); };
            // Boundary vertices are projected in every evaluation (the energy sees the true
            // positions; its gradient goes through the projection's tangent plane).
            project_in_apply_ = !freeze_boundary_;
            const LbfgsResult r = minimizeLbfgs(f, q, lo);
            project_in_apply_ = false;
            restore(saved, saved_loc);
            rep_.lbfgs_iterations += r.iterations;
            // Feasibility line search on the block's displacement: positions base + t (x - base),
            // boundary vertices projected, for t = 1, 1/2, ..., 1/64 until accepted.
            std::vector<double> new_sj(elems_.size());
            std::vector<char> new_valid(elems_.size());
            bool ok = false;
            double new_min = std::numeric_limits<double>::infinity(), others = new_min;
            for (double t = 1; t >= 1.0 / 64 && r.iterations > 0; t *= 0.5) {
                project_in_apply_ = true;
                apply(q * t);
                project_in_apply_ = false;
                for (std::size_t i = 0; i < free_.size(); ++i) loc_[static_cast<std::size_t>(free_[i])] = cur_loc_[i];
                ok = checkBlock(m0, new_sj, new_valid, new_min, others);
                if (ok) break;
                restore(saved, saved_loc);
            }
            if (!ok) {
                restore(saved, saved_loc);
                // Boundary vertices first: on faceted surfaces (a tet mesh's boundary) their
                // tangent-plane moves can lower the worst SJ at first order once projected;
                // then the blocks move interior vertices only (the local phase moves the
                // boundary with exact projections).
                if (!freeze_boundary_) {
                    freeze_boundary_ = true;
                    continue;
                }
                k *= 2.5;
                if (k > 5000) break;
                continue;
            }
            ++rep_.accepted_blocks;
            for (std::size_t i = 0; i < elems_.size(); ++i) {
                const std::size_t c = static_cast<std::size_t>(elems_[i]);
                sj_[c] = new_sj[i];
                valid_[c] = new_valid[i] != 0;
            }
            const double m1 = minSJ();
            if (handover && opt_.handover_gain > 0 && elems_.size() > kHandoverElements &&
                m1 - m0 < opt_.handover_gain) {
                handover_min_ = m1;
                ++blocks_done_;
                break;  // large mesh, slow block: the local phase takes over
            }
            if (m1 - m0 < 1e-4) {
                if (++slow >= 3) {
                    k *= 2.5;
                    slow = 0;
                    if (k > 5000) break;
                }
            } else {
                slow = 0;
            }
        }
    }

    /// Local phase: vertex-by-vertex max-min moves on the worst hexes.
    void localPhase() {
        int slow = 0;
        for (int pass = 0; pass < opt_.max_local_passes; ++pass) {
            const double m0 = minSJ();
            if (m0 >= opt_.target) break;
            std::vector<char> mark(mesh_.vertices.size(), 0);
            std::vector<int> cand;
            for (std::size_t c = 0; c < sj_.size(); ++c) {
                if (sj_[c] >= m0 + opt_.local_window) continue;
                for (const int v : mesh_.hexes[c])
                    if (!mark[static_cast<std::size_t>(v)] && kind_[static_cast<std::size_t>(v)] != kFixed) {
                        mark[static_cast<std::size_t>(v)] = 1;
                        cand.push_back(v);
                    }
            }
            std::sort(cand.begin(), cand.end());
            ++rep_.local_passes;
            long moves = 0;
            for (const int v : cand) moves += localMove(v);
            rep_.local_moves += moves;
            const double m1 = minSJ();
            if (moves == 0) break;
            if (m1 - m0 < 1e-5) {
                if (++slow >= 4) break;
            } else {
                slow = 0;
            }
        }
    }

    /// Distances of the boundary vertices to the surface and of feature vertices to their
    /// curve or corner.
    void measureDistances() {
        if (!proj_) return;
        double sum = 0, fsum = 0;
        long n = 0, fn = 0;
        for (std::size_t v = 0; v < mesh_.vertices.size(); ++v) {
            if (!boundary_[v]) continue;
            const Vec3d p = mesh_.vertices[v];
            const double d = proj_->distanceToSurface(p);
            rep_.max_surface_distance = std::max(rep_.max_surface_distance, d);
            sum += d;
            ++n;
            double fd = -1;
            if (corner_of_[v] >= 0) {
                fd = (proj_->corner(corner_of_[v]) - p).norm();
            } else if (kind_[v] == kCurve) {
                int l = loc_[v];
                fd = (proj_->projectOnCurve(p, l) - p).norm();
            }
            if (fd >= 0) {
                rep_.max_feature_distance = std::max(rep_.max_feature_distance, fd);
                fsum += fd;
                ++fn;
            }
        }
        rep_.mean_surface_distance = n > 0 ? sum / static_cast<double>(n) : 0.0;
        rep_.mean_feature_distance = fn > 0 ? fsum / static_cast<double>(fn) : 0.0;
    }

    /// Counts hexes that are not certified valid.
    long invalidCount() const { return static_cast<long>(std::count(valid_.begin(), valid_.end(), false)); }
    const std::vector<double>& sj() const { return sj_; }

private:
    std::array<Vec3d, 8> corners(int c) const {
        std::array<Vec3d, 8> p;
        const auto& h = mesh_.hexes[static_cast<std::size_t>(c)];
        for (std::size_t k = 0; k < 8; ++k) p[k] = mesh_.vertices[static_cast<std::size_t>(h[k])];
        return p;
    }

    double shortestEdge(int v) const {
        double best = std::numeric_limits<double>::infinity();
        for (const int* c = vh_.begin(v); c != vh_.end(v); ++c) {
            const auto& h = mesh_.hexes[static_cast<std::size_t>(*c)];
            for (const auto& e : HexArcs::kHexEdges) {
                const int a = h[static_cast<std::size_t>(e[0])], b = h[static_cast<std::size_t>(e[1])];
                if (a != v && b != v) continue;
                best = std::min(best, (mesh_.vertices[static_cast<std::size_t>(a)] - mesh_.vertices[static_cast<std::size_t>(b)]).norm());
            }
        }
        return std::isfinite(best) ? best : 0.0;
    }

    /// Projection of @p p for vertex @p v by its kind (location @p l updated); the normal
    /// (surface) or tangent (curve) goes to @p dir.
    Vec3d project(int v, const Vec3d& p, int& l, Vec3d* dir) const {
        const char k = kind_[static_cast<std::size_t>(v)];
        if (k == kSurface) return proj_->projectOnPatch(p, l, dir);
        if (k == kCurve) return proj_->projectOnCurve(p, l, dir);
        return p;
    }

    /// Moves vertex @p v to @p q if every hex at it keeps positive corners, Valid hexes stay
    /// Valid and their smallest SJ exceeds @p floor; updates sj_/valid_. True if moved.
    bool tryPosition(int v, const Vec3d& q, double floor) {
        Vec3d& pos = mesh_.vertices[static_cast<std::size_t>(v)];
        const Vec3d old = pos;
        pos = q;
        std::array<double, 64> s{};
        std::size_t n = 0;
        bool ok = true;
        for (const int* c = vh_.begin(v); c != vh_.end(v) && ok; ++c, ++n) {
            const double x = hexScaledJacobian(corners(*c));
            if (n < s.size()) s[n] = x;
            ok = x > 0 && x > floor;
        }
        n = 0;
        std::array<char, 64> val{};
        for (const int* c = vh_.begin(v); c != vh_.end(v) && ok; ++c, ++n) {
            const bool good = classifyHexValidity(corners(*c)) == HexValidity::Valid;
            if (n < val.size()) val[n] = good;
            ok = good || !valid_[static_cast<std::size_t>(*c)];
        }
        if (!ok || vh_.end(v) - vh_.begin(v) > 64) {
            if (ok) {  // more than 64 hexes at one vertex: recompute
                for (const int* c = vh_.begin(v); c != vh_.end(v); ++c) {
                    const auto p = corners(*c);
                    sj_[static_cast<std::size_t>(*c)] = hexScaledJacobian(p);
                    valid_[static_cast<std::size_t>(*c)] = classifyHexValidity(p) == HexValidity::Valid;
                }
                return true;
            }
            pos = old;
            return false;
        }
        n = 0;
        for (const int* c = vh_.begin(v); c != vh_.end(v); ++c, ++n) {
            sj_[static_cast<std::size_t>(*c)] = s[n];
            valid_[static_cast<std::size_t>(*c)] = val[n] != 0;
        }
        return true;
    }

    /// One max-min move of vertex @p v; true if accepted.
    bool localMove(int v) {
        const char k = kind_[static_cast<std::size_t>(v)];
        double m_old = std::numeric_limits<double>::infinity();
        for (const int* c = vh_.begin(v); c != vh_.end(v); ++c) m_old = std::min(m_old, sj_[static_cast<std::size_t>(*c)]);
        // Gradient of the soft minimum of the corners at the hexes around v, w.r.t. v.
        const double kk = 100;
        Vec3d g(0, 0, 0);
        for (const int* c = vh_.begin(v); c != vh_.end(v); ++c) {
            const auto p = corners(*c);
            const auto& h = mesh_.hexes[static_cast<std::size_t>(*c)];
            for (const auto& f : kHexCornerFrames) {
                int which = -1;
                for (int i = 0; i < 4; ++i)
                    if (h[static_cast<std::size_t>(f[static_cast<std::size_t>(i)])] == v) which = i;
                if (which < 0) continue;
                const Vec3d& o = p[static_cast<std::size_t>(f[0])];
                Vec3d ga, gb, gc;
                const double s = cornerSJWithGradient(p[static_cast<std::size_t>(f[1])] - o, p[static_cast<std::size_t>(f[2])] - o,
                                                      p[static_cast<std::size_t>(f[3])] - o, &ga, &gb, &gc);
                if (s < -1.5) continue;
                const double w = std::exp(std::min(kk * (m_old - s), kMaxExponent));
                const Vec3d ds = which == 0 ? -(ga + gb + gc) : which == 1 ? ga : which == 2 ? gb : gc;
                g += ds * w;  // ascent direction of the soft minimum
            }
        }
        Vec3d d = g;
        const Vec3d p0 = mesh_.vertices[static_cast<std::size_t>(v)];
        int l0 = loc_[static_cast<std::size_t>(v)];
        if (k != kInterior) {
            Vec3d dir;
            int l = l0;
            project(v, p0, l, &dir);
            d = k == kSurface ? d - dir * (d | dir) : dir * (d | dir);
        }
        const double len = d.norm();
        if (!(len > 0) || !std::isfinite(len)) return false;
        d /= len;
        const double h = shortestEdge(v);
        for (double t = 0.25 * h; t > h * 1e-4; t *= 0.5) {
            int l = l0;
            const Vec3d q = project(v, p0 + d * t, l, nullptr);
            if (q == p0) continue;
            if (tryPosition(v, q, m_old + 1e-12)) {
                loc_[static_cast<std::size_t>(v)] = l;
                return true;
            }
        }
        return false;
    }

    /// Free vertices (vertices of hexes with SJ below @p below that may move) and the hexes
    /// they touch; variables and their bases.
    void buildProblem(double below) {
        const std::size_t nv = mesh_.vertices.size();
        std::vector<char> mark(nv, 0);
        free_.clear();
        for (std::size_t c = 0; c < sj_.size(); ++c) {
            if (sj_[c] >= below) continue;
            for (const int v : mesh_.hexes[c])
                if (!mark[static_cast<std::size_t>(v)] && kind_[static_cast<std::size_t>(v)] != kFixed &&
                    (!freeze_boundary_ || kind_[static_cast<std::size_t>(v)] == kInterior)) {
                    mark[static_cast<std::size_t>(v)] = 1;
                    free_.push_back(v);
                }
        }
        std::sort(free_.begin(), free_.end());
        slot_.assign(nv, -1);
        std::vector<char> in(mesh_.hexes.size(), 0);
        elems_.clear();
        for (std::size_t i = 0; i < free_.size(); ++i) {
            slot_[static_cast<std::size_t>(free_[i])] = static_cast<int>(i);
            for (const int* c = vh_.begin(free_[i]); c != vh_.end(free_[i]); ++c) in[static_cast<std::size_t>(*c)] = 1;
        }
        for (std::size_t c = 0; c < in.size(); ++c)
            if (in[c]) elems_.push_back(static_cast<int>(c));
        double sum = 0;
        long ne = 0;
        for (const int e : elems_)
            for (const auto& ed : HexArcs::kHexEdges) {
                const auto& h = mesh_.hexes[static_cast<std::size_t>(e)];
                sum += (mesh_.vertices[static_cast<std::size_t>(h[static_cast<std::size_t>(ed[0])])] -
                        mesh_.vertices[static_cast<std::size_t>(h[static_cast<std::size_t>(ed[1])])]).norm();
                ++ne;
            }
        scale_ = ne > 0 && sum > 0 ? sum / static_cast<double>(ne) : 1.0;
        base_.resize(free_.size());
        basis_.resize(free_.size());
        offset_.resize(free_.size());
        n_vars_ = 0;
        for (std::size_t i = 0; i < free_.size(); ++i) {
            const int v = free_[i];
            const char k = kind_[static_cast<std::size_t>(v)];
            base_[i] = mesh_.vertices[static_cast<std::size_t>(v)];
            offset_[i] = n_vars_;
            n_vars_ += dofOf(k);
            if (k == kInterior) {
                basis_[i] = {{Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, 0, 1)}};
            } else {
                Vec3d dir;
                int l = loc_[static_cast<std::size_t>(v)];
                project(v, base_[i], l, &dir);
                if (k == kSurface) {
                    const auto t = tangentFrame(dir);
                    basis_[i] = {{t[0], t[1], Vec3d(0, 0, 0)}};
                } else {
                    basis_[i] = {{dir, Vec3d(0, 0, 0), Vec3d(0, 0, 0)}};
                }
            }
        }
    }

    /// After a block: SJ and certified validity of the elements into @p new_sj and
    /// @p new_valid; true if all keep positive corners, Valid ones stay Valid and the worst SJ
    /// of the mesh is still >= @p m0 (@p new_min: elements' minimum, @p others: the rest's).
    bool checkBlock(double m0, std::vector<double>& new_sj, std::vector<char>& new_valid, double& new_min, double& others) {
        const int th = elems_.size() < 2048 ? 1 : threads_;
        parallelChunks(elems_.size(), th, [&](int, std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e; ++i) new_sj[i] = hexScaledJacobian(corners(elems_[i]));
        });
        new_min = std::numeric_limits<double>::infinity();
        for (const double x : new_sj) new_min = std::min(new_min, x);
        if (!(new_min > 0) || new_min < m0) return false;
        others = std::numeric_limits<double>::infinity();
        std::vector<char> in(sj_.size(), 0);
        for (const int e : elems_) in[static_cast<std::size_t>(e)] = 1;
        for (std::size_t c = 0; c < sj_.size(); ++c)
            if (!in[c]) others = std::min(others, sj_[c]);
        if (std::min(new_min, others) < m0) return false;
        // A block that does not raise the worst SJ must not lower the mean of the hexes it
        // moved either (the soft minimum alone would trade the mean for nothing).
        if (std::min(new_min, others) <= m0 + 1e-9) {
            double old_sum = 0, new_sum = 0;
            for (std::size_t i = 0; i < elems_.size(); ++i) {
                old_sum += sj_[static_cast<std::size_t>(elems_[i])];
                new_sum += new_sj[i];
            }
            if (new_sum < old_sum) return false;
        }
        // Certified validity: threads_ chunks, each hex's test is independent.
        parallelChunks(elems_.size(), th, [&](int, std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e; ++i) new_valid[i] = classifyHexValidity(corners(elems_[i])) == HexValidity::Valid;
        });
        for (std::size_t i = 0; i < elems_.size(); ++i)
            if (valid_[static_cast<std::size_t>(elems_[i])] && !new_valid[i]) return false;
        return true;
    }

    std::vector<Vec3d> freePositions() const {
        std::vector<Vec3d> p;
        for (const int v : free_) p.push_back(mesh_.vertices[static_cast<std::size_t>(v)]);
        return p;
    }
    std::vector<int> freeLocations() const {
        std::vector<int> l;
        for (const int v : free_) l.push_back(loc_[static_cast<std::size_t>(v)]);
        return l;
    }
    void restore(const std::vector<Vec3d>& p, const std::vector<int>& l) {
        for (std::size_t i = 0; i < free_.size(); ++i) {
            mesh_.vertices[static_cast<std::size_t>(free_[i])] = p[i];
            loc_[static_cast<std::size_t>(free_[i])] = l[i];
        }
    }

    /// Positions for variables @p q: base + basis q, boundary vertices projected onto their
    /// patch or curve (walking from their location at the start of the block); the
    /// locations reached go to cur_loc_.
    void apply(const Eigen::VectorXd& q) {
        cur_loc_.resize(free_.size());
        cur_dir_.resize(free_.size());
        parallelChunks(free_.size(), free_.size() < 4096 ? 1 : threads_, [&](int, std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e; ++i) {
                const int v = free_[i];
                const int dof = dofOf(kind_[static_cast<std::size_t>(v)]);
                Vec3d p = base_[i];
                for (int k = 0; k < dof; ++k) p += basis_[i][static_cast<std::size_t>(k)] * (scale_ * q[offset_[i] + k]);
                int l = loc_[static_cast<std::size_t>(v)];
                if (dof < 3 && project_in_apply_) p = project(v, p, l, &cur_dir_[i]);
                cur_loc_[i] = l;
                mesh_.vertices[static_cast<std::size_t>(v)] = p;
            }
        });
    }

    /// Soft minimum sum exp(k (m0 - SJ_c)) over the corners of the elements at variables
    /// @p q (infinity if a corner Jacobian is <= 0); gradient into @p grad. Per-hex values
    /// are computed in parallel and summed in hex order (thread-count independent).
    double energy(const Eigen::VectorXd& q, double k, double m0, Eigen::VectorXd* grad) {
        apply(q);
        const std::size_t ne = elems_.size();
        e_val_.resize(ne);
        if (grad) e_grad_.resize(ne);
        const auto& pos = mesh_.vertices;
        const double skip_above = m0 - kMinExponent / k;  // corners above this SJ are skipped
        const double skip2 = skip_above > 0 ? skip_above * skip_above : std::numeric_limits<double>::infinity();
        parallelChunks(ne, ne < 2048 ? 1 : threads_, [&](int, std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e; ++i) {
                const auto& hx = mesh_.hexes[static_cast<std::size_t>(elems_[i])];
                double sum = 0;
                std::array<Vec3d, 8> g;
                g.fill(Vec3d(0, 0, 0));
                for (const auto& f : kHexCornerFrames) {
                    const Vec3d& o = pos[static_cast<std::size_t>(hx[static_cast<std::size_t>(f[0])])];
                    const Vec3d a = pos[static_cast<std::size_t>(hx[static_cast<std::size_t>(f[1])])] - o;
                    const Vec3d b2 = pos[static_cast<std::size_t>(hx[static_cast<std::size_t>(f[2])])] - o;
                    const Vec3d c2 = pos[static_cast<std::size_t>(hx[static_cast<std::size_t>(f[3])])] - o;
                    // Quick skip without square roots: SJ > skip_above <=> det^2 > skip_above^2
                    // |a|^2 |b|^2 |c|^2 (det > 0); the term is then below exp(kMinExponent).
                    const double det = (b2 % c2) | a;
                    if (det > 0 && det * det > skip2 * (a.sqrnorm() * b2.sqrnorm() * c2.sqrnorm())) continue;
                    const CornerSJ cs = cornerSJ(a, b2, c2);
                    const double s = cs.s;
                    if (!(s > 0)) {
                        sum = std::numeric_limits<double>::infinity();
                        break;
                    }
                    // Terms below exp(kMinExponent) (relative to the worst corner's, about 1)
                    // change neither the sum nor the gradient in double precision: skipped,
                    // gradient not computed (most corners once k has grown).
                    const double x = k * (m0 - s);
                    if (x < kMinExponent) continue;
                    const double w = std::exp(std::min(x, kMaxExponent));
                    sum += w;
                    Vec3d ga, gb, gc;
                    cornerSJGradient(cs, a, b2, c2, ga, gb, gc);
                    const double dw = -k * w;
                    g[static_cast<std::size_t>(f[1])] += ga * dw;
                    g[static_cast<std::size_t>(f[2])] += gb * dw;
                    g[static_cast<std::size_t>(f[3])] += gc * dw;
                    g[static_cast<std::size_t>(f[0])] -= (ga + gb + gc) * dw;
                }
                e_val_[i] = sum;
                if (grad) e_grad_[i] = g;
            }
        });
        double total = 0;
        for (std::size_t i = 0; i < ne; ++i) total += e_val_[i];
        if (!std::isfinite(total)) return std::numeric_limits<double>::infinity();
        if (grad) {
            vgrad_.assign(free_.size(), Vec3d(0, 0, 0));
            for (std::size_t i = 0; i < ne; ++i) {
                const auto& hx = mesh_.hexes[static_cast<std::size_t>(elems_[i])];
                for (std::size_t c = 0; c < 8; ++c) {
                    const int s = slot_[static_cast<std::size_t>(hx[c])];
                    if (s >= 0) vgrad_[static_cast<std::size_t>(s)] += e_grad_[i][c];
                }
            }
            grad->resize(n_vars_);
            for (std::size_t i = 0; i < free_.size(); ++i) {
                const int dof = dofOf(kind_[static_cast<std::size_t>(free_[i])]);
                Vec3d g = vgrad_[i];
                if (project_in_apply_ && dof == 2) g -= cur_dir_[i] * (cur_dir_[i] | g);  // through the projection
                if (project_in_apply_ && dof == 1) g = cur_dir_[i] * (cur_dir_[i] | g);
                for (int d = 0; d < dof; ++d) (*grad)[offset_[i] + d] = scale_ * (basis_[i][static_cast<std::size_t>(d)] | g);
            }
        }
        return total;
    }

    HexMesh& mesh_;
    const OptimizeOptions& opt_;
    OptimizeReport& rep_;
    int threads_;
    VertexHexes vh_;
    std::unique_ptr<LocalSurfaceProjection> proj_;
    std::vector<char> kind_;
    std::vector<int> loc_, corner_of_;
    std::vector<char> boundary_;
    std::vector<double> sj_;
    int blocks_done_ = 0;  ///< global blocks run so far (all calls of globalPhase())
    double handover_min_ = std::numeric_limits<double>::quiet_NaN();  ///< see handoverMin()
    std::vector<bool> valid_;
    double diag_ = 1;
    // Global phase problem.
    std::vector<int> free_, slot_, elems_, offset_, cur_loc_;
    std::vector<Vec3d> cur_dir_;
    bool project_in_apply_ = false;
    bool freeze_boundary_ = false;
    std::vector<Vec3d> base_;
    std::vector<std::array<Vec3d, 3>> basis_;
    double scale_ = 1;
    int n_vars_ = 0;
    std::vector<double> e_val_;
    std::vector<std::array<Vec3d, 8>> e_grad_;
    std::vector<Vec3d> vgrad_;
};

/// Mean of @p v (0 if empty).
double mean(const std::vector<double>& v) {
    double s = 0;
    for (const double x : v) s += x;
    return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

} // namespace

std::vector<long> scaledJacobianHistogram(const std::vector<double>& sj) {
    std::vector<long> h(20, 0);
    for (const double s : sj) {
        const double x = std::isfinite(s) ? std::clamp(s, -1.0, 1.0) : -1.0;
        const int bin = std::min(19, static_cast<int>(std::floor((x + 1.0) * 10.0)));
        ++h[static_cast<std::size_t>(std::max(0, bin))];
    }
    return h;
}

OptimizeReport optimizeHexMesh(HexMesh& mesh, const OptimizeOptions& options, const TriangleSurface* surface) {
    const auto t0 = std::chrono::steady_clock::now();
    OptimizeReport rep;
    const std::size_t nv = mesh.vertices.size();
    for (const auto& h : mesh.hexes)
        for (const int v : h)
            if (v < 0 || static_cast<std::size_t>(v) >= nv)
                throw std::invalid_argument("optimize: a hex references vertex " + std::to_string(v) + " of " +
                                            std::to_string(nv));
    std::vector<double> sj_input;
    long invalid_input = 0;
    if (options.pillow && !mesh.hexes.empty()) {
        sj_input = scaledJacobians(mesh);
        if (*std::min_element(sj_input.begin(), sj_input.end()) > 0) {
            const std::vector<HexValidity> validity = hexValidities(mesh, options.threads);  // of the input
            for (const auto v : validity) invalid_input += v != HexValidity::Valid;
            PillowOptions po;
            po.depth = options.pillow_depth;
            po.skip_patch_angle_deg = options.pillow_skip_patch_angle_deg;
            po.threads = options.threads;
            po.allow_invalid = true;  // untangled below; undone if that fails
            const HexMesh input = mesh;
            const long nh_input = static_cast<long>(mesh.hexes.size());
            UntangleOptions uo;
            uo.boundary = options.boundary;
            uo.threads = options.threads;
            uo.feature_angle_deg = options.feature_angle_deg;
            // Untangles what the layer left not certified valid; false (and the input back) if that fails.
            auto untangleLayer = [&](long invalid_layer) {
                if (invalid_layer == 0) return true;
                const UntangleReport ur = untangleHexMesh(mesh, uo, surface);
                if (ur.inverted_after == 0 && ur.invalid_after + ur.undecided_after <= invalid_input) return true;
                rep.message = "pillowing undone: " + std::to_string(ur.invalid_after + ur.undecided_after) +
                              " hexes were still not certified valid after untangling the layer";
                mesh = input;
                rep.pillowed_hexes = rep.pillow_vertices = rep.trimmed_hexes = 0;
                return false;
            };
            // A flap of hexes outside the surface (a fold of the map, FoldedBoundary.hh) that
            // holds hexes not certified valid is removed; the whole boundary then gets the
            // layer, and the vertices that the removal exposed go onto the surface (the layer
            // takes up the move, the old hexes stay as they were).
            std::vector<int> exposed;
            if (invalid_input > 0 && surface != nullptr && options.boundary == BoundaryMode::Surface &&
                mesh.polyhedra.empty()) {
                std::vector<int> seeds;
                for (std::size_t c = 0; c < validity.size(); ++c)
                    if (validity[c] != HexValidity::Valid) seeds.push_back(static_cast<int>(c));
                const std::vector<int> flap = hexesOutsideSurface(mesh, *surface, seeds);
                if (!flap.empty() && flap.size() < mesh.hexes.size()) {
                    exposed = removeHexes(mesh, flap);
                    rep.trimmed_hexes = static_cast<long>(flap.size());
                    po.skip_patch_angle_deg = 180;
                }
            }
            PillowReport pr = pillowBoundary(mesh, po);
            if (pr.success && !exposed.empty()) {
                // Boundary vertices keep their indices in the layered mesh.
                const SurfaceProjection proj(*surface, options.feature_angle_deg);
                if (proj.hasSurface()) {
                    for (const int v : exposed) {
                        Vec3d& p = mesh.vertices[static_cast<std::size_t>(v)];
                        p = proj.closestOnSurface(p);
                    }
                    pr.invalid_after = 0;
                    for (const auto v : hexValidities(mesh, options.threads)) pr.invalid_after += v != HexValidity::Valid;
                }
            }
            if (!pr.success) {
                rep.message = pr.message;
                if (rep.trimmed_hexes > 0) {
                    mesh = input;
                    rep.trimmed_hexes = 0;
                }
            } else {
                rep.pillowed_hexes = pr.hexes_added;
                rep.pillow_vertices = pr.vertices_added;
                rep.pillow_invalid = pr.invalid_after;
                if (untangleLayer(pr.invalid_after) && pr.skipped_patches > 0 && options.pillow_second_layer) {
                    // The skipped patches (now with their strips) get a layer too, on the
                    // untangled mesh; undone alone if it cannot be made valid.
                    const HexMesh first = mesh;
                    PillowOptions p2 = po;
                    p2.layered_from = nh_input;
                    const PillowReport pr2 = pillowBoundary(mesh, p2);
                    if (pr2.success && pr2.hexes_added > 0) {
                        const long before_second = rep.pillowed_hexes, vbefore = rep.pillow_vertices;
                        rep.pillowed_hexes += pr2.hexes_added;
                        rep.pillow_vertices += pr2.vertices_added;
                        rep.pillow_invalid += pr2.invalid_after;
                        long invalid_first = 0;
                        for (const auto v : hexValidities(first, options.threads)) invalid_first += v != HexValidity::Valid;
                        if (pr2.invalid_after > invalid_first) {
                            const UntangleReport ur = untangleHexMesh(mesh, uo, surface);
                            if (ur.inverted_after > 0 || ur.invalid_after + ur.undecided_after > invalid_first) {
                                mesh = first;
                                rep.pillowed_hexes = before_second;
                                rep.pillow_vertices = vbefore;
                                rep.message = "second pillow layer undone: its hexes could not all be made certified valid";
                            }
                        }
                    }
                }
            }
            if (options.pillow_flat_corners && rep.pillowed_hexes > 0) {
                FlatCornerOptions fo;
                fo.feature_angle_deg = options.feature_angle_deg;
                const FlatCornerReport fr = splitFlatFeatureCorners(mesh, fo);
                rep.pillowed_hexes += fr.hexes_added;
                rep.pillow_vertices += fr.vertices_added;
            }
        } else {
            sj_input.clear();  // refused below by Optimizer::start()
        }
    }
    rep.hexes = static_cast<long>(mesh.hexes.size());
    Optimizer opt(mesh, options, rep);
    const bool accepted = opt.start();
    rep.min_scaled_jacobian_before = opt.minSJ();
    rep.mean_scaled_jacobian_before = mean(opt.sj());
    rep.histogram_before = scaledJacobianHistogram(opt.sj());
    rep.min_scaled_jacobian_pillowed = opt.minSJ();
    if (!sj_input.empty()) {  // "before" is the input, not the pillowed mesh
        rep.min_scaled_jacobian_before = *std::min_element(sj_input.begin(), sj_input.end());
        rep.mean_scaled_jacobian_before = mean(sj_input);
        rep.histogram_before = scaledJacobianHistogram(sj_input);
        rep.invalid_before = invalid_input;
    }
    auto finish = [&]() {
        rep.min_scaled_jacobian_after = opt.minSJ();
        rep.mean_scaled_jacobian_after = mean(opt.sj());
        rep.histogram_after = scaledJacobianHistogram(opt.sj());
        rep.invalid_after = opt.invalidCount();
        rep.reached_target = !mesh.hexes.empty() && rep.min_scaled_jacobian_after >= options.target;
        rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return rep;
    };
    if (!accepted || mesh.hexes.empty()) {
        rep.min_scaled_jacobian_projected = rep.min_scaled_jacobian_before;
        return finish();
    }
    opt.setup(surface);
    rep.min_scaled_jacobian_projected = opt.minSJ();
    opt.globalPhase(true);
    opt.localPhase();
    // If the local phase could not go on where the global phase handed over (its vertex
    // moves gain nothing, e.g. the worst hex needs several vertices to move together), the
    // global phase resumes with the blocks left, then the local phase again.
    if (opt.handedOver() && opt.minSJ() < opt.handoverMin() + options.handover_gain) {
        opt.globalPhase(false);
        opt.localPhase();
    }
    opt.measureDistances();
    return finish();
}

} // namespace HexEx
