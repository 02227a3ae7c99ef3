/// @file Untangler.cc
/// The untangling driver: neighbourhood selection, boundary constraints, the eps schedule
/// of the regularised elliptic energy and its L-BFGS minimisation.

#include "Untangler.hh"

#include "../Core/Parallel.hh"
#include "../Mesh/HexArcs.hh"
#include "../Mesh/HexMeshQuality.hh"
#include "../Mesh/HexValidity.hh"
#include "EllipticEnergy.hh"
#include "Lbfgs.hh"
#include "SurfaceProjection.hh"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

namespace HexEx {

namespace {

/// Smallest corner Jacobian det(a, b, c) of hex @p h (non-finite counts as -infinity).
double minCornerDet(const std::vector<Vec3d>& pos, const std::array<int, 8>& h) {
    double worst = std::numeric_limits<double>::infinity();
    for (const auto& f : kHexCornerFrames) {
        const Vec3d& o = pos[static_cast<std::size_t>(h[static_cast<std::size_t>(f[0])])];
        const Vec3d a = pos[static_cast<std::size_t>(h[static_cast<std::size_t>(f[1])])] - o;
        const Vec3d b = pos[static_cast<std::size_t>(h[static_cast<std::size_t>(f[2])])] - o;
        const Vec3d c = pos[static_cast<std::size_t>(h[static_cast<std::size_t>(f[3])])] - o;
        const double d = (a % b) | c;
        worst = std::isfinite(d) ? std::min(worst, d) : -std::numeric_limits<double>::infinity();
    }
    return worst;
}

/// True if hex @p h is certified valid (classifyHexValidity(): J > 0 on the whole cube).
/// The corner test first: most inverted hexes fail it, at a fraction of the cost.
bool certifiedValid(const std::vector<Vec3d>& pos, const std::array<int, 8>& h) {
    if (!(minCornerDet(pos, h) > 0)) return false;
    std::array<Vec3d, 8> p;
    for (std::size_t k = 0; k < 8; ++k) p[k] = pos[static_cast<std::size_t>(h[k])];
    return classifyHexValidity(p) == HexValidity::Valid;
}

/// Samples per axis of the energy of a hex at sample level @p level (0: the 8 corner tets).
constexpr int kSamplesPerAxis[3] = {2, 3, 5};
/// Highest sample level.
constexpr char kMaxSampleLevel = 2;

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
};

/// True if vertex @p v lies on a quad that only one hex uses (checked among the hexes at @p v).
bool onBoundary(const HexMesh& mesh, const VertexHexes& vh, int v) {
    const int* first = vh.hexes.data() + vh.offset[static_cast<std::size_t>(v)];
    const int* last = vh.hexes.data() + vh.offset[static_cast<std::size_t>(v) + 1];
    for (const int* c = first; c != last; ++c) {
        const auto& hx = mesh.hexes[static_cast<std::size_t>(*c)];
        for (std::size_t f = 0; f < 6; ++f) {
            std::array<int, 4> q;
            bool has_v = false;
            for (std::size_t i = 0; i < 4; ++i) {
                q[i] = hx[static_cast<std::size_t>(HexArcs::kHexFaces[f][i])];
                has_v = has_v || q[i] == v;
            }
            if (!has_v) continue;
            bool shared = false;
            for (const int* d = first; d != last && !shared; ++d) {
                if (d == c) continue;
                const auto& other = mesh.hexes[static_cast<std::size_t>(*d)];
                shared = std::all_of(q.begin(), q.end(),
                                     [&](int w) { return std::find(other.begin(), other.end(), w) != other.end(); });
            }
            if (!shared) return true;
        }
    }
    return false;
}

/// Two unit vectors orthogonal to the unit vector @p n and to each other.
std::array<Vec3d, 2> tangentFrame(const Vec3d& n) {
    const Vec3d helper = std::abs(n[0]) < 0.6 ? Vec3d(1, 0, 0) : Vec3d(0, 1, 0);
    const Vec3d t1 = (helper - n * (helper | n)).normalized();
    return {{t1, n % t1}};
}

/// Vertex kinds (how a vertex may move); kUnknown until classified.
constexpr char kUnknown = -1;
constexpr char kInterior = 0;  ///< anywhere (3 variables)
constexpr char kSurface = 1;   ///< on the boundary surface (2 variables)
constexpr char kCurve = 2;     ///< on a feature curve (1 variable)
constexpr char kCorner = 3;    ///< fixed: on a feature corner
constexpr char kFixed = 4;     ///< fixed: fixed boundary, no surface, or vertex of a polyhedron

/// How one free vertex moves: position = base + scale * sum_k basis[k] q[k].
struct FreeVertex {
    int vertex = -1;
    int kind = 0;  ///< 0 interior (3 dof), 1 surface (2 dof), 2 feature curve (1 dof)
    int offset = 0;  ///< first variable
    Vec3d base;
    std::array<Vec3d, 3> basis;
};

/// One minimisation problem: the free vertices of a neighbourhood and the hexes they touch.
class Problem {
public:
    /// @p level: per hex of the mesh, the sample level of its energy (kSamplesPerAxis);
    /// badElements() raises it for hexes positive at the corners but not certified valid.
    /// @p certify: a hex is bad unless certified valid (else: unless its 8 corners are positive).
    Problem(HexMesh& mesh, const UntangleOptions& opt, const SurfaceProjection* proj, const std::vector<char>& kind,
            const std::vector<int>& region_vertices, const VertexHexes& vh, const std::vector<double>& h,
            std::vector<char>& level, bool certify)
        : mesh_(mesh), opt_(opt), proj_(proj), h_(h), level_(level), certify_(certify),
          threads_(resolveThreadCount(opt.threads)) {
        if (!certify) sampled_ = 0;
        slot_.assign(mesh.vertices.size(), -1);
        for (const int v : region_vertices) {
            const char k = kind[static_cast<std::size_t>(v)];
            if (k < kInterior || k > kCurve) continue;
            FreeVertex fv;
            fv.vertex = v;
            fv.kind = k;
            slot_[static_cast<std::size_t>(v)] = static_cast<int>(free_.size());
            free_.push_back(fv);
        }
        std::vector<char> in(mesh.hexes.size(), 0);
        for (const auto& fv : free_)
            for (int k = vh.offset[static_cast<std::size_t>(fv.vertex)]; k < vh.offset[static_cast<std::size_t>(fv.vertex) + 1]; ++k)
                in[static_cast<std::size_t>(vh.hexes[static_cast<std::size_t>(k)])] = 1;
        for (std::size_t c = 0; c < in.size(); ++c)
            if (in[c]) elems_.push_back(static_cast<int>(c));
        double sum = 0;
        for (const int e : elems_) sum += h_[static_cast<std::size_t>(e)];
        scale_ = elems_.empty() ? 1.0 : sum / static_cast<double>(elems_.size());
        // Small neighbourhoods run on one thread: starting threads for every energy
        // evaluation costs more than it saves there (the result is the same either way).
        if (elems_.size() < 4096) threads_ = 1;
        rebase();
    }

