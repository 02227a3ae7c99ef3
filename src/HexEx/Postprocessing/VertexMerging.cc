#include "VertexMerging.hh"

#include "../Core/Parallel.hh"
#include "../Core/Prefetch.hh"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <memory>

namespace HexEx {

namespace {

/// Distinct positions (the darts of one h-vertex agree up to rounding in their tets).
std::vector<Vec3d> distinctPositions(std::vector<Vec3d> p, double tol) {
    // Common case: every dart of the class computed the very same position.
    if (std::all_of(p.begin(), p.end(), [&](const Vec3d& x) { return x == p.front(); })) {
        p.resize(std::min<std::size_t>(p.size(), 1));
        return p;
    }
    std::sort(p.begin(), p.end(), [](const Vec3d& a, const Vec3d& b) {
        return a[0] != b[0] ? a[0] < b[0] : a[1] != b[1] ? a[1] < b[1] : a[2] < b[2];
    });
    std::vector<Vec3d> out;
    for (const auto& x : p) {
        bool dup = false;
        for (auto it = out.rbegin(); it != out.rend() && x[0] - (*it)[0] <= tol; ++it)
            if ((x - *it).norm() <= tol) { dup = true; break; }
        if (!dup) out.push_back(x);
    }
    return out;
}

/// The position (up to @p tol) that more than half of @p p share, if there is one and
/// @p p holds more than one position.
bool majorityPosition(const std::vector<Vec3d>& p, double tol, Vec3d& out) {
    const std::vector<Vec3d> dist = distinctPositions(p, tol);
    if (dist.size() < 2) return false;
    for (const Vec3d& x : dist) {
        std::size_t n = 0;
        for (const Vec3d& y : p) n += (x - y).norm() <= tol ? 1 : 0;
        if (2 * n > p.size()) {
            out = x;
            return true;
        }
    }
    return false;
}

/// Moves the entry of @p v within @p tol of @p x to the front (appends @p x if none is).
void moveToFront(std::vector<Vec3d>& v, const Vec3d& x, double tol) {
    auto it = std::find_if(v.begin(), v.end(), [&](const Vec3d& y) { return (x - y).norm() <= tol; });
    if (it == v.end()) v.insert(v.begin(), x);
    else std::rotate(v.begin(), it, it + 1);
}

/// Distance of @p x to the triangle @p a, @p b, @p c (closest point by regions).
double triangleDistance(const Vec3d& x, const Vec3d& a, const Vec3d& b, const Vec3d& c) {
    const Vec3d ab = b - a, ac = c - a, ax = x - a;
    const double d1 = ab | ax, d2 = ac | ax;
    if (d1 <= 0 && d2 <= 0) return ax.norm();
    const Vec3d bx = x - b;
    const double d3 = ab | bx, d4 = ac | bx;
    if (d3 >= 0 && d4 <= d3) return bx.norm();
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return (x - (a + ab * (d1 / (d1 - d3)))).norm();
    const Vec3d cx = x - c;
    const double d5 = ab | cx, d6 = ac | cx;
    if (d6 >= 0 && d5 <= d6) return cx.norm();
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return (x - (a + ac * (d2 / (d2 - d6)))).norm();
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) return (x - (b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))))).norm();
    const double den = 1.0 / (va + vb + vc);
    return (x - (a + ab * (vb * den) + ac * (vc * den))).norm();
}