    std::size_t freeVertices() const { return free_.size(); }
    /// Hex energy evaluations so far (the work budget counts these).
    double work() const { return work_; }
    /// Positions of the free vertices (for restorePositions()).
    std::vector<Vec3d> positions() const {
        std::vector<Vec3d> p;
        p.reserve(free_.size());
        for (const auto& fv : free_) p.push_back(mesh_.vertices[static_cast<std::size_t>(fv.vertex)]);
        return p;
    }
    /// Puts the free vertices back to @p p (from positions()) and resets the bases.
    void restorePositions(const std::vector<Vec3d>& p) {
        for (std::size_t i = 0; i < free_.size(); ++i) mesh_.vertices[static_cast<std::size_t>(free_[i].vertex)] = p[i];
        rebase();
    }
    /// Smallest scaled Jacobian among the elements.
    double minScaledJacobian() const {
        double worst = 1;
        for (const int e : elems_) {
            std::array<Vec3d, 8> p;
            for (std::size_t k = 0; k < 8; ++k)
                p[k] = mesh_.vertices[static_cast<std::size_t>(mesh_.hexes[static_cast<std::size_t>(e)][k])];
            worst = std::min(worst, hexScaledJacobian(p));
        }
        return worst;
    }
    /// Exponent p of the corner energies in the sum (1: the paper's energy).
    void setPower(double p) { power_ = p; }
    const std::vector<int>& elements() const { return elems_; }
    /// True if vertex @p v is a variable of this problem.
    bool isFree(int v) const { return slot_[static_cast<std::size_t>(v)] >= 0; }
    int variables() const { return n_vars_; }

    /// Projects boundary vertices onto their curve/surface and resets bases (q = 0).
    void rebase() {
        n_vars_ = 0;
        for (auto& fv : free_) {
            Vec3d& p = mesh_.vertices[static_cast<std::size_t>(fv.vertex)];
            fv.offset = n_vars_;
            if (fv.kind == 0) {
                fv.basis = {{Vec3d(1, 0, 0), Vec3d(0, 1, 0), Vec3d(0, 0, 1)}};
                n_vars_ += 3;
            } else if (fv.kind == 1) {
                Vec3d n;
                p = proj_->closestOnSurface(p, &n);
                const auto t = tangentFrame(n);
                fv.basis = {{t[0], t[1], Vec3d(0, 0, 0)}};
                n_vars_ += 2;
            } else {
                Vec3d t;
                p = proj_->closestOnFeature(p, &t);
                fv.basis = {{t, Vec3d(0, 0, 0), Vec3d(0, 0, 0)}};
                n_vars_ += 1;
            }
            fv.base = p;
        }
    }

    /// Writes the positions for variables @p q into the mesh.
    void apply(const Eigen::VectorXd& q) {
        for (const auto& fv : free_) {
            const int dof = fv.kind == 0 ? 3 : fv.kind == 1 ? 2 : 1;
            Vec3d p = fv.base;
            for (int k = 0; k < dof; ++k) p += fv.basis[static_cast<std::size_t>(k)] * (scale_ * q[fv.offset + k]);
            mesh_.vertices[static_cast<std::size_t>(fv.vertex)] = p;
        }
    }

    /// Energy at @p q for @p eps; gradient into @p grad if non-null; smallest corner
    /// D = det J into @p min_det if non-null. Per-hex values are computed in parallel and
    /// summed in hex order, so the result does not depend on the thread count.
    double energy(const Eigen::VectorXd& q, double eps, Eigen::VectorXd* grad, double* min_det) {
        apply(q);
        const std::size_t ne = elems_.size();
        // Work in units of the 8-corner energy of one hex (n^3 / 8 for n^3 samples).
        if (sampled_ == 0) work_ += static_cast<double>(ne);
        else
            for (const int c : elems_) {
                const double n = kSamplesPerAxis[static_cast<std::size_t>(level_[static_cast<std::size_t>(c)])];
                work_ += n * n * n / 8.0;
            }
        e_val_.resize(ne);
        e_det_.resize(ne);
        if (grad) e_grad_.resize(ne);
        const auto& pos = mesh_.vertices;
        parallelChunks(ne, threads_, [&](int, std::size_t b, std::size_t e) {
            for (std::size_t i = b; i < e; ++i) {
                const int c = elems_[i];
                const auto& hx = mesh_.hexes[static_cast<std::size_t>(c)];
                const double h = h_[static_cast<std::size_t>(c)];
                const char lvl = level_[static_cast<std::size_t>(c)];
                if (lvl > 0) {  // the inside of the hex: Jacobians at n^3 sample points
                    std::array<Vec3d, 8> p;
                    for (std::size_t k = 0; k < 8; ++k) p[k] = pos[static_cast<std::size_t>(hx[k])];
                    const int n = kSamplesPerAxis[static_cast<std::size_t>(lvl)];
                    double dm = 0;
                    e_val_[i] = hexSampledEnergy(p, n, h, eps, opt_.theta, power_, grad ? &e_grad_[i] : nullptr, &dm);
                    e_det_[i] = dm;
                    continue;
                }
                double sum = 0, dmin = std::numeric_limits<double>::infinity();
                std::array<Vec3d, 8> g;
                if (grad) g.fill(Vec3d(0, 0, 0));
                for (const auto& f : kHexCornerFrames) {
                    const Vec3d& o = pos[static_cast<std::size_t>(hx[static_cast<std::size_t>(f[0])])];
                    const Vec3d a = pos[static_cast<std::size_t>(hx[static_cast<std::size_t>(f[1])])] - o;
                    const Vec3d b2 = pos[static_cast<std::size_t>(hx[static_cast<std::size_t>(f[2])])] - o;
                    const Vec3d c2 = pos[static_cast<std::size_t>(hx[static_cast<std::size_t>(f[3])])] - o;
                    std::array<Vec3d, 3> cg;
                    const double ce = cornerEnergy(a, b2, c2, h, eps, opt_.theta, grad ? &cg : nullptr);
                    dmin = std::min(dmin, ((a % b2) | c2) / (h * h * h));
                    if (power_ == 1) {
                        sum += ce;
                    } else {  // sum of ce^p: the worst corners dominate
                        const double cp = power_ == 4 ? ce * ce * ce : std::pow(ce, power_ - 1);
                        sum += cp * ce;
                        if (grad)
                            for (auto& x : cg) x *= power_ * cp;
                    }
                    if (grad) {
                        for (int k = 0; k < 3; ++k) {
                            g[static_cast<std::size_t>(f[static_cast<std::size_t>(k + 1)])] += cg[static_cast<std::size_t>(k)];
                            g[static_cast<std::size_t>(f[0])] -= cg[static_cast<std::size_t>(k)];
                        }
                    }
                }
                e_val_[i] = sum;
                e_det_[i] = dmin;
                if (grad) e_grad_[i] = g;
            }
        });
        double total = 0, dmin = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < ne; ++i) {
            total += e_val_[i];
            dmin = std::min(dmin, e_det_[i]);
        }
        if (min_det) *min_det = dmin;
        if (grad) {
            vgrad_.assign(free_.size(), Vec3d(0, 0, 0));
            for (std::size_t i = 0; i < ne; ++i) {
                const auto& hx = mesh_.hexes[static_cast<std::size_t>(elems_[i])];
                for (std::size_t k = 0; k < 8; ++k) {
                    const int s = slot_[static_cast<std::size_t>(hx[k])];
                    if (s >= 0) vgrad_[static_cast<std::size_t>(s)] += e_grad_[i][k];
                }
            }
            grad->resize(n_vars_);
            for (std::size_t s = 0; s < free_.size(); ++s) {
                const auto& fv = free_[s];
                const int dof = fv.kind == 0 ? 3 : fv.kind == 1 ? 2 : 1;
                for (int k = 0; k < dof; ++k) (*grad)[fv.offset + k] = scale_ * (fv.basis[static_cast<std::size_t>(k)] | vgrad_[s]);
            }
        }
        return total;
    }