/// Groups the indices d with label[d] >= 0 by label (counting sort: ascending within a
/// label): label l holds idx[off[l] .. off[l + 1]). The counts and the filling run in
/// parallel chunks of @p label, each with its own count per label that becomes its first
/// slot per label (chunk after chunk within a label): the same groups for any chunk count.
/// idx is not zeroed first (every slot is written).
void groupByClass(const std::vector<int>& label, std::size_t nc, int threads, std::vector<int>& off, std::unique_ptr<int[]>& idx) {
    const std::size_t n = label.size();
    const int chunks = n >= 65536 ? std::max(1, std::min(threads, 4)) : 1;
    std::vector<std::vector<int>> next(static_cast<std::size_t>(chunks));  // per chunk: count, then next slot, per label
    parallelChunks(n, chunks, [&](int k, std::size_t b, std::size_t e) {
        std::vector<int>& c = next[static_cast<std::size_t>(k)];
        c.assign(nc, 0);
        for (std::size_t d = b; d < e; ++d)
            if (label[d] >= 0) ++c[static_cast<std::size_t>(label[d])];
    });
    // Offsets: per range of labels its total, then the ranges' starts, then the slots.
    const int ranges = nc >= 65536 ? chunks : 1;
    std::vector<long> rangeStart(static_cast<std::size_t>(ranges) + 1, 0);
    parallelChunks(nc, ranges, [&](int r, std::size_t b, std::size_t e) {
        long t = 0;
        for (std::size_t l = b; l < e; ++l)
            for (const std::vector<int>& c : next) t += c[l];
        rangeStart[static_cast<std::size_t>(r) + 1] = t;
    });
    for (std::size_t r = 0; r < static_cast<std::size_t>(ranges); ++r) rangeStart[r + 1] += rangeStart[r];
    off.resize(nc + 1);
    off[nc] = static_cast<int>(rangeStart.back());
    parallelChunks(nc, ranges, [&](int r, std::size_t b, std::size_t e) {
        int at = static_cast<int>(rangeStart[static_cast<std::size_t>(r)]);
        for (std::size_t l = b; l < e; ++l) {
            off[l] = at;
            for (std::vector<int>& c : next) {
                const int m = c[l];
                c[l] = at;
                at += m;
            }
        }
    });
    idx.reset(new int[static_cast<std::size_t>(off[nc])]);
    parallelChunks(n, chunks, [&](int k, std::size_t b, std::size_t e) {
        int* const slot = next[static_cast<std::size_t>(k)].data();
        for (std::size_t d = b; d < e; ++d)
            if (label[d] >= 0) idx[static_cast<std::size_t>(slot[label[d]]++)] = static_cast<int>(d);
    });
}

/// How many classes ahead mergedVertexPositions() asks for the darts' placed points.
constexpr std::size_t kPointsAhead = 16;
/// How many classes ahead it asks for their positions and boundary faces.
constexpr std::size_t kPositionsAhead = 8;

/// Asks the CPU to load the placed-point index of every dart of class @p l early.
void prefetchPoints(const int* idx, const std::vector<int>& off, const DartPlacement& darts, std::size_t l) {
    for (int k = off[l]; k < off[l + 1]; ++k) prefetchKept(&darts.point[static_cast<std::size_t>(idx[k])]);
}

/// Asks the CPU to load the position and boundary faces of every dart of class @p l early.
void prefetchPositions(const int* idx, const std::vector<int>& off, const DartPlacement& darts, std::size_t l) {
    for (int k = off[l]; k < off[l + 1]; ++k) {
        const auto q = static_cast<std::size_t>(darts.point[static_cast<std::size_t>(idx[k])]);
        prefetchKept(&darts.position[q]);
        prefetchKept(&darts.boundary_hf[q]);
    }
}

/// Centroid of @p p (used only to regularize the boundary least-squares problem).
Vec3d centroid(const std::vector<Vec3d>& p) {
    Vec3d c(0, 0, 0);
    for (const auto& x : p) c += x;
    return c / static_cast<double>(p.size());
}

} // namespace