    /// Number of bad elements (at the current mesh positions): not certified valid, or with
    /// a corner Jacobian <= 0 if not certifying. Raises the sample level of the hexes
    /// positive at all 8 corners but not certified valid (their energy must see the inside).
    long badElements() {
        long n = 0;
        for (const int e : elems_) {
            const auto& hx = mesh_.hexes[static_cast<std::size_t>(e)];
            if (certify_ ? certifiedValid(mesh_.vertices, hx) : minCornerDet(mesh_.vertices, hx) > 0) continue;
            ++n;
            if (!certify_) continue;
            char& lvl = level_[static_cast<std::size_t>(e)];
            if (lvl < kMaxSampleLevel && minCornerDet(mesh_.vertices, hx) > 0) ++lvl;
            sampled_ += lvl > 0;
        }
        return n;
    }

private:
    HexMesh& mesh_;
    const UntangleOptions& opt_;
    const SurfaceProjection* proj_;
    const std::vector<double>& h_;
    std::vector<char>& level_;
    bool certify_;
    long sampled_ = 1;  ///< 0 only if no element can have a sample level > 0 (not certifying)
    int threads_;
    std::vector<int> slot_;
    std::vector<FreeVertex> free_;
    std::vector<int> elems_;
    double scale_ = 1;
    double work_ = 0;
    double power_ = 1;
    int n_vars_ = 0;
    std::vector<double> e_val_, e_det_;
    std::vector<std::array<Vec3d, 8>> e_grad_;
    std::vector<Vec3d> vgrad_;
};

/// Runs the eps schedule on @p pb; returns true if no element is inverted at the end.
/// Stops early when @p budget (hex energy evaluations, shared by all attempts) is used up.
/// @p tighten: on steps without progress, lower L-BFGS's relative decrease threshold.
bool minimise(Problem& pb, const UntangleOptions& opt, UntangleReport& rep, double& budget, bool tighten) {
    Eigen::VectorXd q = Eigen::VectorXd::Zero(pb.variables());
    double dmin = 0;
    pb.energy(q, 1.0, nullptr, &dmin);
    double eps = std::sqrt(1e-12 + 0.04 * std::min(dmin, 0.0) * std::min(dmin, 0.0));
    if (eps < 1e-6) eps = 1e-6;
    LbfgsOptions lo;
    lo.max_iterations = opt.max_lbfgs_iterations;
    lo.relative_decrease = 3e-4;
    int steps_without_progress = 0;
    long fewest_inverted = std::numeric_limits<long>::max();
    double best_dmin = -std::numeric_limits<double>::infinity();
    for (int it = 0; it < opt.max_outer_iterations; ++it) {
        q.setZero(pb.variables());
        const double e_prev = pb.energy(q, eps, nullptr, nullptr);
        auto f = [&](const Eigen::VectorXd& x, Eigen::VectorXd& gr) { return pb.energy(x, eps, &gr, nullptr); };
        const LbfgsResult r = minimizeLbfgs(f, q, lo);
        rep.lbfgs_iterations += r.iterations;
        ++rep.outer_iterations;
        const double e = pb.energy(q, eps, nullptr, &dmin);  // also leaves the positions of q in the mesh
        pb.rebase();
        const long inverted = pb.badElements();
        // Done when untangled: further steps (smaller eps) cost as much again and do not
        // raise the worst scaled Jacobian (measured on 18 perturbed cylinders: 0.026 after the
        // first untangled step, 0.022 after 5 more).
        if (inverted == 0) break;
        // Give up on this neighbourhood when the count of inverted hexes has not dropped
        // for 8 steps (a larger one may have room; a fixed boundary may admit no solution).
        // Progress: fewer inverted hexes, or a worst corner that rose by 2 % of its size
        // (with a folded neighbourhood the count often stays while the fold unwinds).
        const bool dmin_rose = dmin > best_dmin + 0.02 * std::abs(best_dmin);
        best_dmin = std::max(best_dmin, dmin);
        if (inverted < fewest_inverted || dmin_rose) {
            fewest_inverted = std::min(fewest_inverted, inverted);
            steps_without_progress = 0;
        } else {
            // No progress: L-BFGS stopped too early for the few hexes left (their energy is
            // a small part of the sum); ask for a 10 times smaller relative decrease.
            // Only in the certified phase and on heavy tangles (the pig at 96 % inverted
            // with a fixed boundary: 15 hexes left after 10 steps without, 0 after 26 with);
            // on S1 x2's first attempt, which cannot succeed, it cost 7 times the iterations.
            if (tighten) lo.relative_decrease = std::max(1e-9, 0.1 * lo.relative_decrease);
            if (++steps_without_progress >= 8) break;
        }
        if (pb.work() >= budget) {
            rep.budget_exhausted = true;
            break;
        }
        const double sigma = std::max(1.0 - e / e_prev, 0.1);
        const double mu = (1.0 - sigma) * regularizedDeterminant(dmin, eps);
        eps = dmin < mu ? 2.0 * std::sqrt(mu * (mu - dmin)) : 1e-10;
        eps = std::max(eps, 1e-12);
    }
    budget -= pb.work();
    return pb.badElements() == 0;
}