std::vector<Vec3d> mergedVertexPositions(const TetMesh& mesh, const std::vector<int>& label, int n_classes,
                                         const DartPlacement& darts, int threads, VertexCandidates* candidates) {
    // Group darts by class (counting sort keeps darts ascending within a class).
    const auto nc = static_cast<std::size_t>(n_classes);
    std::vector<int> off;
    std::unique_ptr<int[]> idx;
    groupByClass(label, nc, threads, off, idx);
    // Extra placed points (removed regular darts) per class, in order.
    std::vector<int> xoff(nc + 1, 0), xidx(darts.extra_dart.size());
    std::vector<char> xflip(darts.extra_dart.size(), 0);
    for (int d : darts.extra_dart)
        if (label[static_cast<std::size_t>(d)] >= 0) ++xoff[static_cast<std::size_t>(label[static_cast<std::size_t>(d)]) + 1];
    for (std::size_t l = 0; l < nc; ++l) xoff[l + 1] += xoff[l];
    {
        std::vector<int> fill(xoff.begin(), xoff.end() - 1);
        for (std::size_t k = 0; k < darts.extra_dart.size(); ++k) {
            const int l = label[static_cast<std::size_t>(darts.extra_dart[k])];
            if (l < 0) continue;
            const auto at = static_cast<std::size_t>(fill[static_cast<std::size_t>(l)]++);
            xidx[at] = darts.extra_point[k];
            xflip[at] = k < darts.extra_flipped.size() ? darts.extra_flipped[k] : 0;
        }
    }
    // Tolerance for "same h-vertex": relative to the mesh size.
    Vec3d lo = mesh.n_vertices() ? mesh.position(VertexHandle(0)) : Vec3d(0, 0, 0), hi = lo;
    for (std::size_t v = 0; v < mesh.n_vertices(); ++v) {
        lo.minimize(mesh.position(VertexHandle(static_cast<int>(v))));
        hi.maximize(mesh.position(VertexHandle(static_cast<int>(v))));
    }
    const double tol = 1e-9 * std::max(1e-300, (hi - lo).norm());

    // Positions of the tet mesh's vertices, sorted by x, with a boundary flag (for the
    // majority and vertex rules; only maps with annihilated darts have extras and need them).
    std::vector<std::pair<Vec3d, bool>> meshVertices;
    if (!darts.extra_dart.empty()) {
        meshVertices.reserve(mesh.n_vertices());
        for (std::size_t v = 0; v < mesh.n_vertices(); ++v) {
            const VertexHandle vh(static_cast<int>(v));
            meshVertices.emplace_back(mesh.position(vh), mesh.is_boundary(vh));
        }
        std::sort(meshVertices.begin(), meshVertices.end(),
                  [](const std::pair<Vec3d, bool>& a, const std::pair<Vec3d, bool>& b) { return a.first[0] < b.first[0]; });
    }
    // Whether @p x is the position of a vertex of the tet mesh (a boundary one if @p boundary).
    auto atMeshVertex = [&](const Vec3d& x, bool boundary) {
        auto it = std::lower_bound(meshVertices.begin(), meshVertices.end(), x[0] - tol,
                                   [](const std::pair<Vec3d, bool>& a, double val) { return a.first[0] < val; });
        for (; it != meshVertices.end() && it->first[0] <= x[0] + tol; ++it)
            if ((!boundary || it->second) && (it->first - x).norm() <= tol) return true;
        return false;
    };
    auto atBoundaryVertex = [&](const Vec3d& x) { return atMeshVertex(x, true); };
    // The one position of @p ps at a vertex of the tet mesh (a boundary one if @p boundary)
    // into @p at; false if none or several are.
    auto onlyAtMeshVertex = [&](const std::vector<Vec3d>& ps, bool boundary, Vec3d& at) {
        int n = 0;
        for (const Vec3d& p : ps)
            if (atMeshVertex(p, boundary)) {
                at = p;
                ++n;
            }
        return n == 1;
    };

    std::vector<Vec3d> out(nc);
    // Classes are independent: parallel chunks, each with its own scratch buffers and its
    // own list of ambiguous classes (concatenated in chunk order: ascending classes).
    const int chunks = std::max(1, std::min(threads, n_classes / 1024));
    std::vector<VertexCandidates> parts(static_cast<std::size_t>(chunks));
    parallelChunks(nc, chunks, [&](int part, std::size_t lb, std::size_t le) {
        VertexCandidates& cand = parts[static_cast<std::size_t>(part)];
        std::vector<Vec3d> all, bnd;
        std::vector<int> planes;
        std::vector<Vec3d> flippedPts;  // positions of annihilated anti darts of the class
        std::vector<int> support;       // placed points of the class (surviving and removed regular darts)
        std::vector<Vec3d> supportPts;  // their positions
        std::vector<std::pair<Vec3d, double>> normals;  // boundary planes n.x = off
        for (std::size_t l = lb; l < le; ++l) {
            // The darts of a class lie anywhere in the per-dart and per-point arrays, and the
            // usual case below is a chain of two dependent loads per dart: ask for the darts'
            // placed points kPointsAhead classes ahead, their positions and boundary faces
            // kPositionsAhead classes ahead (by then the points have arrived).
            if (l + kPointsAhead < le) prefetchPoints(idx.get(), off, darts, l + kPointsAhead);
            if (l + kPositionsAhead < le) prefetchPositions(idx.get(), off, darts, l + kPositionsAhead);
            // Usual case: no extras and every dart of the class at the very same position
            // (operator==, as distinctPositions() compares). The rules below then give the
            // first boundary dart's position if the class has one (the boundary rule with one
            // distinct position), else the first dart's, and list no candidates. The boundary
            // dart is still looked for: +0.0 == -0.0, so equal positions may differ in bytes.
            if (off[l] < off[l + 1] && xoff[l] == xoff[l + 1]) {
                const auto q0 = static_cast<std::size_t>(darts.point[static_cast<std::size_t>(idx[static_cast<std::size_t>(off[l])])]);
                const Vec3d& p0 = darts.position[q0];
                std::size_t firstBoundary = darts.boundary_hf[q0][0] >= 0 ? q0 : darts.position.size();
                bool same = true;
                for (int k = off[l] + 1; k < off[l + 1] && same; ++k) {
                    const auto q = static_cast<std::size_t>(darts.point[static_cast<std::size_t>(idx[static_cast<std::size_t>(k)])]);
                    same = darts.position[q] == p0;
                    if (firstBoundary == darts.position.size() && darts.boundary_hf[q][0] >= 0) firstBoundary = q;
                }
                if (same) {
                    out[l] = firstBoundary < darts.position.size() ? darts.position[firstBoundary] : p0;
                    continue;
                }
            }
            all.clear();
            bnd.clear();
            planes.clear();
            auto addPoint = [&](std::size_t q) {
                all.push_back(darts.position[q]);
                if (darts.boundary_hf[q][0] >= 0) {
                    bnd.push_back(darts.position[q]);
                    for (int hf : darts.boundary_hf[q])
                        if (hf >= 0) planes.push_back(hf);
                }
            };
            flippedPts.clear();
            for (int k = off[l]; k < off[l + 1]; ++k) {
                const auto d = static_cast<std::size_t>(idx[static_cast<std::size_t>(k)]);
                addPoint(static_cast<std::size_t>(darts.point[d]));
            }
            // Whether the vertex is on the boundary is decided by its own (surviving)
            // h-vertices: a removed dart inherited through the annihilation can sit at
            // another grid point on the boundary (an alpha_0 pair joins the vertices at both
            // ends of its edge), and its boundary planes would pull an interior vertex there.
            // Without an own boundary h-vertex, the removed darts' positions are plain
            // candidates.
            const bool ownBoundary = !bnd.empty();
            // Where most of the vertex's own darts are: a fold copy of a grid point carries
            // only the darts of the few hex corners the fold covers that survived the
            // annihilation, the proper preimage those of all the others (issue 22: 19-80
            // darts against 2-10). Such a majority is the only preferred candidate.
            Vec3d major(0, 0, 0);
            const bool hasMajor = majorityPosition(all, tol, major);
            bool supportMajor = false;
            for (int k = xoff[l]; k < xoff[l + 1]; ++k) {
                const auto q = static_cast<std::size_t>(xidx[static_cast<std::size_t>(k)]);
                if (xflip[static_cast<std::size_t>(k)]) flippedPts.push_back(darts.position[q]);
                else if (ownBoundary) addPoint(q);
                else all.push_back(darts.position[q]);
            }
            if (all.empty()) continue;
            // Distinct anti-dart positions not among @p known (last-resort candidates).
            auto flippedExtras = [&](const std::vector<Vec3d>& known) {
                std::vector<Vec3d> extra;
                if (flippedPts.empty()) return extra;
                for (const Vec3d& p : distinctPositions(flippedPts, tol)) {
                    bool dup = false;
                    for (const Vec3d& q : known) dup = dup || (p - q).norm() <= tol;
                    if (!dup) extra.push_back(p);
                }
                return extra;
            };
            if (bnd.empty()) {
                auto dist = distinctPositions(all, tol);
                if (dist.size() > 1) {
                    // The position with more than half of the class's placed points (one per
                    // tet and grid point, of surviving and of removed regular darts) comes
                    // first, else the majority of the surviving darts. A fold copy lies inside
                    // one tet of the fold; a proper preimage at a vertex of the tet mesh is seen
                    // from all the tets around it, whose darts the annihilation removed with
                    // the fold (issue 22: 14-34 removed darts' placed points at the source
                    // position against 1 at each fold copy, even where the fold copy held
                    // more surviving darts, 15 against 9).
                    support.clear();
                    for (int k = off[l]; k < off[l + 1]; ++k) support.push_back(darts.point[static_cast<std::size_t>(idx[static_cast<std::size_t>(k)])]);
                    for (int k = xoff[l]; k < xoff[l + 1]; ++k)
                        if (!xflip[static_cast<std::size_t>(k)]) support.push_back(xidx[static_cast<std::size_t>(k)]);
                    std::sort(support.begin(), support.end());
                    support.erase(std::unique(support.begin(), support.end()), support.end());
                    supportPts.clear();
                    for (int q : support) supportPts.push_back(darts.position[static_cast<std::size_t>(q)]);
                    Vec3d most(0, 0, 0);
                    if (majorityPosition(supportPts, tol, most)) {
                        moveToFront(dist, most, tol);
                        supportMajor = true;
                    } else if (hasMajor) {
                        moveToFront(dist, major, tol);
                    }
                }
                // A candidate at a vertex of the tet mesh maps exactly onto the grid point; a
                // fold copy lies inside a tet, a face or an edge, where no vertex maps to it.
                // If exactly one candidate is such a vertex, it is the only preferred one, even
                // against the majorities (issue 22: pig at a = 0.8, seed 18: 18 of 24 darts and
                // 8 of 12 placed points at a fold copy, whose hex the source position of the
                // neighbour then inverted).
                Vec3d at(0, 0, 0);
                const bool atVertexRule = dist.size() > 1 && !meshVertices.empty() && onlyAtMeshVertex(dist, false, at);
                if (atVertexRule) moveToFront(dist, at, tol);
                out[l] = dist[0];
                const auto extra = flippedExtras(dist);
                if (dist.size() > 1 || !extra.empty()) {
                    cand.vertex.push_back(static_cast<int>(l));
                    cand.preferred.push_back(hasMajor || supportMajor || atVertexRule ? 1 : static_cast<int>(dist.size()));
                    cand.offset.push_back(static_cast<int>(cand.position.size()));
                    cand.position.insert(cand.position.end(), dist.begin(), dist.end());
                    cand.position.insert(cand.position.end(), extra.begin(), extra.end());
                }
                continue;
            }
            std::vector<Vec3d> dist = distinctPositions(bnd, tol);
            const std::vector<Vec3d> allDist = distinctPositions(all, tol);
            if (dist.size() == 1 && allDist.size() == 1 && flippedPts.empty()) {
                out[l] = dist[0];
                continue;
            }
            std::sort(planes.begin(), planes.end());
            planes.erase(std::unique(planes.begin(), planes.end()), planes.end());
            // Least squares: sum_i (n_i . x - n_i . a_i)^2, regularized towards the centroid so
            // that directions no plane constrains stay put.
            const Vec3d c = centroid(dist);
            Eigen::Matrix3d M = Eigen::Matrix3d::Identity() * 1e-8;
            Eigen::Vector3d rhs(c[0] * 1e-8, c[1] * 1e-8, c[2] * 1e-8);
            normals.clear();
            for (int hf : planes) {
                const auto v = mesh.halfface_vertices(HalfFaceHandle(hf));
                const Vec3d a = mesh.position(v[0]);
                Vec3d n = (mesh.position(v[1]) - a) % (mesh.position(v[2]) - a);
                const double len = n.norm();
                if (!(len > 0)) continue;
                n /= len;
                normals.emplace_back(n, n | a);
                const Eigen::Vector3d ne(n[0], n[1], n[2]);
                M += ne * ne.transpose();
                rhs += ne * (n | a);
            }
            const Eigen::Vector3d x = M.ldlt().solve(rhs);
            const Vec3d target(x[0], x[1], x[2]);
            // Candidates that lie on all the planes as well as any other (equal residual up
            // to rounding) are equally good for the rule: boundary h-vertices, and interior
            // ones that lie on the planes too (a grid point at a boundary vertex of the tet
            // mesh seen from a tet that touches the boundary only there). The one nearest the
            // least-squares point comes first, the others of that group next, then the rest.
            auto residualOf = [&](const Vec3d& p) {
                double r = 0;
                for (const auto& [n, off] : normals) r += ((n | p) - off) * ((n | p) - off);
                return r;
            };
            double minRes = residualOf(dist[0]);
            for (const Vec3d& p : dist) minRes = std::min(minRes, residualOf(p));
            const double resTol = minRes + 4.0 * tol * tol * static_cast<double>(normals.size() + 1);
            for (const Vec3d& p : allDist) {
                bool known = false;
                for (const Vec3d& q : dist) known = known || (p - q).norm() <= tol;
                if (!known && residualOf(p) <= resTol) dist.push_back(p);
            }
            std::vector<Vec3d> extra;
            for (const Vec3d& p : flippedExtras(dist))
                if (residualOf(p) <= resTol) extra.push_back(p);
            // On a smooth part of the boundary a fold copy and the proper preimage both lie on
            // the surface up to its curvature, and the planes cannot tell them apart: the
            // darts decide. A majority that lies clearly off the planes (its distance to them
            // more than a quarter of its distance to the plane rule's choice: a copy inside
            // the volume, or on one side of a sharp edge) is not taken, nor one that is not on
            // one of those boundary faces themselves (a plane goes on past the face's edges)
            // or at a boundary vertex of the tet mesh.
            auto onBoundaryFace = [&](const Vec3d& x) {
                for (int hf : planes) {
                    const auto v = mesh.halfface_vertices(HalfFaceHandle(hf));
                    if (triangleDistance(x, mesh.position(v[0]), mesh.position(v[1]), mesh.position(v[2])) <= 1e3 * tol) return true;
                }
                return false;
            };
            auto takeMajor = [&](const Vec3d& choice) {
                return hasMajor && std::sqrt(residualOf(major)) <= 0.25 * (major - choice).norm() + tol && (onBoundaryFace(major) || atBoundaryVertex(major));
            };
            // A candidate at a boundary vertex of the tet mesh: that vertex maps exactly onto
            // the grid point. A fold copy lies inside a tet or on a boundary face, at a point
            // no vertex of the mesh maps to; on a curved boundary the planes of the copy's
            // face can rate it above the proper preimage (issue 22). If exactly one of the
            // surviving and removed regular darts' positions is such a vertex, it is the only
            // preferred candidate.
            Vec3d atVertex(0, 0, 0);
            bool hasVertex = onlyAtMeshVertex(allDist, true, atVertex);
            // Where no surviving or removed regular dart sits at a vertex of the tet mesh and the
            // survivors are split over several positions with no majority, the annihilated anti
            // darts may decide: every tet at the proper preimage can be flipped, and then only
            // fold copies survive (pig folded by 1.2 and 1.5, seed 29: 9 of 10 anti darts at the
            // source position, a boundary vertex of the tet mesh, the 18 surviving darts at two
            // boundary and two interior copies, 5/7/2/4). If exactly one of their positions is a
            // boundary vertex of the tet mesh, it is the only preferred candidate. Not where the
            // survivors agree (one position, or a majority): on S1 perturbed by 0.7 two such
            // vertices have anti darts at a tet-mesh vertex, and their output stays as it was.
            if (!hasVertex && !flippedPts.empty() && !hasMajor && allDist.size() > 1) {
                bool anyAtVertex = false;
                for (const Vec3d& p : allDist) anyAtVertex = anyAtVertex || atMeshVertex(p, false);
                if (!anyAtVertex) hasVertex = onlyAtMeshVertex(distinctPositions(flippedPts, tol), true, atVertex);
            }
            if (dist.size() == 1 && extra.empty() && !(hasMajor && (major - dist[0]).norm() > tol && takeMajor(dist[0])) &&
                !(hasVertex && (atVertex - dist[0]).norm() > tol)) {
                out[l] = dist[0];
                continue;
            }
            std::vector<double> residual(dist.size(), 0.0);
            for (std::size_t k = 0; k < dist.size(); ++k) residual[k] = residualOf(dist[k]);
            std::size_t best = dist.size();
            for (std::size_t k = 0; k < dist.size(); ++k)
                if (residual[k] <= resTol &&
                    (best == dist.size() || (dist[k] - target).sqrnorm() < (dist[best] - target).sqrnorm()))
                    best = k;
            std::vector<Vec3d> ordered(1, dist[best]);
            int preferred = 1;
            for (std::size_t k = 0; k < dist.size(); ++k)
                if (k != best && residual[k] <= resTol) {
                    ordered.push_back(dist[k]);
                    ++preferred;
                }
            for (std::size_t k = 0; k < dist.size(); ++k)
                if (k != best && residual[k] > resTol) ordered.push_back(dist[k]);
            ordered.insert(ordered.end(), extra.begin(), extra.end());
            if (takeMajor(dist[best])) {
                moveToFront(ordered, major, tol);
                preferred = 1;
            }
            if (hasVertex && (ordered[0] - atVertex).norm() > tol) {
                moveToFront(ordered, atVertex, tol);
                preferred = 1;
            }
            out[l] = ordered[0];
            cand.vertex.push_back(static_cast<int>(l));
            cand.offset.push_back(static_cast<int>(cand.position.size()));
            cand.preferred.push_back(preferred);
            cand.position.insert(cand.position.end(), ordered.begin(), ordered.end());
        }
    });
    if (candidates) {
        *candidates = VertexCandidates();
        for (const VertexCandidates& c : parts) {
            const int base = static_cast<int>(candidates->position.size());
            candidates->vertex.insert(candidates->vertex.end(), c.vertex.begin(), c.vertex.end());
            candidates->preferred.insert(candidates->preferred.end(), c.preferred.begin(), c.preferred.end());
            for (int o : c.offset) candidates->offset.push_back(base + o);
            candidates->position.insert(candidates->position.end(), c.position.begin(), c.position.end());
        }
        candidates->offset.push_back(static_cast<int>(candidates->position.size()));
    }
    return out;
}

} // namespace HexEx