/// Quality rounds on an untangled problem @p pb: L-BFGS on the sum of the corner energies to
/// the power quality_power (the worst corners dominate) with eps so small that the energy is
/// the barrier, 5 iterations a round, quality_iterations in all; the round with the largest
/// worst scaled Jacobian of the elements and no inverted hex is kept (the energy is not the
/// scaled Jacobian, so a round can also lower it).
void improveQuality(Problem& pb, const UntangleOptions& opt, UntangleReport& rep, double& budget) {
    if (pb.freeVertices() == 0 || pb.badElements() > 0) return;
    std::vector<Vec3d> best = pb.positions();
    double best_sj = pb.minScaledJacobian();
    pb.setPower(opt.quality_power);
    const double eps_q = 1e-8;
    LbfgsOptions lq;
    lq.relative_decrease = 1e-6;
    Eigen::VectorXd q;
    for (int done = 0; done < opt.quality_iterations && pb.work() < budget;) {
        lq.max_iterations = std::min(5, opt.quality_iterations - done);
        q.setZero(pb.variables());
        auto f = [&](const Eigen::VectorXd& x, Eigen::VectorXd& gr) { return pb.energy(x, eps_q, &gr, nullptr); };
        const LbfgsResult r = minimizeLbfgs(f, q, lq);
        rep.quality_iterations += r.iterations;
        done += std::max(r.iterations, 1);
        pb.energy(q, eps_q, nullptr, nullptr);
        pb.rebase();
        if (pb.badElements() > 0) break;
        const double sj = pb.minScaledJacobian();
        if (sj > best_sj) {
            best_sj = sj;
            best = pb.positions();
        }
        if (r.iterations < lq.max_iterations) break;  // converged
    }
    pb.setPower(1);
    pb.restorePositions(best);
    budget -= pb.work();
}

} // namespace

UntangleReport untangleHexMesh(HexMesh& mesh, const UntangleOptions& options, const TriangleSurface* surface) {
    const auto t0 = std::chrono::steady_clock::now();
    UntangleReport rep;
    const std::size_t nv = mesh.vertices.size();
    for (const auto& h : mesh.hexes)
        for (const int v : h)
            if (v < 0 || static_cast<std::size_t>(v) >= nv)
                throw std::invalid_argument("untangle: a hex references vertex " + std::to_string(v) + " of " +
                                            std::to_string(nv));
    rep.hexes = static_cast<long>(mesh.hexes.size());
    const QualityStats before = computeQuality(mesh, options.threads);
    rep.inverted_before = before.inverted_hexes;
    rep.invalid_before = before.invalid_hexes;
    rep.undecided_before = before.undecided_hexes;
    rep.min_scaled_jacobian_before = before.min_scaled_jacobian;
    rep.mean_scaled_jacobian_before = before.mean_scaled_jacobian;
    auto finish = [&]() {
        const QualityStats after = computeQuality(mesh, options.threads);
        rep.inverted_after = after.inverted_hexes;
        rep.invalid_after = after.invalid_hexes;
        rep.undecided_after = after.undecided_hexes;
        rep.min_scaled_jacobian_after = after.min_scaled_jacobian;
        rep.mean_scaled_jacobian_after = after.mean_scaled_jacobian;
        rep.success = rep.invalid_after == 0 && rep.undecided_after == 0;
        rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        return rep;
    };
    // Two phases: first the classical criterion (a hex is bad if a corner Jacobian is <= 0),
    // then, from its result, the certified one (bad unless classifyHexValidity() proves it
    // valid). "inverted" from here on: the bad hexes of the current phase.
    bool certify = false;
    std::vector<int> inverted;
    std::vector<char> level(mesh.hexes.size(), 0);  // sample level of each hex's energy
    // Per hex, the results of both tests (-1: not known), kept until one of its vertices
    // moves: after an attempt only the hexes at moved vertices are tested again (a pass of
    // the certified test over all hexes of S1 x2 costs about as much as its corner phase).
    std::vector<signed char> corners_state(mesh.hexes.size(), -1), certified_state(mesh.hexes.size(), -1);
    std::vector<Vec3d> tested_positions;           // vertex positions the states belong to
    const VertexHexes* incidence = nullptr;        // set once built; until then every hex is tested
    auto cornersOk = [&](std::size_t c) {
        signed char& s = corners_state[c];
        if (s < 0) s = minCornerDet(mesh.vertices, mesh.hexes[c]) > 0 ? 1 : 0;
        return s == 1;
    };
    auto certifiedOk = [&](std::size_t c) {
        signed char& s = certified_state[c];
        if (s < 0) {
            std::array<Vec3d, 8> p;
            for (std::size_t k = 0; k < 8; ++k) p[k] = mesh.vertices[static_cast<std::size_t>(mesh.hexes[c][k])];
            s = cornersOk(c) && classifyHexValidity(p) == HexValidity::Valid ? 1 : 0;
        }
        return s == 1;
    };
    auto findBad = [&]() {
        if (incidence) {  // forget the states of the hexes at vertices that moved
            for (std::size_t v = 0; v < nv; ++v) {
                if (mesh.vertices[v] == tested_positions[v]) continue;
                tested_positions[v] = mesh.vertices[v];
                for (int k = incidence->offset[v]; k < incidence->offset[v + 1]; ++k) {
                    const std::size_t c = static_cast<std::size_t>(incidence->hexes[static_cast<std::size_t>(k)]);
                    corners_state[c] = certified_state[c] = -1;
                }
            }
        }
        inverted.clear();
        for (std::size_t c = 0; c < mesh.hexes.size(); ++c) {
            if (certify ? certifiedOk(c) : cornersOk(c)) continue;
            inverted.push_back(static_cast<int>(c));
            if (certify && level[c] == 0 && cornersOk(c)) level[c] = 1;
        }
    };
    findBad();
    if (inverted.empty()) {
        certify = true;
        findBad();
    }
    if (inverted.empty()) return finish();

    const std::vector<Vec3d> original = mesh.vertices;
    Vec3d lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const auto& p : mesh.vertices) {
        lo.minimize(p);
        hi.maximize(p);
    }
    const double diag = (hi - lo).norm() > 0 ? (hi - lo).norm() : 1.0;

    // Reference edge length per hex: its mean edge length (at least 10 % of the mesh mean).
    std::vector<double> h(mesh.hexes.size());
    double h_sum = 0;
    for (std::size_t c = 0; c < mesh.hexes.size(); ++c) {
        double s = 0;
        for (const auto& e : HexArcs::kHexEdges)
            s += (mesh.vertices[static_cast<std::size_t>(mesh.hexes[c][static_cast<std::size_t>(e[0])])] -
                  mesh.vertices[static_cast<std::size_t>(mesh.hexes[c][static_cast<std::size_t>(e[1])])]).norm();
        h[c] = s / 12.0;
        h_sum += h[c];
    }
    const double h_floor = 0.1 * h_sum / static_cast<double>(mesh.hexes.size());
    for (auto& x : h) x = std::max(x, h_floor > 0 ? h_floor : 1.0);

    // Vertex roles (0 interior, 1 boundary, 2 vertex of a polyhedron: never moves), found
    // when a vertex is first needed, so that the cost follows the neighbourhood, not the mesh.
    std::vector<char> role(nv, -1);
    for (const auto& p : mesh.polyhedra)
        for (const auto& f : p.faces)
            for (const int v : f)
                if (v >= 0 && static_cast<std::size_t>(v) < nv) role[static_cast<std::size_t>(v)] = 2;
    std::unique_ptr<SurfaceProjection> proj;
    if (options.boundary == BoundaryMode::Surface) {
        proj.reset(new SurfaceProjection(surface ? *surface : hexMeshBoundary(mesh), options.feature_angle_deg));
        if (!proj->hasSurface()) proj.reset();
    }
    const double tol = options.on_surface_tolerance * diag;
    const VertexHexes vh(nv, mesh.hexes);
    tested_positions = mesh.vertices;  // the states above belong to these positions
    incidence = &vh;
    auto roleOf = [&](int v) {
        char& r = role[static_cast<std::size_t>(v)];
        if (r < 0) r = onBoundary(mesh, vh, v) ? 1 : 0;
        return r;
    };
    // Vertex kinds, classified when a vertex first enters a neighbourhood.
    std::vector<char> kind(nv, kUnknown);
    auto classify = [&](int v) {
        char& k = kind[static_cast<std::size_t>(v)];
        if (k != kUnknown) return k;
        const char r = roleOf(v);
        if (r == 0) {
            k = kInterior;
        } else if (r == 2 || !proj) {
            k = kFixed;
        } else {
            const Vec3d p = mesh.vertices[static_cast<std::size_t>(v)];
            if (proj->distanceToCorner(p) <= tol) k = kCorner;
            else if (proj->hasFeatures() && (proj->closestOnFeature(p) - p).norm() <= tol) k = kCurve;
            else k = kSurface;
        }
        return k;
    };

    int rings = std::max(0, options.rings);
    // Heavy tangles: a neighbourhood of rings around most hexes is the whole mesh anyway,
    // and smaller attempts first only cost time.
    bool whole_mesh = static_cast<double>(inverted.size()) > options.global_fraction * static_cast<double>(mesh.hexes.size());
    // There, boundary vertices first stay where they are (sliding them on the surface while
    // the interior unfolds measured slower and less reliable: the pig at 96 % inverted ended
    // with 1 invalid hex after 60 steps, 6 s CPU, against 0 after 26 steps, 2 s CPU, held);
    // they move in a second attempt if the first one leaves invalid hexes.
    bool hold_boundary = whole_mesh && proj != nullptr;
    double budget = std::max(options.min_work, options.work_per_hex * static_cast<double>(mesh.hexes.size()));
    // The best placement seen (fewest inverted hexes in the whole mesh): an attempt that ends
    // worse than it started (possible when boundary vertices are projected back) is undone.
    std::vector<Vec3d> best = mesh.vertices;
    std::size_t best_inverted = inverted.size();
    // Ties in the count of hexes not certified valid go to the placement with fewer hexes
    // inverted at a corner.
    auto cornerInverted = [&]() {
        long n = 0;
        for (const int c : inverted) n += !cornersOk(static_cast<std::size_t>(c));
        return n;
    };
    long best_corner_inverted = cornerInverted();
    int ring_attempts = 0;
    for (;;) {
        // Region: vertices within `rings` hex rings of the inverted hexes.
        std::vector<char> in_v(nv, 0), in_h(mesh.hexes.size(), 0);
        std::vector<int> frontier;
        for (const int c : inverted) {
            in_h[static_cast<std::size_t>(c)] = 1;
            for (const int v : mesh.hexes[static_cast<std::size_t>(c)])
                if (!in_v[static_cast<std::size_t>(v)]) {
                    in_v[static_cast<std::size_t>(v)] = 1;
                    frontier.push_back(v);
                }
        }
        for (int r = 0; (whole_mesh || r < rings) && !frontier.empty(); ++r) {
            std::vector<int> next;
            for (const int v : frontier)
                for (int k = vh.offset[static_cast<std::size_t>(v)]; k < vh.offset[static_cast<std::size_t>(v) + 1]; ++k) {
                    const int c = vh.hexes[static_cast<std::size_t>(k)];
                    if (in_h[static_cast<std::size_t>(c)]) continue;
                    in_h[static_cast<std::size_t>(c)] = 1;
                    for (const int w : mesh.hexes[static_cast<std::size_t>(c)])
                        if (!in_v[static_cast<std::size_t>(w)]) {
                            in_v[static_cast<std::size_t>(w)] = 1;
                            next.push_back(w);
                        }
                }
            frontier.swap(next);
        }
        const bool whole = frontier.empty();
        std::vector<int> region;
        for (std::size_t v = 0; v < nv; ++v)
            if (in_v[v]) {
                const char k = classify(static_cast<int>(v));
                if (hold_boundary && k != kInterior) continue;
                region.push_back(static_cast<int>(v));
            }
        Problem pb(mesh, options, proj.get(), kind, region, vh, h, level, certify);
        ++rep.attempts;
        rep.rings = whole ? -1 : rings;
        rep.free_vertices = static_cast<long>(pb.freeVertices());
        if (pb.freeVertices() > 0 && minimise(pb, options, rep, budget, certify || whole_mesh) && options.quality_iterations > 0) {
            // Quality: only the free vertices of the hexes whose scaled Jacobian is below
            // quality_threshold move (far fewer than the whole neighbourhood, usually).
            std::vector<char> low(nv, 0);
            std::vector<int> low_vertices;
            for (const int e : pb.elements()) {
                std::array<Vec3d, 8> p;
                for (std::size_t k = 0; k < 8; ++k)
                    p[k] = mesh.vertices[static_cast<std::size_t>(mesh.hexes[static_cast<std::size_t>(e)][k])];
                if (hexScaledJacobian(p) >= options.quality_threshold) continue;
                for (const int v : mesh.hexes[static_cast<std::size_t>(e)])
                    if (!low[static_cast<std::size_t>(v)] && pb.isFree(v)) {
                        low[static_cast<std::size_t>(v)] = 1;
                        low_vertices.push_back(v);
                    }
            }
            std::sort(low_vertices.begin(), low_vertices.end());
            Problem pq(mesh, options, proj.get(), kind, low_vertices, vh, h, level, certify);
            improveQuality(pq, options, rep, budget);
        }
        findBad();
        const long corner_inverted = cornerInverted();
        const bool attempt_improved = inverted.size() < best_inverted;
        if (inverted.size() < best_inverted ||
            (inverted.size() == best_inverted && corner_inverted < best_corner_inverted)) {
            best = mesh.vertices;
            best_inverted = inverted.size();
            best_corner_inverted = corner_inverted;
        } else {
            mesh.vertices = best;
            findBad();
        }
        if (inverted.empty() && !certify) {  // corners done: now the inside
            certify = true;
            findBad();
            if (!inverted.empty()) {
                rings = std::max(0, options.rings);
                ring_attempts = 0;
                hold_boundary = false;
                best = mesh.vertices;
                best_inverted = inverted.size();
                best_corner_inverted = 0;
                // Few hexes left negative inside a large mesh: a bounded extra effort
                // (S1 x2: its last hex did not become valid with 30 times this).
                if (!whole_mesh)
                    budget = std::min(budget, std::max(0.1 * options.min_work, 20.0 * static_cast<double>(mesh.hexes.size())));
                if (budget > 0) continue;
            }
        }
        if (inverted.empty() || budget <= 0) break;
        if (hold_boundary) {  // the interior alone did not suffice: let the boundary move too
            hold_boundary = false;
            continue;
        }
        // Feature vertices of hexes that stay inverted may be what blocks them (e.g. a hex
        // with two edges along one straight feature curve at a vertex can only have a zero
        // Jacobian there): let them slide on the surface and retry with the same rings.
        long released = 0;
        if (options.release_features)
            for (const int c : inverted)
                for (const int v : mesh.hexes[static_cast<std::size_t>(c)]) {
                    char& k = kind[static_cast<std::size_t>(v)];
                    if (k == kCurve || k == kCorner) {
                        k = kSurface;
                        ++released;
                    }
                }
        rep.released_feature_vertices += released;
        if (released > 0) continue;
        if (whole) break;
        // Three ring sizes at most (rings, 4 rings, 16 rings); heavy tangles are untangled
        // on the whole mesh from the start (whole_mesh).
        // The certified phase starts from hexes positive at their corners and stops after
        // two sizes: a third (16 rings) cost S1 x2 40 s without removing its last hex.
        // In the certified phase of a light tangle the neighbourhood grows only if the smaller
        // one left fewer hexes not certified: on S1 x2 the 4-ring attempt after a fruitless
        // 1-ring one cost 3 times its corner phase (1,100 L-BFGS iterations at the tightened
        // threshold) and at best traded the hex for a degenerate neighbour (algorithm.md).
        if (certify && !whole_mesh && !attempt_improved) break;
        if (++ring_attempts >= (certify && !whole_mesh ? 2 : 3)) break;
        rings = rings == 0 ? 1 : 4 * rings;
    }

    // Displacements.
    double max_d = 0, sum_d = 0;
    for (std::size_t v = 0; v < nv; ++v) {
        if (mesh.vertices[v] == original[v]) continue;
        const double d = (mesh.vertices[v] - original[v]).norm();
        ++rep.moved_vertices;
        max_d = std::max(max_d, d);
        sum_d += d;
    }
    rep.max_displacement = max_d / diag;
    rep.mean_displacement = rep.moved_vertices > 0 ? sum_d / static_cast<double>(rep.moved_vertices) / diag : 0;
    finish();
    if (!inverted.empty()) {
        long stuck = 0, at_polyhedra = 0, on_features = 0, on_fixed_boundary = 0;
        for (const int c : inverted) {
            bool any_free = false, poly = false, feature = false, fixed = false;
            for (const int v : mesh.hexes[static_cast<std::size_t>(c)]) {
                const char k = classify(v);
                any_free = any_free || k == kInterior || k == kSurface || k == kCurve;
                poly = poly || roleOf(v) == 2;
                feature = feature || k == kCurve || k == kCorner;
                fixed = fixed || (k == kFixed && roleOf(v) == 1);
            }
            stuck += !any_free;
            at_polyhedra += any_free && poly;
            on_features += any_free && !poly && feature;
            on_fixed_boundary += any_free && !poly && !feature && fixed;
        }
        rep.message = std::to_string(inverted.size()) + " hexes remain invalid (" + std::to_string(rep.inverted_after) +
                      " inverted at a corner, " + std::to_string(rep.undecided_after) + " undecided)";
        const auto cause = [&](long count, const char* what) {
            if (count > 0) rep.message += "; " + std::to_string(count) + " of them " + what;
        };
        cause(stuck, "have no vertex that may move (all on a fixed boundary, feature corners or polyhedra), so the "
                     "boundary itself forces the inversion");
        cause(at_polyhedra, "share vertices with non-hex cells (polyhedra), whose vertices do not move");
        cause(on_features, "have vertices held on feature curves or corners (features were not released)");
        cause(on_fixed_boundary, "have vertices on the fixed boundary, which may not admit a foldover-free placement");
        if (stuck + at_polyhedra + on_features + on_fixed_boundary < static_cast<long>(inverted.size()))
            rep.message += "; for " + std::to_string(static_cast<long>(inverted.size()) - stuck - at_polyhedra - on_features - on_fixed_boundary) +
                           " of them the minimisation found no foldover-free placement within its limits (" +
                           std::to_string(rep.outer_iterations) + " regularisation steps" +
                           (rep.budget_exhausted ? ", work budget used up" : "") + ")";
    }
    return rep;
}

} // namespace HexEx
